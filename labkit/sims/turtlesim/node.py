"""`ros2 run turtlesim turtlesim_node`: the node /turtlesim, as Humble's turtlesim behaves.

Interface per turtle: topics <name>/cmd_vel (subscribed), <name>/pose,
<name>/color_sensor; services <name>/set_pen, <name>/teleport_absolute,
<name>/teleport_relative; action <name>/rotate_absolute. Global services
clear, reset, spawn, kill. Parameters background_r/g/b.

The simulation itself is physics.TurtleWorld; this module is plain rclpy code
around it. Viewers find running simulators with `running()`.
"""
import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.action import ActionServer, CancelResponse, GoalResponse
from labkit.rclpy.exceptions import NameValidationException
from labkit.rclpy.node import Node
from labkit.rclpy.qos import QoSProfile, qos_profile_sensor_data
from labkit.rclpy.task import Future

from . import physics
from .cpp_node import like_rclcpp
from .physics import f32

Twist = get_type("geometry_msgs/msg/Twist")
Pose = get_type("turtlesim/msg/Pose")
Color = get_type("turtlesim/msg/Color")
SetPen = get_type("turtlesim/srv/SetPen")
TeleportAbsolute = get_type("turtlesim/srv/TeleportAbsolute")
TeleportRelative = get_type("turtlesim/srv/TeleportRelative")
Spawn = get_type("turtlesim/srv/Spawn")
Kill = get_type("turtlesim/srv/Kill")
Empty = get_type("std_srvs/srv/Empty")
RotateAbsolute = get_type("turtlesim/action/RotateAbsolute")
ParameterEvent = get_type("rcl_interfaces/msg/ParameterEvent")
ParameterDescriptor = get_type("rcl_interfaces/msg/ParameterDescriptor")
IntegerRange = get_type("rcl_interfaces/msg/IntegerRange")

_running = []        # TurtleSim nodes alive in this interpreter, oldest first


def running():
    """The turtlesim nodes currently alive (newest last)."""
    return list(_running)


class _Goal(physics.RotationGoal):
    """A rotate_absolute goal handle seen by the physics; the outcome resolves `done`."""

    def __init__(self, goal_handle):
        self.handle = goal_handle
        self.theta = f32(goal_handle.request.theta)   # float32 on the wire, as C++ sees it
        self.done = Future()

    def is_canceling(self):
        return self.handle.is_cancel_requested

    def publish_feedback(self, remaining):
        feedback = RotateAbsolute.Feedback()
        feedback.remaining = f32(remaining)
        self.handle.publish_feedback(feedback)

    def _finish(self, outcome, delta):
        if not self.done.done():
            self.done.set_result((outcome, delta))

    def succeed(self, delta):
        self._finish("succeed", delta)

    def canceled(self, delta):
        self._finish("canceled", delta)

    def abort(self, delta):
        self._finish("abort", delta)


class _TurtleEndpoints:
    """The ROS interface of one turtle (created on spawn, destroyed on kill/reset)."""

    def __init__(self, sim, name):
        node = sim
        qos = QoSProfile(depth=7)
        self.name = name
        self.cmd_vel = node.create_subscription(
            Twist, name + "/cmd_vel", lambda msg: sim._on_cmd_vel(name, msg), qos)
        self.pose = node.create_publisher(Pose, name + "/pose", qos)
        self.color = node.create_publisher(Color, name + "/color_sensor", qos)
        self.set_pen = node.create_service(
            SetPen, name + "/set_pen", lambda req, res: sim._on_set_pen(name, req, res))
        self.teleport_relative = node.create_service(
            TeleportRelative, name + "/teleport_relative",
            lambda req, res: sim._on_teleport_relative(name, req, res))
        self.teleport_absolute = node.create_service(
            TeleportAbsolute, name + "/teleport_absolute",
            lambda req, res: sim._on_teleport_absolute(name, req, res))
        self.rotate_absolute = ActionServer(
            node, RotateAbsolute, name + "/rotate_absolute",
            execute_callback=sim._execute_rotation,
            goal_callback=lambda goal: GoalResponse.ACCEPT,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT,
            handle_accepted_callback=lambda handle: sim._on_goal_accepted(name, handle))

    def destroy(self, node):
        node.destroy_subscription(self.cmd_vel)
        node.destroy_publisher(self.pose)
        node.destroy_publisher(self.color)
        node.destroy_service(self.set_pen)
        node.destroy_service(self.teleport_relative)
        node.destroy_service(self.teleport_absolute)
        self.rotate_absolute.destroy()


