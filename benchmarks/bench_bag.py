"""Bag throughput: labkit's writer, `ros2 bag record` and `ros2 bag play` against `rosbags`.

    .venv/bin/python benchmarks/bench_bag.py [N]

Each figure is messages per second over N geometry_msgs/Twist messages (52 bytes of
CDR), sqlite3 and mcap storage, virtual time. Goal: a ratio of at least 0.8 against doing the
same with rosbags directly: writer vs "serialize + rosbags Writer.write", record vs a node that writes with
rosbags on the same in-process transport (and vs the bare Writer), play vs
"rosbags Reader + deserialize + publish to the same subscriber" (a bag player must
publish; the bare read + deserialize figure is printed too).
"""
import os
import sys
import tempfile
import time

os.environ.setdefault('LABKIT_TIME', 'virtual')
REPEATS = 3


def _messages(n):
    import labkit.interfaces as ifc
    Twist = ifc.get_type('geometry_msgs/msg/Twist')
    out = []
    for k in range(n):
        t = Twist()
        t.linear.x = float(k)
        t.angular.z = 1.8
        out.append(t)
    return out


def _rosbags_writer(path, storage):
    from rosbags.rosbag2 import StoragePlugin, Writer
    plugin = StoragePlugin.MCAP if storage == 'mcap' else StoragePlugin.SQLITE3
    return Writer(path, version=8, storage_plugin=plugin)


def rosbags_write(path, msgs, serialize, storage):
    """The baseline: rosbags writes each message (serialized here, as a recorder must)."""
    from rosbags.typesys import Stores, get_typestore
    store = get_typestore(Stores.ROS2_HUMBLE)
    t0 = time.perf_counter()
    with _rosbags_writer(path, storage) as w:
        conn = w.add_connection('/cmd', 'geometry_msgs/msg/Twist', typestore=store)
        for k, m in enumerate(msgs):
            w.write(conn, k * 1000, serialize(m))
    return time.perf_counter() - t0


def labkit_write(path, msgs, serialize, storage):
    from labkit.bag import rosbag2_py
    t0 = time.perf_counter()
    w = rosbag2_py.SequentialWriter()
    w.open(rosbag2_py.StorageOptions(uri=path, storage_id=storage),
           rosbag2_py.ConverterOptions('', ''))
    w.create_topic(rosbag2_py.TopicMetadata('/cmd', 'geometry_msgs/msg/Twist', 'cdr'))
    for k, m in enumerate(msgs):
        w.write('/cmd', serialize(m), k * 1000)
    w.close()
    return time.perf_counter() - t0


def _publish_in_batches(msgs):
    import labkit
    import labkit.rclpy as rclpy
    from labkit.rclpy.qos import QoSProfile
    rclpy.init()
    node = rclpy.create_node('bench_pub')
    pub = node.create_publisher(type(msgs[0]), '/cmd', QoSProfile(depth=10))
    labkit.sleep(0.2)  # discovery
    t0 = time.perf_counter()
    for k in range(0, len(msgs), 10):  # a depth-10 subscriber keeps up
        for m in msgs[k:k + 10]:
            pub.publish(m)
        labkit.sleep(0.001)
    return node, t0


def rosbags_recorder(path, msgs, storage):
    """The baseline for record on the same transport: a node that writes with rosbags."""
    import labkit
    import labkit.rclpy as rclpy
    from labkit import process
    from rosbags.typesys import Stores, get_typestore
    store = get_typestore(Stores.ROS2_HUMBLE)

    def main(args=None):
        rclpy.init(args=args)
        node = rclpy.create_node('rosbags_recorder')
        with _rosbags_writer(path, storage) as w:
            conn = w.add_connection('/cmd', 'geometry_msgs/msg/Twist', typestore=store)
            clock = node.get_clock()
            node.create_subscription(
                type(msgs[0]), '/cmd',
                lambda data: w.write(conn, clock.now().nanoseconds, data), 10, raw=True)
            try:
                rclpy.spin(node)
            except Exception:
                pass
    proc = process.start(main=main, name='rosbags_recorder')
    node, t0 = _publish_in_batches(msgs)
    proc.stop()
    took = time.perf_counter() - t0
    node.destroy_node()
    rclpy.shutdown()
    labkit.reset()
    return took


def labkit_record(path, msgs, storage):
    """`ros2 bag record` a publisher: publish, deliver, serialize, write, then stop."""
    import labkit
    import labkit.rclpy as rclpy
    rec = labkit.ros2(f'bag record -s {storage} -o {path} /cmd')
    node, t0 = _publish_in_batches(msgs)
    rec.stop()
    took = time.perf_counter() - t0
    from labkit.bag.storage import read_bag_metadata
    recorded = read_bag_metadata(path).message_count
    assert recorded == len(msgs), f'recorded {recorded} of {len(msgs)}'
    node.destroy_node()
    rclpy.shutdown()
    labkit.reset()
    return took


