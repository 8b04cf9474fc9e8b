"""turtlesim_node driven by plain rclpy client code, in virtual time."""
import math

import pytest

import labkit.rclpy as rclpy
from labkit import process
from labkit.interfaces import get_type
from labkit.rclpy.action import ActionClient
from labkit.sims.turtlesim import physics

Twist = get_type("geometry_msgs/msg/Twist")
Pose = get_type("turtlesim/msg/Pose")
Color = get_type("turtlesim/msg/Color")
Spawn = get_type("turtlesim/srv/Spawn")
Kill = get_type("turtlesim/srv/Kill")
SetPen = get_type("turtlesim/srv/SetPen")
TeleportAbsolute = get_type("turtlesim/srv/TeleportAbsolute")
TeleportRelative = get_type("turtlesim/srv/TeleportRelative")
Empty = get_type("std_srvs/srv/Empty")
RotateAbsolute = get_type("turtlesim/action/RotateAbsolute")
GoalStatus = get_type("action_msgs/msg/GoalStatus")
GetParameters = get_type("rcl_interfaces/srv/GetParameters")
SetParameters = get_type("rcl_interfaces/srv/SetParameters")
DescribeParameters = get_type("rcl_interfaces/srv/DescribeParameters")
Parameter = get_type("rcl_interfaces/msg/Parameter")
ParameterValue = get_type("rcl_interfaces/msg/ParameterValue")


class Client:
    """A test node with helpers to call, listen and wait (in virtual time)."""

    def __init__(self):
        rclpy.init()
        self.node = rclpy.create_node("tester")
        self.poses = {}
        self.colors = {}

    def listen(self, turtle="turtle1"):
        self.poses.setdefault(turtle, [])
        self.colors.setdefault(turtle, [])
        self.node.create_subscription(Pose, "/%s/pose" % turtle, self.poses[turtle].append, 10)
        self.node.create_subscription(Color, "/%s/color_sensor" % turtle,
                                      self.colors[turtle].append, 10)

    def spin_for(self, seconds):
        clock = self.node.get_clock()
        end = clock.now().nanoseconds + int(seconds * 1e9)
        while clock.now().nanoseconds < end:
            rclpy.spin_once(self.node, timeout_sec=(end - clock.now().nanoseconds) / 1e9)

    def wait(self, future, timeout=5.0):
        rclpy.spin_until_future_complete(self.node, future, timeout_sec=timeout)
        assert future.done()
        return future.result()

    def call(self, srv_type, service, **fields):
        client = self.node.create_client(srv_type, service)
        assert client.wait_for_service(timeout_sec=2.0)
        response = self.wait(client.call_async(srv_type.Request(**fields)))
        self.node.destroy_client(client)
        return response

    def publish_twist(self, turtle="turtle1", x=0.0, y=0.0, z=0.0):
        pub = self.node.create_publisher(Twist, "/%s/cmd_vel" % turtle, 10)
        msg = Twist()
        msg.linear.x, msg.linear.y, msg.angular.z = float(x), float(y), float(z)
        pub.publish(msg)
        self.node.destroy_publisher(pub)

    def set_background(self, **values):
        params = [Parameter(name=k, value=ParameterValue(type=2, integer_value=v))
                  for k, v in values.items()]
        return self.call(SetParameters, "/turtlesim/set_parameters", parameters=params)


@pytest.fixture
def sim():
    proc = process.start(["turtlesim", "turtlesim_node"], echo=False)
    client = Client()
    yield proc, client
    client.node.destroy_node()
    rclpy.try_shutdown()
    proc.stop()


def logs(proc):
    return "\n".join(proc.output)


