"""rclpy.publisher.Publisher: publish = type check, one copy, hand to matched subscriptions."""
from labkit.rclpy._entity import Handle
from labkit.rclpy import _msgs


class Publisher:
    def __init__(self, publisher_impl, msg_type, topic, qos_profile, event_callbacks=None,
                 callback_group=None):
        self.__publisher = publisher_impl          # the graph endpoint
        self._endpoint = publisher_impl
        self.msg_type = msg_type
        self.topic = topic
        self.qos_profile = qos_profile
        self.event_handlers = []
        self.event_callbacks = event_callbacks
        self.callback_group = callback_group
        self._destroyed = False
        self._handle = Handle(self)
        self._node = None
        self._context = _ALWAYS_OK

    def publish(self, msg):
        """Send a message to every matched subscription (a bytes message is CDR)."""
        if type(msg) is not self.msg_type and not isinstance(msg, self.msg_type):
            if isinstance(msg, (bytes, bytearray)):
                from labkit.interfaces import deserialize
                msg = deserialize(bytes(msg), self.msg_type)
            else:
                raise TypeError('Expected {}, got {}'.format(self.msg_type, type(msg)))
        if self._destroyed:
            from labkit.rclpy.exceptions import InvalidHandle
            raise InvalidHandle('cannot use Destroyable because destruction was requested')
        if not self._context._ok:
            from labkit.rclpy.exceptions import RCLError
            raise RCLError("Failed to publish: publisher's context is invalid")
        ep = self._endpoint
        sinks = ep.matched
        history = ep.history
        if sinks or history is not None:
            m = _msgs.copy_message(msg)
            if history is not None:
                history.append(m)
            for sink in sinks:
                sink(m)

    @property
    def handle(self):
        return self._handle

    @property
    def topic_name(self):
        with self._handle:
            return self._endpoint.name

    def get_subscription_count(self):
        with self._handle:
            ep = self._endpoint
            if ep.bridge is None:
                return len(ep.matched)
            # on DDS, `matched` also holds the DDS writer (one for every remote reader, and
            # always for TRANSIENT_LOCAL): count the subscriptions themselves, as rmw does
            from labkit.graph import registry
            with registry.GRAPH.lock:
                subs = list(registry.GRAPH.endpoints[registry.SUB].get(ep.name, ()))
            domain = ep.node.domain_id
            return sum(1 for sub in subs if sub.node.domain_id == domain
                       and registry._compatible(ep.qos, sub.qos)[0])

    def assert_liveliness(self):
        with self._handle:
            pass

    def wait_for_all_acked(self, timeout=None):
        with self._handle:
            return True

    def destroy(self):
        if self._node is not None:
            self._node.destroy_publisher(self)
        else:
            self._destroy()

    def _destroy(self):
        if not self._destroyed:
            self._destroyed = True
            from labkit.graph.registry import GRAPH
            GRAPH.remove(self._endpoint)


class _AlwaysOk:
    _ok = True


_ALWAYS_OK = _AlwaysOk()


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
