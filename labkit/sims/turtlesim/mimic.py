"""`ros2 run turtlesim mimic`: node /turtle_mimic, input/pose -> output/cmd_vel.

Remap the two names to make one turtle copy another, e.g.
`ros2 run turtlesim mimic --ros-args -r input/pose:=turtle1/pose -r output/cmd_vel:=turtle2/cmd_vel`.
"""
import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node

from .cpp_node import like_rclcpp

Twist = get_type("geometry_msgs/msg/Twist")
Pose = get_type("turtlesim/msg/Pose")


class Mimic(Node):
    def __init__(self):
        super().__init__("turtle_mimic")
        like_rclcpp(self)
        self.twist_pub = self.create_publisher(Twist, "output/cmd_vel", 1)
        self.pose_sub = self.create_subscription(Pose, "input/pose", self.pose_callback, 1)

    def pose_callback(self, pose):
        # the leader's body velocities, replayed: the follower draws the same shape
        twist = Twist()
        twist.angular.z = float(pose.angular_velocity)
        twist.linear.x = float(pose.linear_velocity)
        self.twist_pub.publish(twist)


def main(args=None):
    rclpy.init(args=args)
    node = Mimic()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    except Exception as exc:
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
