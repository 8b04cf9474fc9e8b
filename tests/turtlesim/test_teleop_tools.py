"""turtle_teleop_key (key map, press()), mimic and draw_square against a running turtlesim."""
import re

import pytest

import labkit.rclpy as rclpy
from labkit import process
from labkit.interfaces import get_type
from labkit.sims.turtlesim import keys, teleop

Pose = get_type("turtlesim/msg/Pose")
Twist = get_type("geometry_msgs/msg/Twist")
Spawn = get_type("turtlesim/srv/Spawn")
GetParameters = get_type("rcl_interfaces/srv/GetParameters")


class Watcher:
    def __init__(self):
        rclpy.init()
        self.node = rclpy.create_node("watcher")
        self.poses = {}
        self.twists = []

    def listen(self, turtle):
        self.poses[turtle] = []
        self.node.create_subscription(Pose, "/%s/pose" % turtle, self.poses[turtle].append, 10)

    def spin_for(self, seconds):
        clock = self.node.get_clock()
        end = clock.now().nanoseconds + int(seconds * 1e9)
        while clock.now().nanoseconds < end:
            rclpy.spin_once(self.node, timeout_sec=(end - clock.now().nanoseconds) / 1e9)

    def call(self, srv_type, service, **fields):
        client = self.node.create_client(srv_type, service)
        assert client.wait_for_service(timeout_sec=2.0)
        future = client.call_async(srv_type.Request(**fields))
        rclpy.spin_until_future_complete(self.node, future, timeout_sec=5.0)
        return future.result()


@pytest.fixture
def watcher():
    w = Watcher()
    yield w
    w.node.destroy_node()
    rclpy.try_shutdown()


@pytest.fixture
def turtlesim():
    proc = process.start(["turtlesim", "turtlesim_node"], echo=False)
    yield proc
    proc.stop()


def test_key_names():
    assert keys.key_name("ArrowUp") == "up" and keys.key_name("LEFT") == "left"
    assert keys.key_name("G") == "g" and keys.key_name("x") is None
    assert set(keys.ROTATE) == set("gbvcdert")
    assert keys.ROTATE["r"] == 1.5708 and keys.ROTATE["b"] == -0.7854


def test_press_without_teleop_says_so():
    with pytest.raises(RuntimeError, match="turtle_teleop_key is not running"):
        teleop.press("up")


def test_teleop_banner_parameters_and_arrows(turtlesim, watcher):
    tele = process.start(["turtlesim", "turtle_teleop_key"], echo=False)
    assert tele.output[:5] == keys.BANNER.split("\n")
    values = watcher.call(GetParameters, "/teleop_turtle/get_parameters",
                          names=["scale_angular", "scale_linear"]).values
    assert [v.double_value for v in values] == [2.0, 2.0]
    assert ("teleop_turtle", "/") in watcher.node.get_node_names_and_namespaces()
    # an rclcpp node: rclcpp's parameter-events subscription and qos_overrides parameters
    subs = {name: types for name, types in
            watcher.node.get_subscriber_names_and_types_by_node("teleop_turtle", "/")
            if "/_" not in name}                       # hidden action topics aside
    assert subs == {"/parameter_events": ["rcl_interfaces/msg/ParameterEvent"]}
    pubs = dict(watcher.node.get_publisher_names_and_types_by_node("teleop_turtle", "/"))
    assert pubs["/turtle1/cmd_vel"] == ["geometry_msgs/msg/Twist"]
    depth = watcher.call(GetParameters, "/teleop_turtle/get_parameters",
                         names=["qos_overrides./parameter_events.publisher.depth"]).values
    assert depth[0].integer_value == 1000
    watcher.listen("turtle1")
    watcher.spin_for(0.1)
    x0 = watcher.poses["turtle1"][-1].x
    teleop.press("up")
    watcher.spin_for(0.3)
    assert watcher.poses["turtle1"][-1].linear_velocity == 2.0     # scale_linear * 1.0
    watcher.spin_for(1.0)
    assert watcher.poses["turtle1"][-1].x - x0 == pytest.approx(2.0, abs=0.04)
    teleop.press("left")
    watcher.spin_for(0.2)
    assert watcher.poses["turtle1"][-1].angular_velocity == 2.0    # scale_angular * 1.0
    with pytest.raises(ValueError):
        teleop.press("x")
    tele.stop()


def test_teleop_rotation_keys_and_cancel(turtlesim, watcher):
    tele = process.start(["turtlesim", "turtle_teleop_key"], echo=False)
    watcher.listen("turtle1")
    teleop.press("r")                       # rotate to 1.5708
    watcher.spin_for(2.0)
    assert watcher.poses["turtle1"][-1].theta == pytest.approx(1.5708, abs=0.02)
    assert "Rotation goal completed successfully" in "\n".join(turtlesim.output)
    teleop.press("v")                       # to -1.5708: needs ~3 s
    watcher.spin_for(0.5)
    teleop.press("f")
    watcher.spin_for(0.2)
    assert "Rotation goal canceled" in "\n".join(turtlesim.output)
    theta = watcher.poses["turtle1"][-1].theta
    watcher.spin_for(0.5)
    assert watcher.poses["turtle1"][-1].theta == theta   # stopped where it was
    tele.stop()


def test_teleop_q_quits(turtlesim, watcher):
    tele = process.start(["turtlesim", "turtle_teleop_key"], echo=False)
    assert tele.running
    teleop.press("q")
    watcher.spin_for(0.1)
    assert not tele.running
    assert teleop.running() == []


def test_mimic_copies_the_leader(turtlesim, watcher):
    watcher.call(Spawn, "/spawn", x=2.0, y=2.0, theta=0.0, name="turtle2")
    mimic = process.start(["turtlesim", "mimic", "--ros-args",
                           "-r", "input/pose:=turtle1/pose",
                           "-r", "output/cmd_vel:=turtle2/cmd_vel"], echo=False)
    assert ("turtle_mimic", "/") in watcher.node.get_node_names_and_namespaces()
    watcher.listen("turtle1")
    watcher.listen("turtle2")
    pub = watcher.node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    twist = Twist()
    twist.linear.x, twist.angular.z = 1.0, 0.5
    pub.publish(twist)
    watcher.spin_for(1.5)
    leader, follower = watcher.poses["turtle1"][-1], watcher.poses["turtle2"][-1]
    assert leader.theta == pytest.approx(0.5, abs=0.05)
    assert follower.theta == pytest.approx(leader.theta, abs=0.05)     # same turn...
    assert follower.x - 2.0 == pytest.approx(leader.x - 5.544444561004639, abs=0.1)  # ...same path
    mimic.stop()


def test_draw_square_drives_a_square(turtlesim, watcher):
    drawer = process.start(["turtlesim", "draw_square"], echo=False)
    watcher.listen("turtle1")
    watcher.spin_for(9.0)
    text = "\n".join(drawer.output)
    assert "[draw_square]: New goal [7.544445 5.544445, 0.000000]" in text
    assert "[draw_square]: Reached goal" in text
    assert re.search(r"New goal \[7\.\d+ 5\.5444\d\d, 1\.570796\]", text)
    pose = watcher.poses["turtle1"][-1]
    assert pose.x == pytest.approx(7.54, abs=0.15)      # at the first corner, turning north
    assert pose.y > 5.5
    drawer.stop()
