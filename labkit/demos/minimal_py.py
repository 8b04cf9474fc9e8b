"""examples_rclpy_minimal_publisher / _subscriber of a Humble desktop install.

The Python twins of examples_rclcpp_minimal_*: same node names and topic, Python's
texts (`Publishing: "Hello World: 0"`, `I heard: "Hello World: 0"`). The real packages
have three executables each (member function, local function, "old school"); they
differ only in how the code is written, not in what a user sees, so all three start
the same node here.
"""
from labkit.demos.minimal import _run as _spin   # init, spin until Ctrl+C, clean up
from labkit.interfaces import module
from labkit.rclpy.node import Node

String = module('std_msgs.msg').String


class Publisher(Node):

    def __init__(self):
        super().__init__('minimal_publisher')
        self.sent = 0
        self.pub = self.create_publisher(String, 'topic', 10)
        self.create_timer(0.5, self.tick)

    def tick(self):
        msg = String(data=f'Hello World: {self.sent}')
        self.pub.publish(msg)
        self.get_logger().info(f'Publishing: "{msg.data}"')
        self.sent += 1


class Subscriber(Node):

    def __init__(self):
        super().__init__('minimal_subscriber')
        self.create_subscription(String, 'topic', self.heard, 10)

    def heard(self, msg):
        self.get_logger().info(f'I heard: "{msg.data}"')


def publisher_main(args=None):
    _spin(Publisher, args)


def subscriber_main(args=None):
    _spin(Subscriber, args)