def test_startup_lines_and_interface(sim):
    proc, c = sim
    text = logs(proc)
    assert "[INFO]" in text
    assert "[turtlesim]: Starting turtlesim with node name /turtlesim" in text
    assert "[turtlesim]: Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]" in text
    topics = dict(c.node.get_topic_names_and_types())
    assert topics["/turtle1/cmd_vel"] == ["geometry_msgs/msg/Twist"]
    assert topics["/turtle1/pose"] == ["turtlesim/msg/Pose"]
    assert topics["/turtle1/color_sensor"] == ["turtlesim/msg/Color"]
    services = dict(c.node.get_service_names_and_types())
    for name, kind in (("/clear", "std_srvs/srv/Empty"), ("/reset", "std_srvs/srv/Empty"),
                       ("/spawn", "turtlesim/srv/Spawn"), ("/kill", "turtlesim/srv/Kill"),
                       ("/turtle1/set_pen", "turtlesim/srv/SetPen"),
                       ("/turtle1/teleport_absolute", "turtlesim/srv/TeleportAbsolute"),
                       ("/turtle1/teleport_relative", "turtlesim/srv/TeleportRelative")):
        assert services[name] == [kind]
    assert "/turtle1/rotate_absolute/_action/send_goal" in services
    assert ("turtlesim", "/") in c.node.get_node_names_and_namespaces()


def test_pose_after_one_second_at_two_metres_per_second(sim):
    proc, c = sim
    c.listen()
    c.spin_for(0.1)
    start = c.poses["turtle1"][-1]
    assert (start.x, start.y, start.theta) == (5.544444561004639, 5.544444561004639, 0.0)
    c.publish_twist(x=2.0)
    c.spin_for(0.5)
    assert c.poses["turtle1"][-1].linear_velocity == 2.0
    c.spin_for(1.0)
    end = c.poses["turtle1"][-1]
    # 62 or 63 ticks of 16 ms inside the 1 s the command lasts, depending on the phase
    assert end.x - start.x == pytest.approx(2.0, abs=0.04)
    assert end.y == pytest.approx(start.y)
    assert end.linear_velocity == 0.0          # the command timed out: the turtle stopped
    c.spin_for(0.5)
    assert c.poses["turtle1"][-1].x == end.x


def test_pose_rate_is_62_5_hz(sim):
    proc, c = sim
    c.listen()
    c.spin_for(0.1)
    n0 = len(c.poses["turtle1"])
    c.spin_for(1.0)
    assert len(c.poses["turtle1"]) - n0 in (62, 63)


def test_wall_clamp_and_warning(sim):
    proc, c = sim
    c.listen()
    c.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=10.9, y=3.0, theta=0.0)
    c.publish_twist(x=2.0)
    c.spin_for(0.5)
    assert c.poses["turtle1"][-1].x == pytest.approx(physics.WIDTH_IN_METERS)
    warnings = [line for line in proc.output if "Oh no! I hit the wall!" in line]
    assert warnings and "[WARN]" in warnings[0]
    assert "[turtlesim]: Oh no! I hit the wall! (Clamping from [x=11.0" in warnings[0]
    assert warnings[0].endswith(", y=8.088889])")


def test_spawn_names_errors_and_kill(sim):
    proc, c = sim
    assert c.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.2, name="").name == "turtle2"
    assert c.call(Spawn, "/spawn", x=3.0, y=3.0, theta=0.0, name="").name == "turtle3"
    assert "Spawning turtle [turtle2] at x=[2.000000], y=[2.000000], theta=[0.200000]" in logs(proc)
    # a taken name: an empty answer and ROS's error line
    assert c.call(Spawn, "/spawn", x=1.0, y=1.0, theta=0.0, name="turtle1").name == ""
    assert "[ERROR]" in logs(proc)
    assert "[turtlesim]: A turtle named [turtle1] already exists" in logs(proc)
    topics = dict(c.node.get_topic_names_and_types())
    assert "/turtle3/pose" in topics
    c.call(Kill, "/kill", name="turtle3")
    c.spin_for(0.05)
    topics = dict(c.node.get_topic_names_and_types())
    assert "/turtle3/pose" not in topics and "/turtle2/pose" in topics
    c.call(Kill, "/kill", name="nobody")
    assert "[turtlesim]: Tried to kill turtle [nobody], which does not exist" in logs(proc)


def test_reset_respawns_turtle1_only(sim):
    proc, c = sim
    c.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.0, name="")
    c.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=1.0, y=1.0, theta=1.0)
    c.spin_for(0.1)
    c.call(Empty, "/reset")
    assert "[turtlesim]: Resetting turtlesim." in logs(proc)
    c.spin_for(0.05)
    topics = dict(c.node.get_topic_names_and_types())
    assert "/turtle2/pose" not in topics
    c.listen()
    c.spin_for(0.1)
    pose = c.poses["turtle1"][-1]
    assert (pose.x, pose.y, pose.theta) == (5.544444561004639, 5.544444561004639, 0.0)
    assert c.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.0, name="").name == "turtle2"


