"""turtle_tf2_broadcaster: /<turtlename>/pose -> transform world -> <turtlename> on /tf."""
import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.tf2.ros import TransformBroadcaster
from labkit.tf2.transformations import quaternion_from_euler

from . import spin_until_stopped

TransformStamped = get_type("geometry_msgs/msg/TransformStamped")
Pose = get_type("turtlesim/msg/Pose")


class FramePublisher(Node):
    def __init__(self):
        super().__init__("turtle_tf2_frame_publisher")
        self.turtlename = self.declare_parameter(
            "turtlename", "turtle").get_parameter_value().string_value
        self.tf_broadcaster = TransformBroadcaster(self)
        self.subscription = self.create_subscription(
            Pose, f"/{self.turtlename}/pose", self.handle_turtle_pose, 1)

    def handle_turtle_pose(self, msg):
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = self.turtlename
        # a turtle lives in the plane: x, y and a yaw
        t.transform.translation.x = msg.x
        t.transform.translation.y = msg.y
        t.transform.translation.z = 0.0
        q = quaternion_from_euler(0, 0, msg.theta)
        t.transform.rotation.x = q[0]
        t.transform.rotation.y = q[1]
        t.transform.rotation.z = q[2]
        t.transform.rotation.w = q[3]
        self.tf_broadcaster.sendTransform(t)


def main(args=None):
    rclpy.init(args=args)
    spin_until_stopped(FramePublisher())
