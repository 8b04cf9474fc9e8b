"""QoS overriding options (accepted; labkit does not declare qos_overrides parameters)."""
from enum import IntEnum


class QosCallbackResult:
    def __init__(self, successful=True, reason=''):
        self.successful = successful
        self.reason = reason


class QoSPolicyKindOverride(IntEnum):
    HISTORY = 0
    DEPTH = 1
    RELIABILITY = 2
    DURABILITY = 3


class QoSOverridingOptions:
    def __init__(self, policy_kinds, *, callback=None, entity_id=None):
        self._policy_kinds = policy_kinds
        self._callback = callback
        self._entity_id = entity_id

    @property
    def policy_kinds(self):
        return self._policy_kinds

    @property
    def callback(self):
        return self._callback

    @property
    def entity_id(self):
        return self._entity_id

    @classmethod
    def with_default_policies(cls, *, callback=None, entity_id=None):
        return cls(policy_kinds=(), callback=callback, entity_id=entity_id)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
