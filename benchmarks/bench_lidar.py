"""2D lidar and simulator speed figures (printed, not asserted).

    .venv/bin/python benchmarks/bench_lidar.py

- one scan: 360 rays and the seed's 640 rays against the visualize_lidar world
- CPU share of a 360-ray scan at 10 Hz (scan cost x 10 per second)
- the whole simulator (diff drive + 640-ray lidar at 10 Hz + odometry), live mode:
  CPU share while it runs in real time for a few seconds
"""
import math
import os
import resource
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from labkit.sims.world2d import world as w2d  # noqa: E402
from labkit.sims.world2d.sim import Simulation  # noqa: E402
from labkit.sims.world2d.transport import Transport  # noqa: E402


def cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def scan_cost(samples, repeats=300):
    world = w2d.load("visualize_lidar.sdf")
    lidar = w2d.LidarConfig(samples=samples, min_angle=-math.pi,
                            max_angle=math.pi * (samples - 2) / samples)
    w2d.scan_ranges(world, lidar, (-4.0, 0.0, 0.0))
    start = time.perf_counter()
    for i in range(repeats):
        w2d.scan_ranges(world, lidar, (-4.0 + i * 0.001, 0.0, 0.01 * i))
    return (time.perf_counter() - start) / repeats


def simulator_steps(seconds=20.0):
    sim = Simulation(w2d.load("visualize_lidar.sdf"), transport=Transport())
    sim.vehicle().cmd_linear, sim.vehicle().cmd_angular = 0.5, 0.2
    start = time.perf_counter()
    sim.advance(seconds)
    return seconds / (time.perf_counter() - start)


def live_cpu_share(seconds=3.0):
    import labkit
    labkit.set_time_mode("live")
    from labkit.sims import world2d
    world2d.register()
    world2d.ign("gazebo -r visualize_lidar.sdf")
    c0, t0 = cpu(), time.perf_counter()
    time.sleep(seconds)
    share = (cpu() - c0) / (time.perf_counter() - t0)
    sim = world2d.current()
    sim_time = sim.sim_time
    labkit.reset()
    return share, sim_time


def main():
    for samples in (360, 640):
        cost = scan_cost(samples)
        print(f"scan, {samples} rays: {cost * 1e3:.3f} ms  "
              f"(at 10 Hz: {cost * 10 * 100:.2f} % of one core)")
    print(f"simulator in virtual time (no ROS): {simulator_steps():.0f} sim s per wall s")
    share, sim_time = live_cpu_share()
    print(f"live `ign gazebo -r` (100 Hz steps, 640-ray lidar at 10 Hz): "
          f"{share * 100:.1f} % CPU, sim time {sim_time:.2f} s after 3 s")


if __name__ == "__main__":
    main()
