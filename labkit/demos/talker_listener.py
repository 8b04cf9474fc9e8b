"""demo_nodes_cpp talker / listener: `std_msgs/String` on `chatter`, once a second."""
import labkit.rclpy as rclpy
from labkit.interfaces import module
from labkit.rclpy.executors import ExternalShutdownException
from labkit.rclpy.node import Node

String = module('std_msgs.msg').String


class Talker(Node):

    def __init__(self):
        super().__init__('talker')
        self.count = 1
        self.pub = self.create_publisher(String, 'chatter', 10)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = f'Hello World: {self.count}'
        self.count += 1
        self.get_logger().info(f"Publishing: '{msg.data}'")
        self.pub.publish(msg)


class Listener(Node):

    def __init__(self):
        super().__init__('listener')
        self.sub = self.create_subscription(String, 'chatter', self.on_chatter, 10)

    def on_chatter(self, msg):
        self.get_logger().info(f'I heard: [{msg.data}]')


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


def talker_main(args=None):
    _run(Talker, args)


def listener_main(args=None):
    _run(Listener, args)
