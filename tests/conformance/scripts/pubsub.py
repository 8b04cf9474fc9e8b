"""Conformance: publish/subscribe, QoS depth, transient-local latching, QoS matching.

Plain rclpy: runs unchanged on ROS 2 Humble. Prints only deterministic lines.
"""
import time

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import (QoSDurabilityPolicy, QoSHistoryPolicy, QoSPolicyKind, QoSProfile,
                       QoSReliabilityPolicy)
from rclpy.qos_event import SubscriptionEventCallbacks
from sensor_msgs.msg import Image
from std_msgs.msg import Int32, String


def spin_until(executor, done, steps=100):
    """Spin in short slices until done() or about `steps` * 50 ms have passed."""
    for _ in range(steps):
        if done():
            return True
        executor.spin_once(timeout_sec=0.05)
    return done()


def spin_for(executor, steps):
    for _ in range(steps):
        executor.spin_once(timeout_sec=0.05)


def main():
    rclpy.init()
    talker = rclpy.create_node('talker')
    listener = rclpy.create_node('listener')
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(listener)

    # 1. plain delivery, in order
    pub = talker.create_publisher(String, 'chatter', 10)
    print('publisher topic:', pub.topic_name)
    received = []
    sub = listener.create_subscription(String, 'chatter', lambda m: received.append(m.data), 10)
    print('subscription topic:', sub.topic_name)
    print('matched:', spin_until(executor, lambda: pub.get_subscription_count() == 1))
    for i in range(3):
        pub.publish(String(data=f'Hello World: {i}'))
    spin_until(executor, lambda: len(received) == 3)
    for data in received:
        print('I heard:', data)
    print('count_publishers:', listener.count_publishers('/chatter'))
    print('count_subscribers:', talker.count_subscribers('chatter'))

    # publishing the wrong type is a TypeError
    try:
        pub.publish(Int32(data=1))
    except TypeError as e:
        print('TypeError:', e)

    # 2. KEEP_LAST depth: a queue of 2 keeps the newest two
    reliable2 = QoSProfile(history=QoSHistoryPolicy.KEEP_LAST, depth=2,
                           reliability=QoSReliabilityPolicy.RELIABLE)
    pub_d = talker.create_publisher(Int32, 'numbers', 10)
    got = []
    listener.create_subscription(Int32, 'numbers', lambda m: got.append(m.data), reliable2)
    spin_until(executor, lambda: pub_d.get_subscription_count() == 1)
    for i in range(5):
        pub_d.publish(Int32(data=i))
    time.sleep(0.3)  # let the middleware deliver while nobody takes
    spin_for(executor, 6)
    print('depth 2 kept:', got)

    # 3. transient local: a late subscriber receives the last published message
    latched = QoSProfile(depth=1, durability=QoSDurabilityPolicy.TRANSIENT_LOCAL)
    pub_l = talker.create_publisher(String, 'map_info', latched)
    pub_l.publish(String(data='first'))
    pub_l.publish(String(data='latched'))
    late = []
    listener.create_subscription(String, 'map_info', lambda m: late.append(m.data), latched)
    spin_until(executor, lambda: len(late) >= 1)
    spin_for(executor, 4)
    print('transient local late subscriber got:', late)
    volatile_late = []
    listener.create_subscription(String, 'map_info', lambda m: volatile_late.append(m.data), 10)
    spin_until(executor, lambda: pub_l.get_subscription_count() == 2)
    spin_for(executor, 4)
    print('volatile late subscriber got:', volatile_late)

    # 4. incompatible QoS: best-effort publisher, reliable subscription -> not matched
    events = []
    callbacks = SubscriptionEventCallbacks(
        incompatible_qos=lambda e: events.append(QoSPolicyKind(e.last_policy_kind).name))
    best_effort = QoSProfile(depth=10, reliability=QoSReliabilityPolicy.BEST_EFFORT)
    pub_be = talker.create_publisher(String, 'scan_text', best_effort)
    never = []
    listener.create_subscription(String, 'scan_text', lambda m: never.append(m.data), 10,
                                 event_callbacks=callbacks)
    spin_until(executor, lambda: len(events) >= 1)
    pub_be.publish(String(data='lost'))
    spin_for(executor, 6)
    print('incompatible: matched subscriptions', pub_be.get_subscription_count())
    print('incompatible: graph count_subscribers', talker.count_subscribers('/scan_text'))
    print('incompatible: received', never)
    print('incompatible: event policy', events[:1])

    # 5. reliable publisher, best-effort subscription -> compatible
    pub_r = talker.create_publisher(String, 'status', 10)
    be_got = []
    listener.create_subscription(String, 'status', lambda m: be_got.append(m.data), best_effort)
    spin_until(executor, lambda: pub_r.get_subscription_count() == 1)
    pub_r.publish(String(data='ok'))
    spin_until(executor, lambda: len(be_got) == 1)
    print('reliable->best effort received:', be_got)

    # 6. volatile publisher, transient-local subscription -> incompatible (durability)
    pub_v = talker.create_publisher(String, 'volatile_only', 10)
    tl_got = []
    listener.create_subscription(String, 'volatile_only', lambda m: tl_got.append(m.data), latched)
    spin_for(executor, 6)
    print('volatile->transient local matched:', pub_v.get_subscription_count())

    # the subscriber gets its own copy: changing the message after publish() is safe
    pub_img = talker.create_publisher(Image, 'image_raw', 10)
    frames = []
    listener.create_subscription(Image, 'image_raw', frames.append, 10)
    spin_until(executor, lambda: pub_img.get_subscription_count() == 1)
    image = Image(height=2, width=2, encoding='mono8', step=2, data=[1, 2, 3, 4])
    pub_img.publish(image)
    image.data[0] = 99
    image.header.frame_id = 'changed'
    spin_until(executor, lambda: len(frames) == 1)
    print('received copy:', list(frames[0].data), repr(frames[0].header.frame_id),
          frames[0] is image)

    # graph queries
    names = talker.get_topic_names_and_types()
    for name, types in sorted(names):
        if name in ('/chatter', '/numbers', '/map_info', '/scan_text', '/status'):
            print('topic', name, types)
    for info in listener.get_publishers_info_by_topic('/map_info'):
        print('publisher on /map_info:', info.node_name, info.node_namespace, info.topic_type,
              info.qos_profile.durability.name, info.qos_profile.reliability.name)

    executor.shutdown()
    talker.destroy_node()
    listener.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
