"""Node creation and teardown: create N nodes (each with its rosout publisher, parameter
services and a publisher and subscription of its own), then destroy them all; ms per node
for N = 100 and 1,000 (real rclpy: 100 and 300). labkit (live time, `labkit exec`, DDS off and on) against real rclpy,
same program.

    python benchmarks/bench_nodes.py

Goal: destroying N nodes costs no more than creating them.
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

COUNTS = (100, 1000)


def worker():
    import rclpy
    from std_msgs.msg import String

    rclpy.init(args=[])
    figures = {}
    counts = COUNTS
    if '--counts' in sys.argv:
        counts = [int(c) for c in sys.argv[sys.argv.index('--counts') + 1].split(',')]
    for count in counts:
        t0 = time.perf_counter()
        nodes = []
        for i in range(count):
            node = rclpy.create_node(f'bench_node_{i}')
            node.create_publisher(String, f'bench_topic_{i % 10}', 10)
            node.create_subscription(String, f'bench_topic_{(i + 1) % 10}', lambda m: None, 10)
            nodes.append(node)
        t1 = time.perf_counter()
        for node in nodes:
            node.destroy_node()
        t2 = time.perf_counter()
        figures[str(count)] = {'create_ms_per_node': round((t1 - t0) / count * 1e3, 3),
                               'destroy_ms_per_node': round((t2 - t1) / count * 1e3, 3)}
    rclpy.shutdown()
    from _common import emit
    emit(figures)


def main():
    from _common import run_labkit, run_reference, run_worker, REPO
    rows = [('labkit, DDS off', run_worker(
                [sys.executable, '-m', 'labkit', 'exec', '--time', 'live', __file__, '--worker'],
                {'PYTHONPATH': str(REPO), 'LABKIT_TIME': 'live', 'LABKIT_DDS': 'off'})),
            ('labkit, DDS on', run_labkit(__file__, 'live'))]
    # real rclpy at 1,000 nodes takes minutes (discovery): 100 and 300 only
    real = run_reference(__file__, args=('--counts', '100,300'))
    if real is not None:
        rows.append(('real rclpy (Jazzy)', real))
    for label, figures in rows:
        for count, f in figures.items():
            print(f"{label:<20} {count:>5} nodes: create {f['create_ms_per_node']:.3f} ms/node, "
                  f"destroy {f['destroy_ms_per_node']:.3f} ms/node "
                  f"(destroy/create {f['destroy_ms_per_node'] / f['create_ms_per_node']:.2f})")
    if real is None:
        print('real rclpy: reference venv not found (set ROSREF_PYTHON), no ratio')


if __name__ == '__main__':
    worker() if '--worker' in sys.argv else main()
