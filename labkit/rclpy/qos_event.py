"""QoS event callbacks (accepted; in-process endpoints never miss deadlines or liveliness)."""
from enum import IntEnum


class QoSPublisherEventType(IntEnum):
    RCL_PUBLISHER_OFFERED_DEADLINE_MISSED = 0
    RCL_PUBLISHER_LIVELINESS_LOST = 1
    RCL_PUBLISHER_OFFERED_INCOMPATIBLE_QOS = 2


class QoSSubscriptionEventType(IntEnum):
    RCL_SUBSCRIPTION_REQUESTED_DEADLINE_MISSED = 0
    RCL_SUBSCRIPTION_LIVELINESS_CHANGED = 1
    RCL_SUBSCRIPTION_REQUESTED_INCOMPATIBLE_QOS = 2
    RCL_SUBSCRIPTION_MESSAGE_LOST = 3


class QoSIncompatibleQoSInfo:
    """rmw_{offered,requested}_qos_incompatible_event_status_t."""

    def __init__(self, total_count, total_count_change, last_policy_kind):
        self.total_count = total_count
        self.total_count_change = total_count_change
        self.last_policy_kind = last_policy_kind

    def __repr__(self):
        return (f'QoSIncompatibleQoSInfo(total_count={self.total_count}, total_count_change='
                f'{self.total_count_change}, last_policy_kind={self.last_policy_kind!r})')


QoSOfferedIncompatibleQoSInfo = QoSIncompatibleQoSInfo
QoSRequestedIncompatibleQoSInfo = QoSIncompatibleQoSInfo


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
