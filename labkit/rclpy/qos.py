"""Quality of service profiles and policies (rclpy.qos), with rmw's compatibility check."""
from enum import Enum, IntEnum
import warnings

from labkit.graph import qos_match as _match
from labkit.rclpy.duration import Duration

__all__ = ["QoSProfile", "QoSPolicyKind", "HistoryPolicy", "ReliabilityPolicy",
           "DurabilityPolicy", "LivelinessPolicy", "QoSHistoryPolicy", "QoSReliabilityPolicy",
           "QoSDurabilityPolicy", "QoSLivelinessPolicy", "QoSPresetProfiles",
           "QoSCompatibility", "qos_check_compatible", "InvalidQoSProfileException",
           "qos_profile_unknown", "qos_profile_system_default", "qos_profile_sensor_data",
           "qos_profile_services_default", "qos_profile_parameters",
           "qos_profile_parameter_events", "qos_profile_action_status_default",
           "qos_policy_name_from_kind"]


class QoSPolicyKind(IntEnum):
    INVALID = 1 << 0
    DURABILITY = 1 << 1
    DEADLINE = 1 << 2
    LIVELINESS = 1 << 3
    RELIABILITY = 1 << 4
    HISTORY = 1 << 5
    LIFESPAN = 1 << 6
    DEPTH = 1 << 7
    LIVELINESS_LEASE_DURATION = 1 << 8
    AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9


def qos_policy_name_from_kind(policy_kind):
    return QoSPolicyKind(policy_kind).name


class InvalidQoSProfileException(Exception):
    def __init__(self, *args):
        Exception.__init__(self, 'Invalid QoSProfile', *args)


class QoSPolicyEnum(IntEnum):
    # Humble runs on Python 3.10, where str() of an IntEnum member is 'Class.NAME'
    def __str__(self):
        return f'{type(self).__name__}.{self.name}'

    @classmethod
    def short_keys(cls):
        return [k.lower() for k in cls.__members__.keys() if not k.startswith('RMW')]

    @classmethod
    def get_from_short_key(cls, name):
        return cls[name.upper()].value

    @property
    def short_key(self):
        for k, v in self.__class__.__members__.items():
            if k.startswith('RMW'):
                continue
            if self.value == v:
                return k.lower()
        raise AttributeError('failed to find value %s in %s' % (self.value, self.__class__.__name__))


class _DeprecatedAlias:
    def __init__(self, replacement, deprecated):
        self.replacement, self.deprecated = replacement, deprecated

    def __get__(self, obj, cls):
        warnings.warn(f'{cls.__name__}.{self.deprecated} is deprecated. '
                      f'Use {cls.__name__}.{self.replacement} instead.')
        return cls[self.replacement]


def _aliases(prefix, names):
    def decorate(cls):
        for n in names:
            setattr(cls, f'RMW_QOS_POLICY_{prefix}_{n}', _DeprecatedAlias(n, f'RMW_QOS_POLICY_{prefix}_{n}'))
        return cls
    return decorate


@_aliases('HISTORY', ('SYSTEM_DEFAULT', 'KEEP_LAST', 'KEEP_ALL', 'UNKNOWN'))
class HistoryPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


@_aliases('RELIABILITY', ('SYSTEM_DEFAULT', 'RELIABLE', 'BEST_EFFORT', 'UNKNOWN'))
class ReliabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3


@_aliases('DURABILITY', ('SYSTEM_DEFAULT', 'TRANSIENT_LOCAL', 'VOLATILE', 'UNKNOWN'))
class DurabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3


@_aliases('LIVELINESS', ('SYSTEM_DEFAULT', 'AUTOMATIC', 'MANUAL_BY_TOPIC'))
class LivelinessPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4


QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
QoSLivelinessPolicy = LivelinessPolicy

_DEFAULT = dict(depth=10, reliability=ReliabilityPolicy.RELIABLE,
                durability=DurabilityPolicy.VOLATILE, lifespan=Duration(),
                deadline=Duration(), liveliness=LivelinessPolicy.SYSTEM_DEFAULT,
                liveliness_lease_duration=Duration(), avoid_ros_namespace_conventions=False)


