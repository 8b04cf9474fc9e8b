"""Conformance: node, namespace, topic and service names (validation with the exception
class names and texts, expansion of relative and private `~/` names, remapping from
--ros-args -r).

ARGS: --ros-args -r chatter:=conversation -r mover:cmd:=/wheels/cmd -r __ns:=/global_ns

Plain rclpy: runs unchanged on ROS 2 Humble.
"""
import sys

import rclpy
from rclpy.exceptions import (InvalidNamespaceException, InvalidNodeNameException,
                              InvalidServiceNameException, InvalidTopicNameException)
from rclpy.expand_topic_name import expand_topic_name
from rclpy.validate_full_topic_name import validate_full_topic_name
from rclpy.validate_namespace import validate_namespace
from rclpy.validate_node_name import validate_node_name
from rclpy.validate_topic_name import validate_topic_name
from std_msgs.msg import String
from std_srvs.srv import Trigger


def attempt(label, fn):
    try:
        value = fn()
        print(f'{label}: ok {value!r}')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print(f'{label}: {type(e).__name__}:')
        for line in str(e).splitlines():
            print('   |' + line)


def main():
    # validation functions, without a context
    for name in ('talker', 'my_node2', 'my-node', '2fast', '', 'a b', 'ns/node'):
        attempt(f'validate_node_name({name!r})', lambda: validate_node_name(name))
    for ns in ('/', '/robot', '/robot/arm', 'robot', '/robot/', '/2robot', '/ro-bot', '//x'):
        attempt(f'validate_namespace({ns!r})', lambda: validate_namespace(ns))
    for topic in ('chatter', '/chatter', '~/status', '{node}/x', 'bad topic', 'a//b', '/a/',
                  '1topic', '/a/1b', 'ok_1/_x'):
        attempt(f'validate_topic_name({topic!r})', lambda: validate_topic_name(topic))
    for topic in ('/chatter', 'chatter', '/a/b', '~/x'):
        attempt(f'validate_full_topic_name({topic!r})',
                lambda: validate_full_topic_name(topic))
    for topic, node, ns in (('chatter', 'talker', '/'), ('chatter', 'talker', '/robot'),
                            ('~/status', 'talker', '/robot'), ('~', 'talker', '/'),
                            ('/abs', 'talker', '/robot'), ('{node}/out', 'talker', '/ns'),
                            ('{ns}/out', 'talker', '/ns')):
        attempt(f'expand_topic_name({topic!r}, {node!r}, {ns!r})',
                lambda: expand_topic_name(topic, node, ns))

    # nodes with invalid names (args=[]: without it rclpy.init reads sys.argv)
    rclpy.init(args=[])
    attempt('Node("my-node")', lambda: rclpy.create_node('my-node'))
    attempt('Node("talker", namespace="/ro-bot")',
            lambda: rclpy.create_node('talker', namespace='/ro-bot'))
    attempt('Node("talker", namespace="/robot/")',
            lambda: rclpy.create_node('talker', namespace='/robot/'))

    node = rclpy.create_node('mover', namespace='robot')
    print('name:', node.get_name(), 'namespace:', node.get_namespace(),
          'fqn:', node.get_fully_qualified_name())
    for topic in ('cmd_vel', '/cmd_vel', '~/status', '~', 'cmd'):
        print(f'publisher {topic!r} ->', node.create_publisher(String, topic, 10).topic_name)
    print('resolve_topic_name chatter:', node.resolve_topic_name('chatter'))
    print('resolve_service_name ~/reset:', node.resolve_service_name('~/reset'))
    attempt('create_publisher("bad topic")',
            lambda: node.create_publisher(String, 'bad topic', 10))
    attempt('create_subscription("a//b")',
            lambda: node.create_subscription(String, 'a//b', print, 10))
    attempt('create_service("9lives")',
            lambda: node.create_service(Trigger, '9lives', lambda q, r: r))
    attempt('create_client("bad name")',
            lambda: node.create_client(Trigger, 'bad name'))
    print('exception bases:', [c.__name__ for c in InvalidTopicNameException.__mro__[1:3]],
          issubclass(InvalidServiceNameException, Exception),
          issubclass(InvalidNamespaceException, Exception),
          issubclass(InvalidNodeNameException, Exception))
    node.destroy_node()
    rclpy.shutdown()

    # remapping from the command line: topic rules, node-specific rules, __ns
    rclpy.init(args=sys.argv)
    talker = rclpy.create_node('talker')
    mover = rclpy.create_node('mover', namespace='/robot')
    print('talker ns:', talker.get_namespace(), 'fqn:', talker.get_fully_qualified_name())
    print('mover ns:', mover.get_namespace(), 'fqn:', mover.get_fully_qualified_name())
    print('talker chatter ->', talker.create_publisher(String, 'chatter', 10).topic_name)
    print('talker /chatter ->', talker.create_publisher(String, '/chatter', 10).topic_name)
    print('mover cmd ->', mover.create_publisher(String, 'cmd', 10).topic_name)
    print('talker cmd ->', talker.create_publisher(String, 'cmd', 10).topic_name)
    print('talker only_expand chatter:', talker.resolve_topic_name('chatter', only_expand=True))
    talker.destroy_node()
    mover.destroy_node()

    # remapping given to one node only (cli_args), and node name remap
    node = rclpy.create_node('talker', cli_args=['--ros-args', '-r', '__node:=speaker',
                                                 '-r', 'chatter:=~/said'],
                             use_global_arguments=False)
    print('renamed:', node.get_name(), node.get_namespace(),
          node.create_publisher(String, 'chatter', 10).topic_name)
    node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