def test_clear(sim):
    proc, c = sim
    world = process_world()
    c.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=1.0, y=1.0, theta=0.0)
    c.spin_for(0.1)
    assert (world.path.pixels[..., 3] > 0).any()
    c.call(Empty, "/clear")
    assert "[turtlesim]: Clearing turtlesim." in logs(proc)
    assert not (world.path.pixels[..., 3] > 0).any()


def process_world():
    from labkit.sims.turtlesim.node import running
    return running()[-1].world


def test_parameters_defaults_and_background_change(sim):
    proc, c = sim
    names = ["background_r", "background_g", "background_b", "use_sim_time",
             "qos_overrides./parameter_events.publisher.depth",
             "qos_overrides./parameter_events.publisher.durability",
             "qos_overrides./parameter_events.publisher.history",
             "qos_overrides./parameter_events.publisher.reliability"]
    values = c.call(GetParameters, "/turtlesim/get_parameters", names=names).values
    assert [v.integer_value for v in values[:3]] == [69, 86, 255]
    assert values[3].bool_value is False
    assert values[4].integer_value == 1000
    assert [v.string_value for v in values[5:]] == ["volatile", "keep_last", "reliable"]
    described = c.call(DescribeParameters, "/turtlesim/describe_parameters",
                       names=["background_r", "qos_overrides./parameter_events.publisher.depth"])
    r, depth = described.descriptors
    assert r.description == "Red channel of the background color"
    assert (r.integer_range[0].from_value, r.integer_range[0].to_value) == (0, 255)
    assert depth.read_only
    result = c.set_background(background_r=255, background_g=0)
    assert all(res.successful for res in result.results)
    c.spin_for(0.1)
    assert process_world().background == (255, 0, 255)
    refused = c.call(SetParameters, "/turtlesim/set_parameters", parameters=[Parameter(
        name="qos_overrides./parameter_events.publisher.depth",
        value=ParameterValue(type=2, integer_value=5))])
    assert not refused.results[0].successful


def test_set_pen_and_color_sensor(sim):
    proc, c = sim
    c.listen()
    c.spin_for(0.05)
    assert (c.colors["turtle1"][-1].r, c.colors["turtle1"][-1].g, c.colors["turtle1"][-1].b) \
        == (255, 255, 255)
    c.publish_twist(x=1.0)
    c.spin_for(0.2)
    last = c.colors["turtle1"][-1]
    assert (last.r, last.g, last.b) == (179, 184, 255)
    c.call(SetPen, "/turtle1/set_pen", r=255, g=0, b=0, width=5, off=0)
    c.publish_twist(x=1.0)
    c.spin_for(0.2)
    last = c.colors["turtle1"][-1]
    assert (last.r, last.g, last.b) == (255, 0, 0)
    c.call(SetPen, "/turtle1/set_pen", r=0, g=0, b=0, width=0, off=1)
    world = process_world()
    drawn = int((world.path.pixels[..., 3] > 0).sum())
    c.publish_twist(x=1.0)
    c.spin_for(0.3)
    assert int((world.path.pixels[..., 3] > 0).sum()) == drawn


def test_teleport_absolute_and_relative(sim):
    proc, c = sim
    c.listen()
    c.call(TeleportAbsolute, "/turtle1/teleport_absolute", x=2.0, y=3.0, theta=math.pi / 2)
    c.spin_for(0.05)
    pose = c.poses["turtle1"][-1]
    assert (pose.x, pose.y, pose.theta) == pytest.approx((2.0, 3.0, math.pi / 2), abs=1e-6)
    c.call(TeleportRelative, "/turtle1/teleport_relative", linear=1.0, angular=0.0)
    c.spin_for(0.05)
    pose = c.poses["turtle1"][-1]
    assert (pose.x, pose.y) == pytest.approx((2.0, 4.0), abs=1e-5)