class QoSProfile:
    """Define Quality of Service policies."""

    __slots__ = ['_history', '_depth', '_reliability', '_durability', '_lifespan', '_deadline',
                 '_liveliness', '_liveliness_lease_duration', '_avoid_ros_namespace_conventions']

    def __init__(self, **kwargs):
        assert all('_' + key in self.__slots__ for key in kwargs.keys()), \
            'Invalid arguments passed to constructor: %r' % kwargs.keys()
        if 'history' not in kwargs:
            if 'depth' not in kwargs:
                raise InvalidQoSProfileException('History and/or depth settings are required.')
            kwargs['history'] = HistoryPolicy.KEEP_LAST
        self.history = kwargs.get('history')
        if HistoryPolicy.KEEP_LAST == self.history and 'depth' not in kwargs:
            raise InvalidQoSProfileException('History set to KEEP_LAST without a depth setting.')
        for key, default in _DEFAULT.items():
            setattr(self, key, kwargs.get(key, default))

    @property
    def history(self):
        return self._history

    @history.setter
    def history(self, value):
        assert isinstance(value, QoSHistoryPolicy) or isinstance(value, int)
        self._history = QoSHistoryPolicy(value)

    @property
    def reliability(self):
        return self._reliability

    @reliability.setter
    def reliability(self, value):
        assert isinstance(value, QoSReliabilityPolicy) or isinstance(value, int)
        self._reliability = QoSReliabilityPolicy(value)

    @property
    def durability(self):
        return self._durability

    @durability.setter
    def durability(self, value):
        assert isinstance(value, QoSDurabilityPolicy) or isinstance(value, int)
        self._durability = QoSDurabilityPolicy(value)

    @property
    def depth(self):
        return self._depth

    @depth.setter
    def depth(self, value):
        assert isinstance(value, int)
        self._depth = value

    @property
    def lifespan(self):
        return self._lifespan

    @lifespan.setter
    def lifespan(self, value):
        assert isinstance(value, Duration)
        self._lifespan = value

    @property
    def deadline(self):
        return self._deadline

    @deadline.setter
    def deadline(self, value):
        assert isinstance(value, Duration)
        self._deadline = value

    @property
    def liveliness(self):
        return self._liveliness

    @liveliness.setter
    def liveliness(self, value):
        assert isinstance(value, (QoSLivelinessPolicy, int))
        self._liveliness = QoSLivelinessPolicy(value)

    @property
    def liveliness_lease_duration(self):
        return self._liveliness_lease_duration

    @liveliness_lease_duration.setter
    def liveliness_lease_duration(self, value):
        assert isinstance(value, Duration)
        self._liveliness_lease_duration = value

    @property
    def avoid_ros_namespace_conventions(self):
        return self._avoid_ros_namespace_conventions

    @avoid_ros_namespace_conventions.setter
    def avoid_ros_namespace_conventions(self, value):
        assert isinstance(value, bool)
        self._avoid_ros_namespace_conventions = value

    def get_c_qos_profile(self):
        return self

    def __eq__(self, other):
        if not isinstance(other, QoSProfile):
            return False
        return all(getattr(self, s) == getattr(other, s) for s in self.__slots__)

    def __str__(self):
        return f'{type(self).__name__}(%s)' % (
            ', '.join(f'{slot[1:]}=%s' % getattr(self, slot) for slot in self.__slots__))

    __repr__ = __str__

    def _copy(self):
        return QoSProfile(**{s[1:]: getattr(self, s) for s in self.__slots__})


def _profile(history, depth, reliability, durability, **extra):
    return QoSProfile(history=history, depth=depth, reliability=reliability,
                      durability=durability, **extra)


qos_profile_unknown = _profile(HistoryPolicy.UNKNOWN, 0, ReliabilityPolicy.UNKNOWN,
                               DurabilityPolicy.UNKNOWN, liveliness=LivelinessPolicy.UNKNOWN)
qos_profile_system_default = _profile(HistoryPolicy.SYSTEM_DEFAULT, 0,
                                      ReliabilityPolicy.SYSTEM_DEFAULT,
                                      DurabilityPolicy.SYSTEM_DEFAULT)
qos_profile_sensor_data = _profile(HistoryPolicy.KEEP_LAST, 5, ReliabilityPolicy.BEST_EFFORT,
                                   DurabilityPolicy.VOLATILE)
qos_profile_services_default = _profile(HistoryPolicy.KEEP_LAST, 10,
                                        ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_parameters = _profile(HistoryPolicy.KEEP_LAST, 1000, ReliabilityPolicy.RELIABLE,
                                  DurabilityPolicy.VOLATILE)
qos_profile_parameter_events = _profile(HistoryPolicy.KEEP_LAST, 1000,
                                        ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_action_status_default = _profile(HistoryPolicy.KEEP_LAST, 1,
                                             ReliabilityPolicy.RELIABLE,
                                             DurabilityPolicy.TRANSIENT_LOCAL)
# rcl's /rosout profile (not public in rclpy, used by Node)
qos_profile_rosout_default = _profile(HistoryPolicy.KEEP_LAST, 1000, ReliabilityPolicy.RELIABLE,
                                      DurabilityPolicy.TRANSIENT_LOCAL,
                                      lifespan=Duration(seconds=10))


class QoSPresetProfiles(Enum):
    UNKNOWN = qos_profile_unknown
    SYSTEM_DEFAULT = qos_profile_system_default
    SENSOR_DATA = qos_profile_sensor_data
    SERVICES_DEFAULT = qos_profile_services_default
    PARAMETERS = qos_profile_parameters
    PARAMETER_EVENTS = qos_profile_parameter_events
    ACTION_STATUS_DEFAULT = qos_profile_action_status_default

    @classmethod
    def short_keys(cls):
        return [k.lower() for k in cls.__members__.keys() if not k.startswith('RMW')]

    @classmethod
    def get_from_short_key(cls, name):
        return cls[name.upper()].value


class QoSCompatibility(IntEnum):
    OK = 0
    WARNING = 1
    ERROR = 2


def check_compatible(pub, sub):
    """(QoSCompatibility, reason, last incompatible QoSPolicyKind or None)."""
    result, reason, kind = _match.check_compatible(pub, sub)
    return QoSCompatibility(result), reason, (QoSPolicyKind(kind) if kind else None)


def qos_check_compatible(publisher_qos, subscription_qos):
    compatibility, reason, _ = check_compatible(publisher_qos, subscription_qos)
    return compatibility, reason


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
