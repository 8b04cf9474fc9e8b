"""labkit's turtle_tf2_demo package: turtle2 chases a frame through TF (virtual time)."""
import math

import pytest

import labkit
import labkit.rclpy as rclpy
from labkit import process
from labkit.interfaces import get_type
from labkit.rclpy.time import Time
from labkit.tf2 import ros as tf2_ros

Pose = get_type("turtlesim/msg/Pose")


def run(*argv):
    return process.start(list(argv), echo=False)


def start_demo(target="turtle1"):
    run("turtlesim", "turtlesim_node")
    run("turtle_tf2_demo", "pose_to_tf", "--ros-args", "-r", "__node:=turtle1_tf",
        "-p", "turtle:=turtle1")
    run("turtle_tf2_demo", "pose_to_tf", "--ros-args", "-r", "__node:=turtle2_tf",
        "-p", "turtle:=turtle2")
    return run("turtle_tf2_demo", "chaser", "--ros-args", "-p", f"target:={target}")


class Watcher:
    def __init__(self):
        rclpy.init()
        self.node = rclpy.create_node("watcher")
        self.poses = {}
        for name in ("turtle1", "turtle2"):
            self.node.create_subscription(
                Pose, f"/{name}/pose", lambda m, n=name: self.poses.__setitem__(n, m), 10)
        self.buffer = tf2_ros.Buffer()
        tf2_ros.TransformListener(self.buffer, self.node)

    def spin_for(self, seconds):
        clock = self.node.get_clock()
        end = clock.now().nanoseconds + int(seconds * 1e9)
        while clock.now().nanoseconds < end:
            rclpy.spin_once(self.node, timeout_sec=0.1)

    def distance(self):
        a, b = self.poses["turtle1"], self.poses["turtle2"]
        return math.hypot(a.x - b.x, a.y - b.y)


def test_turtle2_follows_turtle1():
    start_demo()
    w = Watcher()
    w.spin_for(0.5)
    assert "turtle2" in w.poses
    start = w.distance()
    assert start > 3.0                       # spawned at (4, 2), turtle1 at the centre
    t = w.buffer.lookup_transform("world", "turtle1", Time())
    assert t.transform.translation.x == w.poses["turtle1"].x
    # a pose in the plane: a turn about z only, by theta
    theta = w.poses["turtle1"].theta
    r = t.transform.rotation
    assert (r.x, r.y, r.z, r.w) == pytest.approx((0, 0, math.sin(theta / 2), math.cos(theta / 2)))
    w.spin_for(15.0)
    assert w.distance() < 0.5 * start
    # and it keeps following when turtle1 moves
    Twist = get_type("geometry_msgs/msg/Twist")
    pub = w.node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    for _ in range(3):
        msg = Twist()
        msg.linear.x = 2.0
        pub.publish(msg)
        w.spin_for(0.5)
    moved = w.distance()
    w.spin_for(15.0)
    assert w.distance() < moved
    labkit.reset()


def test_carrot_frames():
    run("turtlesim", "turtlesim_node")
    run("turtle_tf2_demo", "pose_to_tf")
    run("turtle_tf2_demo", "carrot")
    w = Watcher()
    w.spin_for(1.0)
    t = w.buffer.lookup_transform("world", "carrot1", Time())
    p = w.poses["turtle1"]
    # 2 m to the left of turtle1, which faces +x at the start
    assert (t.transform.translation.x, t.transform.translation.y) == pytest.approx(
        (p.x, p.y + 2.0))
    labkit.reset()
    run("turtlesim", "turtlesim_node")
    run("turtle_tf2_demo", "pose_to_tf")
    run("turtle_tf2_demo", "carrot", "--ros-args", "-p", "radius:=3.0")
    w = Watcher()
    w.spin_for(1.0)
    t = w.buffer.lookup_transform("turtle1", "carrot1", Time())
    assert math.hypot(t.transform.translation.x, t.transform.translation.y) == \
        pytest.approx(3.0)
    w.spin_for(1.0)         # it circles: 0.5 rad/s by default
    later = w.buffer.lookup_transform("turtle1", "carrot1", Time())
    turned = math.atan2(later.transform.translation.y, later.transform.translation.x) - \
        math.atan2(t.transform.translation.y, t.transform.translation.x)
    assert turned == pytest.approx(0.5, abs=0.06)
    labkit.reset()


def test_chase_carrot_launch_file():
    job = labkit.ros2("launch turtle_tf2_demo chase_carrot.launch.py orbit:=true")
    w = Watcher()
    w.spin_for(2.0)
    assert sorted(labkit.ros2("node list").stdout.split()) == [
        "/carrot", "/chaser", "/sim", "/turtle1_tf", "/turtle2_tf", "/watcher"]
    assert labkit.ros2("param get /chaser target").stdout.strip() == "String value is: carrot1"
    assert labkit.ros2("param get /carrot radius").stdout.strip() == "Double value is: 2.0"
    t = w.buffer.lookup_transform("world", "carrot1", Time())
    start = math.hypot(t.transform.translation.x - 4.0, t.transform.translation.y - 2.0)
    w.spin_for(12.0)
    turtle2 = w.buffer.lookup_transform("carrot1", "turtle2", Time()).transform.translation
    assert math.hypot(turtle2.x, turtle2.y) < 0.5 * start     # turtle2 caught up with it
    job.stop()
