"""labkit core speed figures (printed, not asserted).

    .venv/bin/python benchmarks/bench_core.py

- publish -> spin_once -> callback loop of small messages (executor.spin_once and
  rclpy.spin_once); target >= 210,000 msgs/s (real rclpy: ~7,000)
- 640x480 bgr8 sensor_msgs/Image publish -> callback latency (median; target < 100 us)
- virtual time: simulated seconds per wall second for a 100 Hz talker/listener pair
"""
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

import labkit  # noqa: E402
from labkit import process  # noqa: E402
from labkit.graph import world  # noqa: E402
from labkit.interfaces import get_type  # noqa: E402
import labkit.rclpy as rclpy  # noqa: E402
from labkit.rclpy.executors import SingleThreadedExecutor  # noqa: E402
from labkit.rclpy.node import Node  # noqa: E402

String = get_type('std_msgs/msg/String')
Image = get_type('sensor_msgs/msg/Image')


def best_of(runs, fn):
    return max(fn() for _ in range(runs))


def small_messages(n=200_000):
    node = Node('bench_small')
    got = [0]

    def cb(msg):
        got[0] += 1
    node.create_subscription(String, 'small', cb, 10)
    pub = node.create_publisher(String, 'small', 10)
    msg = String(data='hello')
    ex = SingleThreadedExecutor()
    ex.add_node(node)

    def via_executor():
        t = time.perf_counter()
        for _ in range(n):
            pub.publish(msg)
            ex.spin_once(timeout_sec=0)
        return n / (time.perf_counter() - t)
    a = best_of(3, via_executor)
    ex.remove_node(node)

    def via_rclpy():
        t = time.perf_counter()
        for _ in range(n):
            pub.publish(msg)
            rclpy.spin_once(node, timeout_sec=0)
        return n / (time.perf_counter() - t)
    b = best_of(3, via_rclpy)
    print(f'small messages, executor.spin_once: {a:,.0f} msgs/s')
    print(f'small messages, rclpy.spin_once:    {b:,.0f} msgs/s')
    node.destroy_node()


def image_latency(n=500):
    import numpy as np
    node = Node('bench_image')
    lat = []
    t0 = [0.0]
    node.create_subscription(Image, 'image', lambda m: lat.append(time.perf_counter() - t0[0]),
                             10)
    pub = node.create_publisher(Image, 'image', 10)
    img = Image(height=480, width=640, encoding='bgr8', step=640 * 3,
                data=np.zeros(640 * 480 * 3, np.uint8).tobytes())
    for _ in range(n):
        t0[0] = time.perf_counter()
        pub.publish(img)
        rclpy.spin_once(node, timeout_sec=0)
    print(f'640x480 bgr8 Image publish->callback: median {statistics.median(lat) * 1e6:.1f} us')
    node.destroy_node()


def virtual_speed(seconds=10.0):
    labkit.reset()
    world.set_mode('virtual')

    def talker(args=None):
        rclpy.init(args=args)
        node = Node('talker')
        pub = node.create_publisher(String, 'chatter', 10)
        node.create_timer(0.01, lambda: pub.publish(String(data='x')))
        rclpy.spin(node)

    def listener(args=None):
        rclpy.init(args=args)
        node = Node('listener')
        node.create_subscription(String, 'chatter', lambda m: None, 10)
        rclpy.spin(node)
    process.start(main=talker, name='talker')
    process.start(main=listener, name='listener')
    t = time.perf_counter()
    labkit.sleep(seconds)
    wall = time.perf_counter() - t
    print(f'virtual time, 100 Hz talker+listener: {seconds / wall:,.1f} simulated s per wall s')
    labkit.reset()


if __name__ == '__main__':
    rclpy.init()
    small_messages()
    image_latency()
    rclpy.shutdown()
    virtual_speed()
