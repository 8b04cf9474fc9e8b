"""rclpy.subscription.Subscription: a queue (deque, KEEP_LAST drops oldest) and a callback."""
from collections import deque

from labkit.rclpy._entity import Handle, ReadyEntity


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
        else:
            self._queue = deque(maxlen=max(1, qos_profile.depth))
        self._executor_event = False

    def _deliver(self, msg):
        """The graph hands a message (shared by all subscriptions of one publish)."""
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