class TurtleSim(Node):
    """The /turtlesim node: a TurtleWorld stepped by a 16 ms timer."""

    def __init__(self, node_name="turtlesim", **kwargs):
        super().__init__(node_name, **kwargs)
        self.world = physics.TurtleWorld()
        self._endpoints = {}

        like_rclcpp(self)
        for channel, value, label in (("r", 69, "Red"), ("g", 86, "Green"), ("b", 255, "Blue")):
            self.declare_parameter(
                "background_" + channel, value,
                ParameterDescriptor(
                    description="%s channel of the background color" % label,
                    integer_range=[IntegerRange(from_value=0, to_value=255, step=1)]))
        self._read_background()

        self.create_service(Empty, "clear", self._on_clear)
        self.create_service(Empty, "reset", self._on_reset)
        self.create_service(Spawn, "spawn", self._on_spawn)
        self.create_service(Kill, "kill", self._on_kill)
        events_qos = QoSProfile(depth=100, reliability=qos_profile_sensor_data.reliability,
                                durability=qos_profile_sensor_data.durability,
                                history=qos_profile_sensor_data.history)
        self.create_subscription(ParameterEvent, "/parameter_events", self._on_parameter_event,
                                 events_qos)

        self.get_logger().info("Starting turtlesim with node name %s" % self.get_fully_qualified_name())
        self._spawn("", physics.CENTER, physics.CENTER, 0.0)
        self.update_timer = self.create_timer(physics.UPDATE_PERIOD, self._on_update)
        _running.append(self)

    def destroy_node(self):
        if self in _running:
            _running.remove(self)
        for turtle in list(self.world.turtles.values()):
            if turtle.goal is not None:
                turtle.goal.abort(turtle.goal_delta)
        return super().destroy_node()

    def _now_ns(self):
        return self.get_clock().now().nanoseconds

    # -- spawning ---------------------------------------------------------------------
    def _spawn(self, name, x, y, theta):
        real_name = self.world.spawn(name, x, y, theta, self._now_ns())
        if real_name:
            try:
                self._endpoints[real_name] = _TurtleEndpoints(self, real_name)
            except NameValidationException as exc:
                # e.g. a name that is no valid topic name: rclcpp would throw and end the
                # process; we refuse this spawn instead and say why
                self.world.kill(real_name)
                self.get_logger().error("Cannot spawn turtle [%s]: %s" % (real_name, exc))
                return None
            self.get_logger().info("Spawning turtle [%s] at x=[%f], y=[%f], theta=[%f]"
                                   % (real_name, f32(x), f32(y), f32(theta)))
        return real_name

    def _remove(self, name):
        turtle = self.world.turtles.get(name)
        if turtle is not None and turtle.goal is not None:
            turtle.goal.abort(turtle.goal_delta)
        endpoints = self._endpoints.pop(name, None)
        if endpoints is not None:
            endpoints.destroy(self)

    # -- global services (a failed call still answers: rclcpp ignores the bool) --------
    def _on_spawn(self, request, response):
        name = self._spawn(request.name, request.x, request.y, request.theta)
        if name is None:
            return response
        if not name:
            self.get_logger().error("A turtle named [%s] already exists" % request.name)
            return response
        response.name = name
        return response

    def _on_kill(self, request, response):
        if not self.world.has_turtle(request.name):
            self.get_logger().error(
                "Tried to kill turtle [%s], which does not exist" % request.name)
            return response
        self._remove(request.name)
        self.world.kill(request.name)
        return response

    def _on_clear(self, request, response):
        self.get_logger().info("Clearing turtlesim.")
        self.world.clear()
        return response

    def _on_reset(self, request, response):
        self.get_logger().info("Resetting turtlesim.")
        for name in list(self._endpoints):
            self._remove(name)
        self.world.remove_all()
        self._spawn("", physics.CENTER, physics.CENTER, 0.0)
        self.world.clear()
        return response

    # -- per-turtle callbacks -----------------------------------------------------------
    def _on_cmd_vel(self, name, msg):
        turtle = self.world.turtles.get(name)
        if turtle is None:
            return
        with self.world.lock:
            aborted = turtle.command_velocity(msg.linear.x, msg.linear.y, msg.angular.z,
                                              self._now_ns())
        if aborted is not None:
            self.get_logger().warning("Velocity command received during rotation goal. Aborting goal")
            aborted.abort(turtle.goal_delta)

    def _on_set_pen(self, name, request, response):
        with self.world.lock:
            self.world.turtles[name].set_pen(request.r, request.g, request.b, request.width,
                                             request.off)
        return response

    def _on_teleport_absolute(self, name, request, response):
        with self.world.lock:
            self.world.turtles[name].teleport_absolute(
                f32(request.x), f32(request.y), f32(request.theta))
        return response

    def _on_teleport_relative(self, name, request, response):
        with self.world.lock:
            self.world.turtles[name].teleport_relative(
                f32(request.linear), f32(request.angular))
        return response

    def _on_goal_accepted(self, name, goal_handle):
        turtle = self.world.turtles.get(name)
        goal = goal_handle.rotation = _Goal(goal_handle)   # found again by _execute_rotation
        goal_handle.execute()
        if turtle is None:                                 # killed meanwhile
            goal.abort(0.0)
            return
        with self.world.lock:
            delta = turtle.goal_delta
            previous = turtle.accept_goal(goal)
        if previous is not None:
            self.get_logger().warning(
                "Rotation goal received before a previous goal finished. Aborting previous goal")
            previous.abort(delta)

    async def _execute_rotation(self, goal_handle):
        # the 16 ms update settles the goal (succeed/cancel/abort); wait for its verdict
        outcome, delta = await goal_handle.rotation.done
        if outcome == "succeed":
            goal_handle.succeed()
        elif outcome == "canceled":
            goal_handle.canceled()
        else:
            goal_handle.abort()
        result = RotateAbsolute.Result()
        result.delta = f32(delta)
        return result

    # -- parameters ---------------------------------------------------------------------
    def _read_background(self):
        rgb = [self.get_parameter("background_" + c).value for c in "rgb"]
        self.world.set_background(rgb)

    def _on_parameter_event(self, event):
        if event.node == self.get_fully_qualified_name():
            self._read_background()

    # -- the 16 ms tick -------------------------------------------------------------------
    def _on_update(self):
        results = self.world.step(self._now_ns())
        logger = self.get_logger()
        for res in results:
            endpoints = self._endpoints.get(res.name)
            if endpoints is None:
                continue
            for line in res.infos:
                logger.info(line)
            if res.warning:
                logger.warning(res.warning)
            x, y, theta, linear, angular = res.pose
            pose = Pose()
            pose.x, pose.y, pose.theta = f32(x), f32(y), f32(theta)
            pose.linear_velocity, pose.angular_velocity = f32(linear), f32(angular)
            endpoints.pose.publish(pose)
            color = Color()
            color.r, color.g, color.b = res.color
            endpoints.color.publish(color)


# In a notebook kernel turtlesim_node opens its "window": the live canvas (with its PNG).
SHOW_WINDOW = True


def _show_window(node):
    try:
        from IPython import get_ipython
    except ImportError:
        return
    shell = get_ipython()
    if not SHOW_WINDOW or shell is None or getattr(shell, "kernel", None) is None:
        return
    # the canvas lives with the other viewers (labkit/viz); loaded only when a kernel can show it
    from labkit.viz.canvas import TurtleCanvas
    TurtleCanvas(node)._ipython_display_()


def _terminal_window(node):
    """Started from a terminal (labkit ros2 run, live time): the window in a browser
    (labkit/viz/window.py); None elsewhere."""
    from labkit.viz import window
    if not window.ENABLED:
        return None
    from labkit.viz.canvas import render
    return window.open_window("TurtleSim", lambda: render(node.world),
                              lambda: node.world.version, node.get_logger().info)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleSim()
    _show_window(node)
    browser_window = _terminal_window(node)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    except Exception as exc:      # ExternalShutdownException: the process was stopped
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        if browser_window is not None:
            browser_window.close()
        node.destroy_node()
        rclpy.try_shutdown()
