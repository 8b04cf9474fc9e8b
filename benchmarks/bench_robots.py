"""robot_state_publisher speed figures (printed, not asserted).

    .venv/bin/python benchmarks/bench_robots.py

- live time: robot_state_publisher for the facer model fed JointState at 100 Hz
  (`--ignore-timestamp`: no throttling by stamps, every message gives a /tf)
  by a publisher process for 5 s: CPU share of this whole Python process
  (both nodes plus the middleware), /tf messages received
- the transform math alone: one JointState -> TFMessage (us)
- the driving facer animated snapshot: build time and iframe size
"""
import os
import resource
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
os.environ["LABKIT_TIME"] = "live"
IGNORE = "true" if "--ignore-timestamp" in sys.argv else "false"


def cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def bench_live(seconds=5.0, rate=100.0):
    import labkit
    import labkit.rclpy as rclpy
    from labkit import process
    from labkit.interfaces import get_type
    from labkit.robots import facer
    JointState = get_type("sensor_msgs/msg/JointState")
    TFMessage = get_type("tf2_msgs/msg/TFMessage")
    with open(facer.model_path()) as handle:
        facer.start_robot_state_publisher(
            handle.read(), echo=False,
            extra_args=["--ros-args", "-p", "publish_frequency:=100.0",
                        "-p", "ignore_timestamp:=" + IGNORE])

    def joint_feeder(args=None):
        rclpy.init(args=args)
        node = rclpy.create_node("feeder")
        pub = node.create_publisher(JointState, "joint_states", 10)
        step = [0]

        def tick():
            j = facer.joints_at(step[0] / rate)
            msg = JointState(name=list(j), position=list(j.values()))
            msg.header.stamp = node.get_clock().now().to_msg()
            pub.publish(msg)
            step[0] += 1
        node.create_timer(1.0 / rate, tick)
        rclpy.spin(node)
    process.start(main=joint_feeder, name="feeder", echo=False)
    rclpy.init()
    listener = rclpy.create_node("tf_counter")
    count = [0]
    listener.create_subscription(TFMessage, "/tf",
                                 lambda m: count.__setitem__(0, count[0] + 1), 100)
    c0, t0 = cpu(), time.perf_counter()
    end = t0 + seconds
    while time.perf_counter() < end:
        rclpy.spin_once(listener, timeout_sec=0.05)
    c1, t1 = cpu(), time.perf_counter()
    labkit.reset()
    return (c1 - c0) / (t1 - t0), count[0] / (t1 - t0)


def bench_math(n=2000):
    from labkit.interfaces import get_type
    from labkit.robots import facer, robot_state_publisher as rsp
    from labkit.robots.urdf import load
    model = load(facer.model_path())
    moving = model.movable_joints()
    Time = get_type("builtin_interfaces/msg/Time")
    [rsp.transform_stamped(j.parent, j.child, Time(), *j.transform(0.0)) for j in moving]
    start = time.perf_counter()
    for k in range(n):
        [rsp.transform_stamped(j.parent, j.child, Time(), *j.transform(k * 1e-3)) for j in moving]
    return (time.perf_counter() - start) / n * 1e6


def bench_snapshot():
    from labkit.robots import facer
    start = time.perf_counter()
    view = facer.drive_view(seconds=12.0, fps=10)
    frame = view.iframe()
    return time.perf_counter() - start, len(frame)


if __name__ == "__main__":
    share, rate = bench_live()
    print(f"robot_state_publisher facer @100 Hz (live, 5 s): CPU {share * 100:.1f}% of one core "
          f"(rsp + feeder + listener), /tf received {rate:.1f}/s")
    print(f"JointState -> 4 TransformStamped: {bench_math():.1f} us")
    seconds, size = bench_snapshot()
    print(f"facer driving snapshot (12 s at 10 fps): built in {seconds:.2f} s, "
          f"iframe {size / 1e6:.2f} MB")
