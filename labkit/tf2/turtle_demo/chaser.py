"""chaser: a second turtle that drives toward a tf2 frame.

Parameters: `chaser` (turtle2) is spawned at (`start_x`, `start_y`) = (4, 2);
`target` (turtle1) is the frame it heads for. Five times a second it asks tf2
where `target` is as seen from `chaser` and sets its speed from the answer.
"""
import math

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.rclpy.time import Time
from labkit.tf2.ros import Buffer, TransformException, TransformListener

from . import run

Spawn = get_type("turtlesim/srv/Spawn")
Twist = get_type("geometry_msgs/msg/Twist")


class Chaser(Node):
    def __init__(self):
        super().__init__("chaser")
        self.me = self.declare_parameter("chaser", "turtle2").value
        self.target = self.declare_parameter("target", "turtle1").value
        self.start = (self.declare_parameter("start_x", 4.0).value,
                      self.declare_parameter("start_y", 2.0).value)
        self.frames = Buffer()
        self.frames_in = TransformListener(self.frames, self)
        self.spawn = self.create_client(Spawn, "spawn")
        self.spawned = None          # the future of the spawn call
        self.drive = self.create_publisher(Twist, f"{self.me}/cmd_vel", 10)
        self.create_timer(0.2, self.step)

    def step(self):
        if self.spawned is None:
            if not self.spawn.service_is_ready():
                self.get_logger().info("waiting for the spawn service")
                return
            self.spawned = self.spawn.call_async(
                Spawn.Request(x=float(self.start[0]), y=float(self.start[1]), name=self.me))
            return
        if not self.spawned.done():
            return
        try:
            seen = self.frames.lookup_transform(self.me, self.target, Time())
        except TransformException as err:
            self.get_logger().info(f"no {self.target} seen from {self.me} yet: {err}")
            return
        ahead = seen.transform.translation
        cmd = Twist()
        cmd.angular.z = 2.0 * math.atan2(ahead.y, ahead.x)     # turn toward it
        cmd.linear.x = 0.8 * math.hypot(ahead.x, ahead.y)      # faster when far
        self.drive.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    run(Chaser())
