from labkit.rclpy.constants import S_TO_NS
from labkit.rclpy._msgs import msg_class

RMW_DURATION_INFINITE = 2**63 - 1


class Duration:
    """A signed span of time in nanoseconds."""

    __slots__ = ("_nanoseconds",)

    def __init__(self, *, seconds=0, nanoseconds=0):
        total = int(seconds * S_TO_NS) + int(nanoseconds)
        if total >= 2**63 or total < -2**63:
            raise OverflowError('Total nanoseconds value is too large to store in C duration.')
        self._nanoseconds = total

    @property
    def nanoseconds(self):
        return self._nanoseconds

    def __repr__(self):
        return 'Duration(nanoseconds={0})'.format(self._nanoseconds)

    def __str__(self):
        if self._nanoseconds == RMW_DURATION_INFINITE:
            return 'Infinite'
        return f'{self._nanoseconds} nanoseconds'

    def __hash__(self):
        return hash(self._nanoseconds)

    def __eq__(self, other):
        if isinstance(other, Duration):
            return self._nanoseconds == other._nanoseconds
        raise TypeError("Can't compare duration with object of type: ", type(other))

    def __ne__(self, other):
        return not self.__eq__(other)

    def __lt__(self, other):
        if isinstance(other, Duration):
            return self._nanoseconds < other._nanoseconds
        return NotImplemented

    def __le__(self, other):
        if isinstance(other, Duration):
            return self._nanoseconds <= other._nanoseconds
        return NotImplemented

    def __gt__(self, other):
        if isinstance(other, Duration):
            return self._nanoseconds > other._nanoseconds
        return NotImplemented

    def __ge__(self, other):
        if isinstance(other, Duration):
            return self._nanoseconds >= other._nanoseconds
        return NotImplemented

    def to_msg(self):
        seconds, nanoseconds = divmod(self._nanoseconds, S_TO_NS)
        return msg_class('builtin_interfaces/msg/Duration')(sec=seconds, nanosec=nanoseconds)

    @classmethod
    def from_msg(cls, msg):
        if type(msg).__name__ != 'Duration' or not hasattr(msg, 'nanosec'):
            raise TypeError('Must pass a builtin_interfaces.msg.Duration object')
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)

    def get_c_duration(self):
        return self


Infinite = Duration(nanoseconds=RMW_DURATION_INFINITE)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
