"""`ros2 run turtlesim draw_square`: node /draw_square resets the simulator and drives
turtle1 round a 2 m square (forward, stop, turn 90 degrees, stop, ...).

Humble's own draw_square.cpp has a bug (its timer returns as soon as the first
pose arrives, so the turtle never moves); this follows the repaired version
(ros_tutorials #152), which is what the tutorials describe.
"""
import math

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node

from .cpp_node import like_rclcpp
from .physics import f32

Twist = get_type("geometry_msgs/msg/Twist")
Pose = get_type("turtlesim/msg/Pose")
Empty = get_type("std_srvs/srv/Empty")

PI = f32(3.141592)
FORWARD, STOP_FORWARD, TURN, STOP_TURN = range(4)


class DrawSquare(Node):
    def __init__(self):
        super().__init__("draw_square")
        like_rclcpp(self)
        self.twist_pub = self.create_publisher(Twist, "turtle1/cmd_vel", 1)
        self.pose_sub = self.create_subscription(Pose, "turtle1/pose", self.pose_callback, 1)
        self.reset_client = self.create_client(Empty, "reset")
        self.timer = self.create_timer(0.016, self.timer_callback)
        self.reset_result = self.reset_client.call_async(Empty.Request())
        self.pose = None
        self.goal = None            # (x, y, theta) as float32, like a Pose
        self.state = FORWARD

    def pose_callback(self, pose):
        self.pose = pose

    def has_reached_goal(self):
        p, (gx, gy, gt) = self.pose, self.goal
        return abs(f32(p.x - gx)) < 0.1 and abs(f32(p.y - gy)) < 0.1 and abs(f32(p.theta - gt)) < 0.01

    def has_stopped(self):
        return self.pose.angular_velocity < 0.0001 and self.pose.linear_velocity < 0.0001

    def set_goal(self, x, y, theta):
        self.goal = (f32(x), f32(y), f32(theta))
        self.get_logger().info("New goal [%f %f, %f]" % self.goal)

    def command(self, linear, angular):
        twist = Twist()
        twist.linear.x = float(linear)
        twist.angular.z = float(angular)
        self.twist_pub.publish(twist)

    def goal_ahead(self):
        p = self.pose
        self.set_goal(math.cos(p.theta) * 2 + p.x, math.sin(p.theta) * 2 + p.y, p.theta)

    def timer_callback(self):
        # start once the simulator has been reset and has told us where the turtle is
        if not self.reset_result.done() or self.pose is None:
            return
        if self.goal is None:
            self.state = FORWARD
            self.goal_ahead()

        if self.state == FORWARD:
            if self.has_reached_goal():
                self.state = STOP_FORWARD
                self.command(0, 0)
            else:
                self.command(1.0, 0)
        elif self.state == STOP_FORWARD:
            if self.has_stopped():
                self.get_logger().info("Reached goal")
                self.state = TURN
                theta = f32(math.fmod(f32(self.pose.theta + PI / 2.0), f32(2.0 * PI)))
                if theta >= PI:             # wrap to [-pi, pi)
                    theta = f32(theta - 2.0 * PI)
                self.set_goal(self.pose.x, self.pose.y, theta)
            else:
                self.command(0, 0)
        elif self.state == TURN:
            if self.has_reached_goal():
                self.state = STOP_TURN
                self.command(0, 0)
            else:
                self.command(0, 0.4)
        elif self.state == STOP_TURN:
            if self.has_stopped():
                self.get_logger().info("Reached goal")
                self.state = FORWARD
                self.goal_ahead()
            else:
                self.command(0, 0)


def main(args=None):
    rclpy.init(args=args)
    node = DrawSquare()
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
