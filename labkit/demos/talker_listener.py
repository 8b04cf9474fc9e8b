"""demo_nodes_cpp (and demo_nodes_py) talker / listener: `std_msgs/String` on `chatter`, 1 Hz.

The two packages print slightly differently: the C++ talker counts from 1 and
quotes with '...', the Python one counts from 0 and quotes with "...".
"""
import labkit.rclpy as rclpy
from labkit.interfaces import module
from labkit.rclpy.executors import ExternalShutdownException
from labkit.rclpy.node import Node

String = module('std_msgs.msg').String


class Talker(Node):

    def __init__(self, python_style=False):
        super().__init__('talker')
        self.python_style = python_style
        self.count = 0 if python_style else 1
        self.pub = self.create_publisher(String, 'chatter', 10)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = f'Hello World: {self.count}'
        self.count += 1
        quoted = f'"{msg.data}"' if self.python_style else f"'{msg.data}'"
        self.get_logger().info(f'Publishing: {quoted}')
        self.pub.publish(msg)


class Listener(Node):

    def __init__(self):
        super().__init__('listener')
        self.sub = self.create_subscription(String, 'chatter', self.on_chatter, 10)

    def on_chatter(self, msg):
        self.get_logger().info(f'I heard: [{msg.data}]')


def _is_python_package(args):
    # `ros2 run` hands the executable's path first: .../lib/demo_nodes_py/talker
    return bool(args) and '/demo_nodes_py/' in str(args[0])


def _run(make_node, args):
    rclpy.init(args=args)
    node = make_node()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


def talker_main(args=None):
    _run(lambda: Talker(python_style=_is_python_package(args)), args)


def listener_main(args=None):
    _run(Listener, args)
