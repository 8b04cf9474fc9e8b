"""The turtles of a turtlesim in another process, for the canvas to draw.

    import labkit
    labkit.set_time_mode('live'); labkit.connect()
    from labkit.viz.remote_turtles import RemoteTurtles
    turtles = RemoteTurtles()            # follows every /<name>/pose on the graph
    TurtleCanvas.attach(turtles.world)   # draws them like a local turtlesim
    TurtleCanvas.remote()                # the same in one line

A turtlesim in another terminal (`labkit ros2 run turtlesim turtlesim_node`, or a
real one) publishes each turtle's turtlesim/msg/Pose on /<name>/pose at 62.5 Hz.
A hidden node subscribes to every such topic it finds on the graph and moves a
turtle of a local TurtleWorld (a model only: it is never stepped) to each pose,
drawing the pen line between consecutive poses, so TurtleCanvas draws it as it
draws a local simulation. What the poses do not carry is not shown: the remote
pen's colour, width and on/off (set_pen), and its background colour, keep
turtlesim's defaults; a turtle whose pose topic has no publisher any more is
removed. labkit.reset() stops the node.
"""
import re
import threading

from labkit.sims.turtlesim import physics

POSE_TYPE = "turtlesim/msg/Pose"
_POSE_TOPIC = re.compile(r"^/([A-Za-z_][A-Za-z0-9_]*)/pose$")
SCAN_PERIOD = 0.5        # s between looks at the graph for new or gone turtles
_running = []


class RemoteTurtles:
    def __init__(self, node_name="_turtle_canvas"):
        import labkit.rclpy as rclpy
        from labkit.rclpy.context import Context
        from labkit.rclpy.executors import SingleThreadedExecutor
        self.world = physics.TurtleWorld()
        self.poses_seen = 0
        self._context = Context()
        rclpy.init(args=[], context=self._context)
        self._node = rclpy.create_node(node_name, context=self._context,
                                       start_parameter_services=False)
        self._executor = SingleThreadedExecutor(context=self._context)
        self._executor.add_node(self._node)
        self._subs = {}                  # turtle name -> subscription
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._spin, name="labkit-remote-turtles",
                                        daemon=True)
        _running.append(self)
        _install_reset_hook()
        self._thread.start()

    # -- the graph: which turtles are there --------------------------------------------
    def _scan(self):
        from labkit.interfaces import get_type
        node = self._node
        found = set()
        for topic, types in node.get_topic_names_and_types():
            m = _POSE_TOPIC.match(topic)
            if m and POSE_TYPE in types and node.count_publishers(topic) > 0:
                found.add(m.group(1))
        for name in sorted(found - set(self._subs)):
            self._subs[name] = node.create_subscription(
                get_type(POSE_TYPE), f"/{name}/pose",
                lambda msg, name=name: self._on_pose(name, msg), 10)
        for name in sorted(set(self._subs) - found):
            node.destroy_subscription(self._subs.pop(name))
            self.world.kill(name)

    def _on_pose(self, name, msg):
        world = self.world
        with world.lock:
            self.poses_seen += 1
            turtle = world.turtles.get(name)
            if turtle is None:
                world.spawn(name, msg.x, msg.y, msg.theta)
                return
            old = list(turtle.pos)
            new = [physics.f32(msg.x), physics.HEIGHT_IN_METERS - physics.f32(msg.y)]
            theta = physics.f32(msg.theta)
            if new == old and theta == turtle.orient:
                return
            turtle.pos, turtle.orient = new, theta
            if turtle.pen_on and new != old:
                world.path.draw_line(new, old, turtle.pen_rgb, turtle.pen_width)
            world._changed()

    def _spin(self):
        import time
        next_scan = 0.0
        while not self._stop.is_set():
            now = time.monotonic()
            try:
                if now >= next_scan:
                    self._scan()
                    next_scan = now + SCAN_PERIOD
                self._executor.spin_once(timeout_sec=0.05)
            except Exception:
                if self._stop.is_set() or not self._context.ok():
                    break
                raise

    def close(self):
        """Stop following (the model keeps its last picture)."""
        if self._stop.is_set():
            return
        self._stop.set()
        if self._thread is not threading.current_thread():
            self._thread.join(2)
        try:
            self._node.destroy_node()
            self._context.try_shutdown()
        except Exception:
            pass
        if self in _running:
            _running.remove(self)


def stop_all():
    for turtles in list(_running):
        turtles.close()


def _install_reset_hook():
    try:
        from labkit import process
    except ImportError:
        return
    if stop_all not in process.reset_hooks:
        process.reset_hooks.append(stop_all)