def _action(c):
    client = ActionClient(c.node, RotateAbsolute, "/turtle1/rotate_absolute")
    assert client.wait_for_server(timeout_sec=2.0)
    return client


def test_rotate_absolute_feedback_and_result(sim):
    proc, c = sim
    client = _action(c)
    feedback = []
    handle = c.wait(client.send_goal_async(
        RotateAbsolute.Goal(theta=-1.57), feedback_callback=lambda m: feedback.append(m.feedback.remaining)))
    assert handle.accepted
    response = c.wait(handle.get_result_async(), timeout=5.0)
    assert response.status == GoalStatus.STATUS_SUCCEEDED
    assert response.result.delta == 1.5520000457763672
    assert feedback[0] == -1.5700000524520874 and feedback[1] == -1.5540000200271606
    assert feedback[-1] == -0.018000006675720215
    assert "[turtlesim]: Rotation goal completed successfully" in logs(proc)


def test_rotate_absolute_cancel(sim):
    proc, c = sim
    client = _action(c)
    handle = c.wait(client.send_goal_async(RotateAbsolute.Goal(theta=3.0)))
    c.spin_for(0.5)
    c.wait(handle.cancel_goal_async())
    response = c.wait(handle.get_result_async())
    assert response.status == GoalStatus.STATUS_CANCELED
    assert response.result.delta == pytest.approx(-0.5, abs=0.05)
    assert "[turtlesim]: Rotation goal canceled" in logs(proc)


def test_rotate_absolute_preempted_by_goal_and_by_cmd_vel(sim):
    proc, c = sim
    client = _action(c)
    first = c.wait(client.send_goal_async(RotateAbsolute.Goal(theta=3.0)))
    c.spin_for(0.2)
    second = c.wait(client.send_goal_async(RotateAbsolute.Goal(theta=-3.0)))
    assert c.wait(first.get_result_async()).status == GoalStatus.STATUS_ABORTED
    assert "Rotation goal received before a previous goal finished. Aborting previous goal" \
        in logs(proc)
    c.spin_for(0.2)
    c.publish_twist(x=1.0)
    assert c.wait(second.get_result_async()).status == GoalStatus.STATUS_ABORTED
    assert "[turtlesim]: Velocity command received during rotation goal. Aborting goal" in logs(proc)


def test_two_turtles_move_independently(sim):
    proc, c = sim
    c.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.0, name="leo")
    c.listen("turtle1")
    c.listen("leo")
    c.publish_twist("leo", x=1.0)
    c.spin_for(0.5)
    assert c.poses["leo"][-1].x > 2.3
    assert c.poses["turtle1"][-1].x == 5.544444561004639


def test_spawn_with_an_invalid_name_is_refused(sim):
    proc, c = sim
    assert c.call(Spawn, "/spawn", x=1.0, y=1.0, theta=0.0, name="my turtle").name == ""
    assert "Cannot spawn turtle [my turtle]" in logs(proc)
    assert "my turtle" not in process_world().turtles
    assert c.call(Spawn, "/spawn", x=1.0, y=1.0, theta=0.0, name="").name == "turtle2"


def test_canvas_follows_a_restarted_turtlesim(sim):
    from labkit.viz.canvas import TurtleCanvas
    proc, c = sim
    canvas = TurtleCanvas.attach()
    first = canvas.world
    proc.stop()
    again = process.start(["turtlesim", "turtlesim_node"], echo=False)
    try:
        canvas.snapshot()
        assert canvas.world is not first and canvas.world is process_world()
    finally:
        again.stop()
    with pytest.raises(RuntimeError, match="turtlesim is not running"):
        TurtleCanvas.attach()


def test_killing_a_rotating_turtle_removes_its_action_server(sim):
    proc, c = sim
    client = _action(c)
    handle = c.wait(client.send_goal_async(RotateAbsolute.Goal(theta=3.0)))
    c.spin_for(0.2)
    c.call(Kill, "/kill", name="turtle1")
    c.spin_for(0.1)
    # like rclcpp, the server goes with the turtle: no result will come, nothing crashed
    assert not client.server_is_ready()
    assert "Traceback" not in logs(proc) and proc.running
    assert process_world().turtles == {}
