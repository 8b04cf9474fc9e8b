"""rosbag2_transport's Player on the rclpy API: republish a bag with its recorded timing."""
from labkit.commands import CliNode

DEFAULT_DEPTH = 10


def publisher_qos(offered):
    """Rosbag2QoS for playback: the recorded publishers' durability when they all agree."""
    from labkit.rclpy.qos import DurabilityPolicy, QoSProfile
    profile = QoSProfile(depth=DEFAULT_DEPTH)
    durabilities = [line.split(':')[1].strip() for line in offered.splitlines()
                    if line.strip().startswith('durability:')]
    if durabilities and all(d == str(int(DurabilityPolicy.TRANSIENT_LOCAL))
                            for d in durabilities):
        profile.durability = DurabilityPolicy.TRANSIENT_LOCAL
    return profile


class Player:
    def __init__(self, args):
        self.args = args

    def play(self, reader=None):
        from labkit.bag.storage import BagReader
        from labkit.interfaces import deserialize
        a = self.args
        reader = reader or BagReader(a.bag_path, a.storage)
        remap = dict(r.split(':=', 1) for r in (a.remap or []) if ':=' in r)
        try:
            with CliNode('rosbag2_player', default_context=True) as node:
                log = node.get_logger()
                publishers = self._publishers(node, reader, remap, log)
                if not a.disable_keyboard_controls:
                    log.info('Adding keyboard callbacks.')
                    for key, op in (('SPACE', 'Pause/Resume'),
                                    ('CURSOR_RIGHT', 'Play Next Message'),
                                    ('CURSOR_UP', 'Increase Rate 10%'),
                                    ('CURSOR_DOWN', 'Decrease Rate 10%')):
                        log.info(f'Press {key} for {op}')
                first = reader.metadata.starting_time
                start = first + int(a.start_offset * 1e9)
                topics = list(publishers)
                if not topics:
                    return 0
                rclpy_node, context = node.node, node.context
                clock = rclpy_node.get_clock()
                while context.ok():
                    if a.delay > 0:
                        self._sleep_until(node, clock.now().nanoseconds + int(a.delay * 1e9))
                    t0 = now = clock.now().nanoseconds
                    rate = a.rate
                    for topic, data, stamp in reader.messages(topics, start):
                        due = t0 + (stamp - start if rate == 1.0
                                    else int((stamp - start) / rate))
                        if due > now:  # (a message already due needs no clock reading)
                            now = clock.now().nanoseconds
                            if due > now:
                                if not self._sleep_until(node, due):
                                    return 0
                                now = due
                        if not context.ok():
                            return 0
                        pub, cls = publishers[topic]
                        pub.publish(deserialize(data, cls))
                    if not a.loop:
                        break
        except KeyboardInterrupt:
            pass
        finally:
            reader.close()
        return 0

    def _publishers(self, node, reader, remap, log):
        from labkit.commands import get_message
        wanted = set(self.args.topics or [])
        publishers = {}
        for topic in reader.topics():
            if wanted and topic.name not in wanted:
                continue
            try:
                cls = get_message(topic.type)
            except ValueError:
                log.warn(f"Ignoring a topic '{topic.name}', reason: package "
                         f"'{topic.type.split('/')[0]}' not found.")
                continue
            name = remap.get(topic.name, topic.name)
            publishers[topic.name] = (
                node.create_publisher(cls, name, publisher_qos(topic.offered_qos_profiles)),
                cls)
        return publishers

    @staticmethod
    def _sleep_until(node, due_ns):
        """Wait (a world wait point) until the clock reaches `due_ns`; False if stopped."""
        clock = node.node.get_clock()
        while node.context.ok():
            left = due_ns - clock.now().nanoseconds
            if left <= 0:
                return True
            node.spin_once(timeout_sec=left / 1e9)
        return False
