"""Small-message throughput: publish -> spin_once -> callback, one process, one
SingleThreadedExecutor. Prints msgs/s on labkit (live and virtual time) and, when the
reference venv exists, on real rclpy, with the ratio (target: labkit >= 30x real).

    python benchmarks/bench_pubsub.py
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

SECONDS = 1.0


def worker():
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from std_msgs.msg import String

    rclpy.init(args=[])
    node = rclpy.create_node('bench_pubsub')
    received = [0]

    def on_message(msg):
        received[0] += 1

    pub = node.create_publisher(String, 'bench_chatter', 10)
    node.create_subscription(String, 'bench_chatter', on_message, 10)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    for _ in range(200):  # real DDS needs a moment to match
        if pub.get_subscription_count():
            break
        executor.spin_once(timeout_sec=0.05)
    msg = String(data='Hello World: 0')

    def burst(seconds, batch):
        """Publish `batch` messages, then spin until their callbacks ran; repeat."""
        sent = 0
        received[0] = 0
        start = time.perf_counter()
        while time.perf_counter() - start < seconds:
            for _ in range(batch):
                pub.publish(msg)
            sent += batch
            for _ in range(batch):
                if received[0] >= sent:
                    break
                executor.spin_once(timeout_sec=1.0)
        return {'msgs_per_s': received[0] / (time.perf_counter() - start), 'sent': sent,
                'received': received[0]}

    burst(0.2, 10)  # warm-up
    figures = {'one': burst(SECONDS, 1), 'batch10': burst(SECONDS, 10)}
    executor.shutdown()
    node.destroy_node()
    rclpy.shutdown()
    from _common import emit
    emit(figures)


def show(label, figures):
    for mode, text in (('one', 'publish+spin each'), ('batch10', 'batches of 10')):
        f = figures[mode]
        print(f"{label:<22} {text:<18} {f['msgs_per_s']:>10,.0f} msgs/s "
              f"({f['received']}/{f['sent']} received)")


def main():
    from _common import run_labkit, run_reference
    live = run_labkit(__file__, 'live')
    show('labkit (live time)', live)
    show('labkit (virtual time)', run_labkit(__file__, 'virtual'))
    real = run_reference(__file__)
    if real is None:
        print('real rclpy: reference venv not found (set ROSREF_PYTHON), no ratio')
        return
    show('real rclpy (Jazzy)', real)
    for mode in ('one', 'batch10'):
        ratio = live[mode]['msgs_per_s'] / real[mode]['msgs_per_s']
        print(f'ratio labkit live / real, {mode}: {ratio:.1f}x (target >= 30x)')


if __name__ == '__main__':
    worker() if '--worker' in sys.argv else main()
