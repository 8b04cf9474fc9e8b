"""examples_rclcpp_minimal_publisher / _subscriber (member-function style), on `topic`."""
import labkit.rclpy as rclpy
from labkit.interfaces import module
from labkit.rclpy.executors import ExternalShutdownException
from labkit.rclpy.node import Node

String = module('std_msgs.msg').String


class MinimalPublisher(Node):

    def __init__(self):
        super().__init__('minimal_publisher')
        self.count = 0
        self.publisher = self.create_publisher(String, 'topic', 10)
        self.timer = self.create_timer(0.5, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = f'Hello, world! {self.count}'
        self.count += 1
        self.get_logger().info(f"Publishing: '{msg.data}'")
        self.publisher.publish(msg)


class MinimalSubscriber(Node):

    def __init__(self):
        super().__init__('minimal_subscriber')
        self.subscription = self.create_subscription(String, 'topic', self.on_message, 10)

    def on_message(self, msg):
        self.get_logger().info(f"I heard: '{msg.data}'")


def _run(node_class, args):
    rclpy.init(args=args)
    node = node_class()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


def publisher_main(args=None):
    _run(MinimalPublisher, args)


def subscriber_main(args=None):
    _run(MinimalSubscriber, args)
