"""turtlesim speed figures (printed, not asserted).

    .venv/bin/python benchmarks/bench_turtlesim.py

- simulation step (physics only) for 1, 10, 100 moving turtles
- the whole node in virtual time: simulated seconds per wall second
- canvas: live frame cost (ms and CPU per frame), PNG snapshot, 5 s replay
- idle CPU of a live canvas following a simulator where nothing moves
"""
import math
import os
import resource
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from labkit.sims.turtlesim import physics as P  # noqa: E402

TICK = 16_000_000


def cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def moving_world(n):
    w = P.TurtleWorld()
    for i in range(n):
        w.spawn("", 1 + (i % 10), 1 + (i // 10) % 10, i * 0.3)
    w.step(0)
    return w


def bench_step(n, steps=500):
    w = moving_world(n)
    t = 0
    start = time.perf_counter()
    for k in range(steps):
        t += TICK
        if k % 50 == 0:
            for turtle in w.turtles.values():
                turtle.command_velocity(1.5, 0.0, 0.8 * math.sin(k), t)
        w.step(t)
    per = (time.perf_counter() - start) / steps
    print("physics step, %3d turtles: %7.3f ms/step  (budget at 62.5 Hz: 16 ms)" % (n, per * 1e3))


def bench_node(seconds=10.0):
    try:
        os.environ.setdefault("LABKIT_TIME", "virtual")
        import labkit
        from labkit import process
        from labkit.graph import world
        world.set_mode("virtual")
        proc = process.start(["turtlesim", "turtlesim_node"], name="turtlesim", echo=False)
    except Exception as exc:          # the rclpy layer may not be ready
        print("node in virtual time: skipped (%s: %s)" % (type(exc).__name__, exc))
        return
    try:
        start = time.perf_counter()
        labkit.sleep(seconds)
        wall = time.perf_counter() - start
        print("turtlesim_node, 1 idle turtle, virtual time: %.1f simulated s in %.2f wall s "
              "(%.0fx real time)" % (seconds, wall, seconds / wall))
        import labkit.rclpy as rclpy
        from labkit.interfaces import get_type
        Spawn, Twist = get_type("turtlesim/srv/Spawn"), get_type("geometry_msgs/msg/Twist")
        Pose = get_type("turtlesim/msg/Pose")
        rclpy.init()
        node = rclpy.create_node("bench")
        client = node.create_client(Spawn, "/spawn")
        for i in range(9):
            future = client.call_async(Spawn.Request(x=1.0 + i, y=2.0, theta=0.1 * i))
            rclpy.spin_until_future_complete(node, future)
        received = []
        pubs = []
        for i in range(10):
            name = "turtle%d" % (i + 1)
            node.create_subscription(Pose, "/%s/pose" % name, received.append, 10)
            pubs.append(node.create_publisher(Twist, "/%s/cmd_vel" % name, 10))
        twist = Twist()
        twist.linear.x, twist.angular.z = 1.0, 0.5
        start = time.perf_counter()
        clock = node.get_clock()
        end = clock.now().nanoseconds + int(seconds * 1e9)
        while clock.now().nanoseconds < end:
            for pub in pubs:
                pub.publish(twist)
            rclpy.spin_once(node, timeout_sec=0.5)
        wall = time.perf_counter() - start
        print("turtlesim_node, 10 moving turtles + a pose subscriber, virtual time: %.1f simulated "
              "s in %.2f wall s (%.0fx real time), %d poses received"
              % (seconds, wall, seconds / wall, len(received)))
        node.destroy_node()
        rclpy.try_shutdown()
    finally:
        proc.stop()


def bench_canvas():
    from labkit.viz.canvas import TurtleCanvas, png_bytes, render
    from labkit.viz.replay import replay
    w = moving_world(3)
    t = 0
    canvas = TurtleCanvas(w)
    canvas.widget                       # build; without a kernel the messages go nowhere
    frames, draw_s, draw_cpu = 60, 0.0, 0.0
    for _ in range(frames):
        for turtle in w.turtles.values():
            turtle.command_velocity(1.0, 0.0, 0.7, t)
        for _ in range(2):              # ~2 simulated steps per 30 fps frame
            t += TICK
            w.step(t)
        c0, t0 = cpu(), time.perf_counter()
        canvas._draw()
        draw_s += time.perf_counter() - t0
        draw_cpu += cpu() - c0
    print("live canvas frame (3 moving turtles): %.2f ms, %.2f ms CPU per frame -> max %.0f fps"
          % (draw_s / frames * 1e3, draw_cpu / frames * 1e3, frames / draw_s))
    t0 = time.perf_counter()
    png = png_bytes(render(w))
    crowd = moving_world(100)
    canvas = TurtleCanvas(crowd)
    canvas.widget
    t, draw_s = 0, 0.0
    for _ in range(frames):
        for turtle in crowd.turtles.values():
            turtle.command_velocity(1.0, 0.0, 0.7, t)
        for _ in range(2):
            t += TICK
            crowd.step(t)
        t0 = time.perf_counter()
        canvas._draw()
        draw_s += time.perf_counter() - t0
    print("live canvas frame (100 moving turtles): %.2f ms per frame" % (draw_s / frames * 1e3))
    print("PNG snapshot: %.1f ms, %d bytes" % ((time.perf_counter() - t0) * 1e3, len(png)))
    for fmt in ("gif", "webp"):
        t0 = time.perf_counter()
        r = replay(w, seconds=5, fps=15, format=fmt)
        print("replay 5 s %s: %.2f s to encode, %d KB, %d frames"
              % (fmt, time.perf_counter() - t0, len(r.data) // 1024, r.frames))

    # idle: the follower thread runs, the world steps but nothing changes
    idle = moving_world(1)
    canvas = TurtleCanvas(idle)
    canvas.start()
    time.sleep(0.3)
    before_frames = canvas.frames_drawn
    c0, t0 = cpu(), time.perf_counter()
    t = 0
    while time.perf_counter() - t0 < 2.0:   # the simulator ticks, nothing moves
        t += TICK
        idle.step(t)
        time.sleep(0.016)
    used = cpu() - c0
    wall = time.perf_counter() - t0
    canvas.stop()
    print("idle live canvas (simulator ticking at 62.5 Hz, nothing moving; CPU includes the ticks): "
          "%.2f%% of one CPU, %d frames drawn in %.1f s"
          % (100 * used / wall, canvas.frames_drawn - before_frames, wall))


if __name__ == "__main__":
    for n in (1, 10, 100):
        bench_step(n)
    bench_canvas()
    bench_node()
