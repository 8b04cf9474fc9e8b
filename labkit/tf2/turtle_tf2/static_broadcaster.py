"""static_turtle_tf2_broadcaster child_frame_name x y z roll pitch yaw: world -> child, latched."""
import sys

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.tf2.ros import StaticTransformBroadcaster
from labkit.tf2.transformations import quaternion_from_euler

from . import spin_until_stopped

TransformStamped = get_type("geometry_msgs/msg/TransformStamped")


class StaticFramePublisher(Node):
    def __init__(self, transformation):
        super().__init__("static_turtle_tf2_broadcaster")
        self.tf_static_broadcaster = StaticTransformBroadcaster(self)
        self.make_transforms(transformation)

    def make_transforms(self, transformation):
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = "world"
        t.child_frame_id = transformation[1]
        t.transform.translation.x = float(transformation[2])
        t.transform.translation.y = float(transformation[3])
        t.transform.translation.z = float(transformation[4])
        quat = quaternion_from_euler(
            float(transformation[5]), float(transformation[6]), float(transformation[7]))
        t.transform.rotation.x = quat[0]
        t.transform.rotation.y = quat[1]
        t.transform.rotation.z = quat[2]
        t.transform.rotation.w = quat[3]
        self.tf_static_broadcaster.sendTransform(t)


def main(args=None):
    argv = list(sys.argv if args is None else args)
    logger = rclpy.logging.get_logger("logger")
    if len(argv) != 8:
        logger.info("Invalid number of parameters. Usage: \n"
                    "$ ros2 run turtle_tf2_py static_turtle_tf2_broadcaster"
                    "child_frame_name x y z roll pitch yaw")
        return 1
    if argv[1] == "world":
        logger.info('Your static turtle name cannot be "world"')
        return 2
    rclpy.init(args=argv)
    spin_until_stopped(StaticFramePublisher(argv))
