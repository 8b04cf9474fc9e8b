"""Start-up cost: a fresh interpreter that activates labkit (as %load_ext does), then
rclpy.init() + a node + a publisher. Five runs, median (target < 1 s).

    python benchmarks/bench_startup.py
"""
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
RUNS = 5

# Timed inside the fresh interpreter, from before `import labkit` to the publisher.
PROGRAM = '''
import time
t0 = time.perf_counter()
import labkit
labkit.activate()
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('startup_probe')
publisher = node.create_publisher(String, 'chatter', 10)
print(time.perf_counter() - t0)
node.destroy_node()
rclpy.shutdown()
'''


def one_run():
    start = time.perf_counter()
    result = subprocess.run([sys.executable, '-c', PROGRAM], capture_output=True, text=True,
                            timeout=120, cwd=REPO, env={'PYTHONPATH': str(REPO),
                                                        'LABKIT_TIME': 'live',
                                                        'PATH': '/usr/bin:/bin'})
    wall = time.perf_counter() - start
    if result.returncode != 0:
        raise RuntimeError(result.stderr[-2000:])
    return wall, float(result.stdout.strip().splitlines()[-1])


def main():
    runs = [one_run() for _ in range(RUNS)]
    walls = [w for w, _ in runs]
    inside = [i for _, i in runs]
    print(f'fresh interpreter, whole process wall time: median {statistics.median(walls):.3f} s '
          f'(runs: {", ".join(f"{w:.3f}" for w in walls)})')
    print(f'import labkit -> activate -> init -> node -> publisher: median '
          f'{statistics.median(inside):.3f} s (target < 1 s)')


if __name__ == '__main__':
    main()
