"""Conformance: what every node brings to the graph (/rosout, /parameter_events,
parameter services), graph queries by node, /rosout records and parameter events.

Plain rclpy: runs unchanged on ROS 2 Humble.
Humble/Jazzy: Jazzy nodes also offer `~/get_type_description`; the expected file keeps
Humble's (no such service).
"""
import os

import rclpy
from rcl_interfaces.msg import Log, ParameterEvent
from rclpy.executors import SingleThreadedExecutor
from rclpy.parameter import Parameter
from rclpy.qos import QoSDurabilityPolicy, QoSProfile
from std_msgs.msg import String


def spin_until(executor, done, steps=100):
    for _ in range(steps):
        if done():
            return True
        executor.spin_once(timeout_sec=0.05)
    return done()


def main():
    rclpy.init(args=[])
    talker = rclpy.create_node('talker', namespace='/demo')
    observer = rclpy.create_node('observer')
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(observer)
    talker.create_publisher(String, 'chatter', 10)
    observer.create_subscription(String, '/demo/chatter', lambda m: None, 10)
    spin_until(executor, lambda: ('talker', '/demo') in
               observer.get_node_names_and_namespaces())

    nodes = sorted(observer.get_node_names_and_namespaces())
    print('nodes:', [n for n in nodes if n[0] in ('talker', 'observer')])
    print('node names:', sorted(n for n in observer.get_node_names()
                                if n in ('talker', 'observer')))
    print('talker publishers:',
          sorted(observer.get_publisher_names_and_types_by_node('talker', '/demo')))
    print('talker subscriptions:',
          sorted(observer.get_subscriber_names_and_types_by_node('talker', '/demo')))
    print('observer subscriptions:',
          sorted(observer.get_subscriber_names_and_types_by_node('observer', '/')))
    for name, types in sorted(observer.get_service_names_and_types_by_node('talker', '/demo')):
        print('talker service:', name, types)
    for info in observer.get_subscriptions_info_by_topic('/demo/chatter'):
        print('subscription on /demo/chatter:', info.node_name, info.node_namespace,
              info.topic_type, info.endpoint_type.name, info.qos_profile.reliability.name,
              info.qos_profile.history.name, info.qos_profile.depth)
    try:
        observer.get_publisher_names_and_types_by_node('nobody', '/')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print('unknown node:', type(e).__name__, e)

    # /rosout: every node logger publishes rcl_interfaces/Log records
    records = []
    rosout_qos = QoSProfile(depth=1000, durability=QoSDurabilityPolicy.TRANSIENT_LOCAL)
    observer.create_subscription(Log, '/rosout', records.append, rosout_qos)
    spin_until(executor, lambda: talker.count_subscribers('/rosout') >= 1)
    spin_until(executor, lambda: False, steps=4)
    records.clear()
    talker.get_logger().warning('low battery')
    spin_until(executor, lambda: any(r.msg == 'low battery' for r in records))
    for r in records:
        if r.msg == 'low battery':
            print('rosout:', r.name, r.level, repr(r.msg), os.path.basename(r.file),
                  r.function, r.line > 0, r.stamp.sec > 0)

    # /parameter_events: declare and change a parameter (undeclaring publishes nothing)
    events = []
    observer.create_subscription(
        ParameterEvent, '/parameter_events',
        lambda e: events.append(e) if e.node == '/demo/talker' else None, 1000)
    spin_until(executor, lambda: talker.count_subscribers('/parameter_events') >= 1)
    spin_until(executor, lambda: False, steps=4)
    talker.declare_parameter('speed', 1.0)
    talker.set_parameters([Parameter('speed', value=2.5)])
    talker.undeclare_parameter('speed')
    spin_until(executor, lambda: len(events) >= 2)
    spin_until(executor, lambda: False, steps=4)
    for e in events:
        print('parameter event:', e.node,
              'new', [(p.name, p.value.type, p.value.double_value) for p in e.new_parameters],
              'changed', [(p.name, p.value.double_value) for p in e.changed_parameters],
              'deleted', [p.name for p in e.deleted_parameters])

    executor.shutdown()
    observer.destroy_node()
    talker.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
