"""The walking r2d2 of the Humble tutorial "Using URDF with robot_state_publisher":
a `state_publisher` node that moves swivel/tilt/periscope and walks `axis`
around a 2 m circle under `odom` (30 Hz). Written with a timer (the tutorial's
Rate-in-a-spin_once loop can block), same motion and messages.

`start_demo()` starts robot_state_publisher with r2d2.urdf.xml plus this node,
like `ros2 launch urdf_tutorial_r2d2 demo.launch.py`.
"""
import math
import os

import labkit.rclpy as rclpy
from labkit.interfaces import module
from labkit.rclpy.executors import ExternalShutdownException
from labkit.rclpy.node import Node
from labkit.rclpy.qos import QoSProfile

DEGREE = math.pi / 180.0


def euler_to_quaternion(roll, pitch, yaw):
    Quaternion = module("geometry_msgs.msg").Quaternion
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return Quaternion(x=sr * cp * cy - cr * sp * sy, y=cr * sp * cy + sr * cp * sy,
                      z=cr * cp * sy - sr * sp * cy, w=cr * cp * cy + sr * sp * sy)


class R2D2Motion:
    """The tutorial's state: one `step()` per 1/30 s."""

    def __init__(self):
        self.tilt, self.tinc = 0.0, DEGREE
        self.swivel, self.angle = 0.0, 0.0
        self.height, self.hinc = 0.0, 0.005

    def joints(self):
        return {"swivel": self.swivel, "tilt": self.tilt, "periscope": self.height}

    def odom(self):
        """(xyz, yaw) of `axis` in `odom`."""
        return ((math.cos(self.angle) * 2, math.sin(self.angle) * 2, 0.7),
                self.angle + math.pi / 2)

    def step(self):
        self.tilt += self.tinc
        if self.tilt < -0.5 or self.tilt > 0.0:
            self.tinc *= -1
        self.height += self.hinc
        if self.height > 0.2 or self.height < 0.0:
            self.hinc *= -1
        self.swivel += DEGREE
        self.angle += DEGREE / 4


class StatePublisher(Node):

    def __init__(self):
        super().__init__("state_publisher")
        qos = QoSProfile(depth=10)
        JointState = module("sensor_msgs.msg").JointState
        self.joint_pub = self.create_publisher(JointState, "joint_states", qos)
        self.tf_pub = self.create_publisher(module("tf2_msgs.msg").TFMessage, "/tf",
                                            QoSProfile(depth=100))
        self.motion = R2D2Motion()
        self.get_logger().info("{0} started".format(self.get_name()))
        self.timer = self.create_timer(1.0 / 30, self.on_timer)

    def on_timer(self):
        from labkit.robots.robot_state_publisher import transform_stamped
        now = self.get_clock().now().to_msg()
        m = self.motion
        joint_state = module("sensor_msgs.msg").JointState()
        joint_state.header.stamp = now
        joint_state.name = ["swivel", "tilt", "periscope"]
        joint_state.position = [m.swivel, m.tilt, m.height]
        xyz, yaw = m.odom()
        q = euler_to_quaternion(0, 0, yaw)
        tf = module("tf2_msgs.msg").TFMessage()
        tf.transforms = [transform_stamped("odom", "axis", now, xyz, (q.x, q.y, q.z, q.w))]
        self.joint_pub.publish(joint_state)
        self.tf_pub.publish(tf)
        m.step()


def main(args=None):
    rclpy.init(args=args)
    node = StatePublisher()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


def urdf_path():
    """The reader's urdf_tutorial_r2d2 copy if a sourced workspace has it, else labkit's."""
    from labkit.robots import packages
    try:
        path = os.path.join(packages.share_directory("urdf_tutorial_r2d2"), "r2d2.urdf.xml")
        if os.path.exists(path):
            return path
    except (KeyError, LookupError):
        pass
    return packages.R2D2_URDF


def start_demo(echo=True):
    """robot_state_publisher (r2d2.urdf.xml) + state_publisher; returns both processes."""
    from labkit import process
    with open(urdf_path(), encoding="utf-8") as handle:
        description = handle.read()
    rsp = start_robot_state_publisher(description, echo=echo)
    walker = process.start(main=main, name="state_publisher", echo=echo)
    return rsp, walker


def start_robot_state_publisher(description, echo=True, extra_args=()):
    """Start robot_state_publisher with `robot_description` set (what a launch file does)."""
    from labkit import process
    from labkit.robots import robot_state_publisher

    def run(args=None):
        return robot_state_publisher.main_with_description(description, args)
    return process.start(main=run, name="robot_state_publisher", echo=echo,
                         args=["robot_state_publisher", *extra_args])