def rosbags_read(path):
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore
    store = get_typestore(Stores.ROS2_HUMBLE)
    t0 = time.perf_counter()
    n = 0
    with Reader(path) as r:
        for c, _, d in r.messages():
            store.deserialize_cdr(d, c.msgtype)
            n += 1
    return time.perf_counter() - t0, n


def rosbags_play(path, expected):
    """The baseline for play: rosbags reads, the same subscriber gets each message published."""
    import labkit
    import labkit.interfaces as ifc
    import labkit.rclpy as rclpy
    from labkit.rclpy.qos import QoSProfile
    from rosbags.rosbag2 import Reader
    rclpy.init()
    node = rclpy.create_node('bench_sub')
    Twist = ifc.get_type('geometry_msgs/msg/Twist')
    got = []
    # KEEP_LAST as deep as the bag: every message waits (KEEP_ALL stops at DDS's 5000)
    node.create_subscription(Twist, '/cmd', got.append, QoSProfile(depth=expected))
    pub = node.create_publisher(Twist, '/cmd', 10)
    t0 = time.perf_counter()
    with Reader(path) as r:
        for _, _, d in r.messages():
            pub.publish(ifc.deserialize(d, Twist))
    took = time.perf_counter() - t0
    while len(got) < expected:
        rclpy.spin_once(node, timeout_sec=0.0)
    node.destroy_node()
    rclpy.shutdown()
    labkit.reset()
    return took


def labkit_play(path, expected):
    """`ros2 bag play` as fast as it can go (huge --rate) into one subscriber."""
    import labkit
    import labkit.rclpy as rclpy
    rclpy.init()
    node = rclpy.create_node('bench_sub')
    got = []
    import labkit.interfaces as ifc
    from labkit.rclpy.qos import QoSProfile
    node.create_subscription(ifc.get_type('geometry_msgs/msg/Twist'), '/cmd', got.append,
                             QoSProfile(depth=expected))
    t0 = time.perf_counter()
    play = labkit.ros2(f'bag play {path} --rate 1000000 --disable-keyboard-controls')
    play.wait()
    took = time.perf_counter() - t0  # every message is in the subscriber's queue
    while len(got) < expected:  # (its callbacks are the subscriber's cost, not the bag's)
        rclpy.spin_once(node, timeout_sec=0.0)
    assert len(got) == expected, f'played {len(got)} of {expected}'
    node.destroy_node()
    rclpy.shutdown()
    labkit.reset()
    return took


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 50000
    import labkit.interfaces as ifc
    msgs = _messages(n)
    best = {}

    def keep(name, seconds):  # best of the repeats: the machine may be busy
        best[name] = min(best.get(name, seconds), seconds)

    rate = lambda s: n / s  # noqa: E731
    with tempfile.TemporaryDirectory() as tmp:
        os.chdir(tmp)
        for rep in range(REPEATS):
            for st in ('sqlite3', 'mcap'):
                keep(('base_w', st), rosbags_write(f'a{rep}{st}', msgs, ifc.serialize, st))
                keep(('ours_w', st), labkit_write(f'b{rep}{st}', msgs, ifc.serialize, st))
                keep(('base_rr', st), rosbags_recorder(f'r{rep}{st}', msgs, st))
                keep(('ours_r', st), labkit_record(f'c{rep}{st}', msgs, st))
            base_r, count = rosbags_read(f'b{rep}sqlite3')
            keep('base_r', base_r)
            keep('base_p', rosbags_play(f'b{rep}sqlite3', count))
            keep('ours_p', labkit_play(f'b{rep}sqlite3', count))
    print(f'messages: {n} geometry_msgs/msg/Twist')
    for st in ('sqlite3', 'mcap'):
        base_w, ours_w = best[('base_w', st)], best[('ours_w', st)]
        base_rr, ours_r = best[('base_rr', st)], best[('ours_r', st)]
        print(f'[{st}]')
        print(f'rosbags Writer (serialize + write)   {rate(base_w):10.0f} msg/s')
        print(f'rosbag2_py SequentialWriter          {rate(ours_w):10.0f} msg/s  '
              f'ratio {base_w / ours_w:.2f}')
        print(f'rosbags in a subscriber (pub -> bag) {rate(base_rr):10.0f} msg/s')
        print(f'ros2 bag record (publish -> bag)     {rate(ours_r):10.0f} msg/s  '
              f'ratio {base_rr / ours_r:.2f} (vs bare rosbags Writer {base_w / ours_r:.2f})')
    base_r, base_p, ours_p = best['base_r'], best['base_p'], best['ours_p']
    print('[sqlite3]')
    print(f'rosbags Reader (read + deserialize)  {rate(base_r):10.0f} msg/s')
    print(f'rosbags Reader -> publish            {rate(base_p):10.0f} msg/s')
    print(f'ros2 bag play (bag -> subscriber)    {rate(ours_p):10.0f} msg/s  '
          f'ratio {base_p / ours_p:.2f}')


if __name__ == '__main__':
    main()
