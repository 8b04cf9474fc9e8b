"""QoS events: incompatible QoS is reported (when the node spins, as in rclpy); in-process
endpoints never miss deadlines or liveliness, so those callbacks are accepted but never run."""
from enum import IntEnum

from labkit.rclpy._entity import ReadyEntity


class QoSPublisherEventType(IntEnum):
    RCL_PUBLISHER_OFFERED_DEADLINE_MISSED = 0
    RCL_PUBLISHER_LIVELINESS_LOST = 1
    RCL_PUBLISHER_OFFERED_INCOMPATIBLE_QOS = 2


class QoSSubscriptionEventType(IntEnum):
    RCL_SUBSCRIPTION_REQUESTED_DEADLINE_MISSED = 0
    RCL_SUBSCRIPTION_LIVELINESS_CHANGED = 1
    RCL_SUBSCRIPTION_REQUESTED_INCOMPATIBLE_QOS = 2
    RCL_SUBSCRIPTION_MESSAGE_LOST = 3


class rmw_qos_policy_kind_t(IntEnum):
    """The policy kind an incompatible-QoS event carries: rclpy hands over the rmw enum
    (`.name` is 'RMW_QOS_POLICY_RELIABILITY'); `QoSPolicyKind(kind)` converts it."""

    RMW_QOS_POLICY_INVALID = 1 << 0
    RMW_QOS_POLICY_DURABILITY = 1 << 1
    RMW_QOS_POLICY_DEADLINE = 1 << 2
    RMW_QOS_POLICY_LIVELINESS = 1 << 3
    RMW_QOS_POLICY_RELIABILITY = 1 << 4
    RMW_QOS_POLICY_HISTORY = 1 << 5
    RMW_QOS_POLICY_LIFESPAN = 1 << 6
    RMW_QOS_POLICY_DEPTH = 1 << 7
    RMW_QOS_POLICY_LIVELINESS_LEASE_DURATION = 1 << 8
    RMW_QOS_POLICY_AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9

    def __str__(self):            # a pybind11 enum prints as Type.NAME
        return f'{type(self).__name__}.{self.name}'


class rmw_requested_qos_incompatible_event_status_t:
    """rmw_{offered,requested}_qos_incompatible_event_status_t (one class in rclpy)."""

    def __init__(self, total_count, total_count_change, last_policy_kind):
        self.total_count = total_count
        self.total_count_change = total_count_change
        self.last_policy_kind = rmw_qos_policy_kind_t(int(last_policy_kind))


for _cls in (rmw_qos_policy_kind_t, rmw_requested_qos_incompatible_event_status_t):
    _cls.__module__ = 'rclpy._rclpy_pybind11'

QoSRequestedIncompatibleQoSInfo = rmw_requested_qos_incompatible_event_status_t
QoSOfferedIncompatibleQoSInfo = QoSRequestedIncompatibleQoSInfo


class SubscriptionEventCallbacks:
    def __init__(self, *, deadline=None, incompatible_qos=None, liveliness=None,
                 message_lost=None, use_default_callbacks=True):
        self.deadline = deadline
        self.incompatible_qos = incompatible_qos
        self.liveliness = liveliness
        self.message_lost = message_lost
        self.use_default_callbacks = use_default_callbacks


class PublisherEventCallbacks:
    def __init__(self, *, deadline=None, liveliness=None, incompatible_qos=None,
                 use_default_callbacks=True):
        self.deadline = deadline
        self.liveliness = liveliness
        self.incompatible_qos = incompatible_qos
        self.use_default_callbacks = use_default_callbacks


class QoSEventHandler(ReadyEntity):
    """Queues incompatible-QoS events of one publisher/subscription for its node's executor."""

    _kind = 'guard'

    def __init__(self, node, entity, is_publisher):
        self._node = node
        self._entity = entity
        self._is_publisher = is_publisher
        self._events = []
        self._total = 0
        self.callback_group = node.default_callback_group
        self.callback = self._handle
        self._executor_event = False

    def occurred(self, other, policy_kind):
        self._total += 1
        self._events.append(QoSRequestedIncompatibleQoSInfo(self._total, 1, policy_kind or 1))
        self._signal()

    def _has_work(self):
        return bool(self._events)

    def _take(self):
        from labkit.rclpy.subscription import _NOTHING
        if not self._events:
            return _NOTHING
        return self._events.pop(0)

    def _callback_and_args(self, info):
        return self._handle, (info,)

    def _handle(self, info):
        callbacks = getattr(self._entity, 'event_callbacks', None)
        user = getattr(callbacks, 'incompatible_qos', None)
        if user is not None:
            user(info)
            return
        if callbacks is not None and not getattr(callbacks, 'use_default_callbacks', True):
            return
        from labkit.rclpy.qos import qos_policy_name_from_kind
        logger = self._node.get_logger()
        policy = qos_policy_name_from_kind(info.last_policy_kind)
        topic = self._entity.topic
        if self._is_publisher:
            logger.warn(f"New subscription discovered on topic '{topic}', requesting "
                        'incompatible QoS. No messages will be sent to it. '
                        f'Last incompatible policy: {policy}')
        else:
            logger.warn(f"New publisher discovered on topic '{topic}', offering incompatible "
                        'QoS. No messages will be received from it. '
                        f'Last incompatible policy: {policy}')


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
