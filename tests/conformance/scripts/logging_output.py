"""Conformance: node loggers (severities, levels, child loggers, once / skip_first,
--ros-args --log-level) as printed on the console.

ARGS: --ros-args --log-level chatty:=debug
ENV: RCUTILS_CONSOLE_OUTPUT_FORMAT=[{severity}] [{name}]: {message}
ENV: RCUTILS_COLORIZED_OUTPUT=0
STREAMS: merged

Plain rclpy: runs unchanged on ROS 2 Humble. The output format is fixed through
RCUTILS_CONSOLE_OUTPUT_FORMAT (no time stamps), and stderr is merged into stdout.
"""
import sys

import rclpy
from rclpy.logging import LoggingSeverity, get_logger


def main():
    rclpy.init(args=sys.argv)
    node = rclpy.create_node('talker')
    log = node.get_logger()
    print('logger name:', log.name)
    print('effective level:', LoggingSeverity(log.get_effective_level()).name)
    log.debug('hidden debug')
    log.info('Publishing: "Hello World: 0"')
    log.warning('a warning')
    log.warn('a warn')
    log.error('an error')
    log.fatal('a fatal')
    for i in range(3):
        log.info(f'once {i}', once=True)
        log.info(f'skip_first {i}', skip_first=True)
    child = log.get_child('motor')
    print('child name:', child.name)
    child.info('from the child')
    log.set_level(LoggingSeverity.DEBUG)
    log.debug('shown debug')
    print('level after set_level:', LoggingSeverity(log.get_effective_level()).name)
    log.set_level(LoggingSeverity.ERROR)
    log.warning('hidden warning')
    log.error('shown error')
    chatty = rclpy.create_node('chatty')
    chatty.get_logger().debug('chatty debug from --log-level chatty:=debug')
    get_logger('plain').info('a logger without a node')
    print('returns:', node.get_logger().error('x') if False else get_logger('plain').info('y'))
    chatty.destroy_node()
    node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
