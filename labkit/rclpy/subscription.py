"""rclpy.subscription.Subscription: a queue (deque, KEEP_LAST drops oldest) and a callback."""
from collections import deque

from labkit.rclpy._entity import Handle, ReadyEntity

# KEEP_ALL is "all, within the resource limits" in DDS. Humble's default middleware,
# Fast DDS, sets ResourceLimitsQosPolicy.max_samples to 5000 for every reader and writer
# (a keyless ROS topic is one instance, so max_samples is the bound); Cyclone DDS leaves it
# unlimited on readers but bounds the writer's unacknowledged history. labkit follows Fast
# DDS: a KEEP_ALL queue holds at most 5000 messages and, when full, rejects the newest
# (DDS's REJECTED_BY_SAMPLES_LIMIT) instead of blocking the publisher or growing.
KEEP_ALL_MAX_SAMPLES = 5000


class Subscription(ReadyEntity):
    _kind = 'sub'

    def __init__(self, subscription_impl, msg_type, topic, callback, callback_group,
                 qos_profile, raw, event_callbacks=None):
        self.__subscription = subscription_impl
        self._endpoint = subscription_impl
        self.msg_type = msg_type
        self.topic = topic
        self.callback = callback
        self.callback_group = callback_group
        self.qos_profile = qos_profile
        self.raw = raw
        self.event_handlers = []
        self.event_callbacks = event_callbacks
        self._handle = Handle(self)
        from labkit.rclpy.qos import HistoryPolicy
        if qos_profile.history == HistoryPolicy.KEEP_ALL:
            self._queue = deque()
            self._deliver = self._deliver_keep_all
        else:
            self._queue = deque(maxlen=max(1, qos_profile.depth))
        self._executor_event = False
        self.rejected = 0                 # KEEP_ALL samples refused at the resource limit

    def _deliver(self, msg):
        """The graph hands a message (shared by all subscriptions of one publish)."""
        self._queue.append(msg)
        if not self._queued:
            self._signal()

    def _deliver_keep_all(self, msg):
        if len(self._queue) >= KEEP_ALL_MAX_SAMPLES:
            self.rejected += 1
            return
        self._queue.append(msg)
        if not self._queued:
            self._signal()

    def _has_work(self):
        return bool(self._queue)

    def _take(self):
        q = self._queue
        if not q:
            return _NOTHING
        msg = q.popleft()
        if q:
            self._signal()
        if self.raw:
            from labkit.interfaces import serialize
            return serialize(msg)
        return msg

    def _callback_and_args(self, msg):
        return self.callback, (msg,)

    @property
    def handle(self):
        return self._handle

    @property
    def topic_name(self):
        with self._handle:
            return self._endpoint.name

    def destroy(self):
        if self._node is not None:
            self._node.destroy_subscription(self)

    def _destroy(self):
        if not self._destroyed:
            self._destroyed = True
            self._queue.clear()
            from labkit.graph.registry import GRAPH
            GRAPH.remove(self._endpoint)


class _Nothing:
    def __repr__(self):
        return '<nothing>'


_NOTHING = _Nothing()


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
