"""Many timers in one node: 1,000 timers at 10 Hz (10,000 fires a second wanted) spun by one
SingleThreadedExecutor for a few seconds. Prints fires per second and the process CPU time
per fire, labkit (live time) against real rclpy, same program.

    python benchmarks/bench_timers.py

Goal: labkit's CPU per fire no higher than real rclpy's, and every fire when a core is free.
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

SECONDS = 3.0
COUNTS = (100, 1000)


def worker():
    import rclpy
    from rclpy.executors import SingleThreadedExecutor

    rclpy.init(args=[])
    figures = {}
    for count in COUNTS:
        node = rclpy.create_node(f'bench_timers_{count}')
        fired = [0]

        def tick():
            fired[0] += 1

        timers = [node.create_timer(0.1, tick) for _ in range(count)]
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        end = time.perf_counter() + 0.3                       # warm-up
        while time.perf_counter() < end:
            executor.spin_once(timeout_sec=0.01)
        fired[0] = 0
        cpu0, wall0 = time.process_time(), time.perf_counter()
        while time.perf_counter() - wall0 < SECONDS:
            executor.spin_once(timeout_sec=0.01)
        cpu, wall = time.process_time() - cpu0, time.perf_counter() - wall0
        figures[str(count)] = {
            'fires_per_s': round(fired[0] / wall), 'wanted_per_s': count * 10,
            'cpu_us_per_fire': round(cpu / max(1, fired[0]) * 1e6, 1),
            'cpu_share': round(cpu / wall, 2)}
        for tmr in timers:
            node.destroy_timer(tmr)
        executor.shutdown()
        node.destroy_node()
    rclpy.shutdown()
    from _common import emit
    emit(figures)


def main():
    from _common import run_labkit, run_reference
    rows = [('labkit (live time)', run_labkit(__file__, 'live'))]
    real = run_reference(__file__)
    if real is not None:
        rows.append(('real rclpy (Jazzy)', real))
    for label, figures in rows:
        for count, f in figures.items():
            print(f"{label:<20} {count:>5} timers @10 Hz: {f['fires_per_s']:>7,} fires/s of "
                  f"{f['wanted_per_s']:,}, {f['cpu_us_per_fire']:>6.1f} us CPU per fire, "
                  f"CPU {f['cpu_share'] * 100:.0f}% of one core")
    if real is None:
        print('real rclpy: reference venv not found (set ROSREF_PYTHON), no ratio')
        return
    for count in real:
        ratio = rows[0][1][count]['cpu_us_per_fire'] / real[count]['cpu_us_per_fire']
        print(f'CPU per fire, labkit / real rclpy, {count} timers: {ratio:.2f} (goal <= 1)')


if __name__ == '__main__':
    worker() if '--worker' in sys.argv else main()
