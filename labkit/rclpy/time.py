from labkit.rclpy._clock_type import ClockType
from labkit.rclpy.duration import Duration
from labkit.rclpy._msgs import msg_class

CONVERSION_CONSTANT = 10 ** 9


class Time:
    """A point in time of one clock type, in nanoseconds."""

    __slots__ = ("_nanoseconds", "_clock_type")

    def __init__(self, *, seconds=0, nanoseconds=0, clock_type=ClockType.SYSTEM_TIME):
        if not isinstance(clock_type, ClockType):
            raise TypeError('Clock type must be a ClockType enum')
        if seconds < 0:
            raise ValueError('Seconds value must not be negative')
        if nanoseconds < 0:
            raise ValueError('Nanoseconds value must not be negative')
        total = int(seconds * CONVERSION_CONSTANT) + int(nanoseconds)
        if total >= 2**63:
            raise OverflowError('Total nanoseconds value is too large to store in C time point.')
        self._nanoseconds = total
        self._clock_type = clock_type

    @property
    def nanoseconds(self):
        return self._nanoseconds

    def seconds_nanoseconds(self):
        return divmod(self._nanoseconds, CONVERSION_CONSTANT)

    @property
    def clock_type(self):
        return self._clock_type

    def __repr__(self):
        return 'Time(nanoseconds={0}, clock_type={1})'.format(
            self._nanoseconds, self._clock_type.name)

    def __hash__(self):
        return hash((self._nanoseconds, self._clock_type))

    def __add__(self, other):
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._nanoseconds + other.nanoseconds,
                            clock_type=self._clock_type)
            except OverflowError as e:
                raise OverflowError('Addition leads to overflow in C storage.') from e
        return NotImplemented

    def __radd__(self, other):
        return self.__add__(other)

    def __sub__(self, other):
        if isinstance(other, Time):
            if self._clock_type != other._clock_type:
                raise TypeError("Can't subtract times with different clock types")
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._nanoseconds - other.nanoseconds,
                            clock_type=self._clock_type)
            except ValueError as e:
                raise ValueError('Subtraction leads to negative time.') from e
        return NotImplemented

    def _check(self, other):
        if self._clock_type != other._clock_type:
            raise TypeError("Can't compare times with different clock types")

    def __eq__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self._nanoseconds == other._nanoseconds
        raise TypeError("Can't compare time with object of type: ", type(other))

    def __ne__(self, other):
        return not self.__eq__(other)

    def __lt__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self._nanoseconds < other._nanoseconds
        return NotImplemented

    def __le__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self._nanoseconds <= other._nanoseconds
        return NotImplemented

    def __gt__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self._nanoseconds > other._nanoseconds
        return NotImplemented

    def __ge__(self, other):
        if isinstance(other, Time):
            self._check(other)
            return self._nanoseconds >= other._nanoseconds
        return NotImplemented

    def to_msg(self):
        seconds, nanoseconds = self.seconds_nanoseconds()
        return msg_class('builtin_interfaces/msg/Time')(sec=seconds, nanosec=nanoseconds)

    @classmethod
    def from_msg(cls, msg, clock_type=ClockType.ROS_TIME):
        if type(msg).__name__ != 'Time' or not hasattr(msg, 'nanosec'):
            raise TypeError('Must pass a builtin_interfaces.msg.Time object')
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
