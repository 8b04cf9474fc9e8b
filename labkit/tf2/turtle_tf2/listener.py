"""turtle_tf2_listener: spawns turtle2 and steers it toward target_frame (turtle1) each second."""
import math

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.rclpy.time import Time
from labkit.tf2.ros import Buffer, TransformException, TransformListener

from . import spin_until_stopped

Twist = get_type("geometry_msgs/msg/Twist")
Spawn = get_type("turtlesim/srv/Spawn")


class FrameListener(Node):
    def __init__(self):
        super().__init__("turtle_tf2_frame_listener")
        self.target_frame = self.declare_parameter(
            "target_frame", "turtle1").get_parameter_value().string_value
        self.tf_buffer = Buffer()
        self.tf_listener = TransformListener(self.tf_buffer, self)
        self.spawner = self.create_client(Spawn, "spawn")
        self.turtle_spawning_service_ready = False
        self.turtle_spawned = False
        self.publisher = self.create_publisher(Twist, "turtle2/cmd_vel", 1)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        from_frame_rel = self.target_frame
        to_frame_rel = "turtle2"
        if self.turtle_spawning_service_ready:
            if self.turtle_spawned:
                try:
                    t = self.tf_buffer.lookup_transform(to_frame_rel, from_frame_rel, Time())
                except TransformException as ex:
                    self.get_logger().info(
                        f"Could not transform {to_frame_rel} to {from_frame_rel}: {ex}")
                    return
                # turn toward the target, drive in proportion to the distance
                msg = Twist()
                scale_rotation_rate = 1.0
                msg.angular.z = scale_rotation_rate * math.atan2(
                    t.transform.translation.y, t.transform.translation.x)
                scale_forward_speed = 0.5
                msg.linear.x = scale_forward_speed * math.sqrt(
                    t.transform.translation.x ** 2 + t.transform.translation.y ** 2)
                self.publisher.publish(msg)
            else:
                if self.result.done():
                    self.get_logger().info(f"Successfully spawned {self.result.result().name}")
                    self.turtle_spawned = True
                else:
                    self.get_logger().info("Spawn is not finished")
        else:
            if self.spawner.service_is_ready():
                request = Spawn.Request()
                request.name = "turtle2"
                request.x = 4.0
                request.y = 2.0
                request.theta = 0.0
                self.result = self.spawner.call_async(request)
                self.turtle_spawning_service_ready = True
            else:
                self.get_logger().info("Service is not ready")


def main(args=None):
    rclpy.init(args=args)
    spin_until_stopped(FrameListener())
