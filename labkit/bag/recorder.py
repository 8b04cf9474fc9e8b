"""rosbag2_transport's Recorder on the rclpy API: one generic (raw) subscription per topic.

Runs inside a `ros2 bag record` job. Stopping the job (Ctrl-C) ends the spin loop;
the bag is then closed (last batch committed, metadata.yaml written).
"""
import re

from labkit.commands import CliNode, is_hidden_name

# Humble's recorder asks for KEEP_LAST 10 (Rosbag2QoS: rmw_qos_profile_default's depth): its DDS reader is fed by the middleware's own
# threads and its callback runs on a CPU of its own, so it keeps up at 1 kHz. labkit's
# processes share one interpreter: a recorder thread that waits 20 ms for its turn would
# lose messages a real recorder never loses. A subscription's history is not part of
# discovery (`ros2 topic info -v` shows UNKNOWN, as on Humble), so the recorder keeps a
# deeper queue without anyone seeing a difference; the cache behind it is bounded by
# --max-cache-size, as in rosbag2.
INTAKE_DEPTH = 10000
_INFINITE = (2147483647, 4294967295)


def _duration_yaml(duration):
    ns = getattr(duration, 'nanoseconds', 0) or 0
    if ns <= 0 or ns >= 2 ** 63 - 1:
        sec, nsec = _INFINITE
    else:
        sec, nsec = divmod(ns, 1_000_000_000)
    return f'    sec: {sec}\n    nsec: {nsec}'


def offered_qos_profiles(infos):
    """The publishers' QoS as Humble's recorder stores it (a YAML list, rmw enum values)."""
    out = []
    for info in infos:
        q = info.qos_profile
        out.append(
            f'- history: {int(q.history)}\n  depth: {int(q.depth)}\n'
            f'  reliability: {int(q.reliability)}\n  durability: {int(q.durability)}\n'
            f'  deadline:\n{_duration_yaml(q.deadline)}\n'
            f'  lifespan:\n{_duration_yaml(q.lifespan)}\n'
            f'  liveliness: {int(q.liveliness)}\n'
            f'  liveliness_lease_duration:\n{_duration_yaml(q.liveliness_lease_duration)}\n'
            f'  avoid_ros_namespace_conventions: '
            f'{"true" if q.avoid_ros_namespace_conventions else "false"}')
    return '\n'.join(out)


def subscription_qos(infos):
    """adapt_request_to_offers: reliable/transient only when every publisher offers it."""
    from labkit.rclpy.qos import (
        DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy)
    profile = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=INTAKE_DEPTH)
    if infos and any(i.qos_profile.reliability != ReliabilityPolicy.RELIABLE for i in infos):
        profile.reliability = ReliabilityPolicy.BEST_EFFORT
    if infos and all(i.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL
                     for i in infos):
        profile.durability = DurabilityPolicy.TRANSIENT_LOCAL
    return profile


class Recorder:
    def __init__(self, args):
        self.args = args
        self.bag = None
        self.subscriptions = {}
        self.requested = []
        self.discovering = not args.no_discovery
        self.paused = args.start_paused

    def _wanted(self, name, types):
        a = self.args
        if len(types) != 1:
            return False
        if not a.include_hidden_topics and is_hidden_name(name):
            return False
        if a.topics and not a.all:
            if name in self.requested:
                return True
            if not a.regex:
                return False
        if a.regex and not a.all and not re.search(a.regex, name):
            return False
        if a.exclude and re.search(a.exclude, name):
            return False
        return True

    def _subscribe_new_topics(self, node):
        for name, types in node.get_topic_names_and_types():
            if name in self.subscriptions or not self._wanted(name, types):
                continue
            infos = node.get_publishers_info_by_topic(name)
            if not infos and not self.args.include_unpublished_topics:
                continue
            self._subscribe(node, name, types[0], infos)

    def _subscribe(self, node, name, type_name, infos):
        from labkit.bag.metadata import TopicMetadata
        from labkit.commands import get_message
        try:
            cls = get_message(type_name)
        except ValueError:
            node.get_logger().warn(f"Topic '{name}' has unknown type '{type_name}'")
            self.subscriptions[name] = None
            return
        self.bag.create_topic(TopicMetadata(name, type_name, 'cdr', offered_qos_profiles(infos)))
        clock = node.get_clock()
        bag = self.bag

        def callback(data):
            if not self.paused:
                bag.write(name, data, clock.now().nanoseconds)

        self.subscriptions[name] = node.create_subscription(
            cls, name, callback, subscription_qos(infos), raw=True)
        node.get_logger().info(f"Subscribed to topic '{name}'")

    def _all_requested_subscribed(self):
        a = self.args
        return bool(a.topics) and not a.all and not a.regex and \
            all(t in self.subscriptions for t in self.requested)

    def record(self):
        from labkit.bag.storage import BagWriter
        from labkit.commands import expand_topic
        a = self.args
        with CliNode('rosbag2_recorder', default_context=True) as node:
            log = node.get_logger()
            log.info('Press SPACE for pausing/resuming')
            self.requested = [expand_topic(node, t) for t in (a.topics or [])]
            self.bag = BagWriter(a.output, a.storage, a.max_bag_size, a.max_bag_duration,
                                 a.max_cache_size)
            try:
                log.info('Listening for topics...')
                log.info('Event publisher thread: Starting')
                self._subscribe_new_topics(node)
                if a.start_paused:
                    log.info('Waiting for recording: Press SPACE to start.')
                else:
                    log.info('Recording...')
                self._spin(node, log)
            finally:
                self._stop(node, log)

    def _spin(self, node, log):
        period = max(self.args.polling_interval, 1) / 1000.0
        try:
            while node.ok():
                if self.discovering:
                    if self._all_requested_subscribed():
                        log.info('All requested topics are subscribed. Stopping discovery...')
                        self.discovering = False
                        continue
                    node.spin_once(timeout_sec=period)
                    if node.ok():
                        self._subscribe_new_topics(node)
                else:
                    node.spin_once(timeout_sec=1.0)
        except KeyboardInterrupt:
            pass
        except Exception:
            if node.ok():
                raise

    def _stop(self, node, log):
        for sub in self.subscriptions.values():
            if sub is not None:
                try:
                    node.destroy_subscription(sub)
                except Exception:
                    pass
        self.bag.close()   # (logs rosbag2_cpp's "Writing remaining messages ..." line)
        log.info('Event publisher thread: Exiting')
        log.info('Recording stopped')
