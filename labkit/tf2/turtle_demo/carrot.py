"""carrot: a frame carried by a turtle (ten times a second on /tf).

Parameters: `parent` (turtle1), `frame` (carrot1), `offset_x`/`offset_y`
(0, 2: two metres to the turtle's left). With `radius` > 0 the carrot circles the
turtle instead, `turn_rate` radians a second.
"""
import math

import labkit.rclpy as rclpy
from labkit.rclpy.node import Node
from labkit.tf2.ros import TransformBroadcaster

from . import run
from .pose_to_tf import planar_transform


class Carrot(Node):
    def __init__(self):
        super().__init__("carrot")
        declare = self.declare_parameter
        self.parent = declare("parent", "turtle1").value
        self.frame = declare("frame", "carrot1").value
        self.offset = (declare("offset_x", 0.0).value, declare("offset_y", 2.0).value)
        self.radius = declare("radius", 0.0).value
        self.turn_rate = declare("turn_rate", 0.5).value
        self.sender = TransformBroadcaster(self)
        self.create_timer(0.1, self.tick)

    def where(self, seconds):
        if self.radius <= 0.0:
            return self.offset
        angle = self.turn_rate * seconds
        return self.radius * math.cos(angle), self.radius * math.sin(angle)

    def tick(self):
        now = self.get_clock().now()
        x, y = self.where(now.nanoseconds * 1e-9)
        self.sender.sendTransform(
            planar_transform(self.parent, self.frame, x, y, 0.0, now.to_msg()))


def main(args=None):
    rclpy.init(args=args)
    run(Carrot())
