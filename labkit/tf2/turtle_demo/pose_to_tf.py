"""pose_to_tf: republish a turtle's pose as a moving tf2 frame.

Parameter `turtle` (default turtle1): listens to /<turtle>/pose and sends the
transform world -> <turtle> on /tf, stamped with the time the pose arrived.
"""
import math

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.tf2.ros import TransformBroadcaster

from . import run

Pose = get_type("turtlesim/msg/Pose")
TransformStamped = get_type("geometry_msgs/msg/TransformStamped")


def planar_transform(parent, child, x, y, yaw, stamp):
    """A TransformStamped for a pose in the plane (only a turn about z)."""
    out = TransformStamped()
    out.header.stamp = stamp
    out.header.frame_id, out.child_frame_id = parent, child
    out.transform.translation.x, out.transform.translation.y = float(x), float(y)
    out.transform.rotation.z = math.sin(yaw / 2.0)
    out.transform.rotation.w = math.cos(yaw / 2.0)
    return out


class PoseToTf(Node):
    def __init__(self):
        super().__init__("pose_to_tf")
        self.turtle = self.declare_parameter("turtle", "turtle1").value
        self.sender = TransformBroadcaster(self)
        self.create_subscription(Pose, f"/{self.turtle}/pose", self.forward, 10)

    def forward(self, pose):
        stamp = self.get_clock().now().to_msg()
        self.sender.sendTransform(
            planar_transform("world", self.turtle, pose.x, pose.y, pose.theta, stamp))


def main(args=None):
    rclpy.init(args=args)
    run(PoseToTf())
