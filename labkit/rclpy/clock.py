"""rclpy.clock: system, steady and ROS clocks over the world clock (virtual or live)."""
from enum import IntEnum
import threading

from labkit.graph import world
from labkit.rclpy._clock_type import ClockType
from labkit.rclpy.duration import Duration
from labkit.rclpy.time import Time

__all__ = ['Clock', 'ROSClock', 'ClockType', 'ClockChange', 'JumpThreshold', 'TimeJump',
           'JumpHandle']


class ClockChange(IntEnum):
    ROS_TIME_NO_CHANGE = 1
    ROS_TIME_ACTIVATED = 2
    ROS_TIME_DEACTIVATED = 3
    SYSTEM_TIME_NO_CHANGE = 4


class JumpThreshold:
    def __init__(self, *, min_forward, min_backward, on_clock_change=True):
        if min_forward is not None and min_forward.nanoseconds <= 0:
            raise ValueError('min_forward must be a positive duration')
        if min_backward is not None and min_backward.nanoseconds >= 0:
            raise ValueError('min_backward must be a negative duration')
        self.min_forward = min_forward
        self.min_backward = min_backward
        self.on_clock_change = on_clock_change


class TimeJump:
    def __init__(self, clock_change, delta):
        self._clock_change = clock_change
        self._delta = delta

    @property
    def clock_change(self):
        return self._clock_change

    @property
    def delta(self):
        return self._delta


class JumpHandle:
    def __init__(self, *, clock, threshold, pre_callback, post_callback):
        self._clock = clock
        self._threshold = threshold
        self._pre = pre_callback
        self._post = post_callback
        clock._jump_handles.append(self)

    def unregister(self):
        if self._clock is not None and self in self._clock._jump_handles:
            self._clock._jump_handles.remove(self)
        self._clock = None

    def _wants(self, change, delta_ns):
        t = self._threshold
        if change in (ClockChange.ROS_TIME_ACTIVATED, ClockChange.ROS_TIME_DEACTIVATED):
            return t.on_clock_change
        if t.min_forward is not None and delta_ns >= t.min_forward.nanoseconds:
            return True
        if t.min_backward is not None and delta_ns <= t.min_backward.nanoseconds:
            return True
        return False


class Clock:
    def __new__(cls, *, clock_type=ClockType.SYSTEM_TIME):
        if not isinstance(clock_type, ClockType):
            raise TypeError('Clock type must be a ClockType enum')
        if clock_type is ClockType.ROS_TIME and cls is Clock:
            self = super().__new__(ROSClock)
        else:
            self = super().__new__(cls)
        self._clock_type = clock_type
        self._jump_handles = []
        self._lock = threading.Lock()
        self._ros_time_is_active = False
        self._ros_time_override = 0
        return self

    def __init__(self, *, clock_type=ClockType.SYSTEM_TIME):
        pass

    @property
    def clock_type(self):
        return self._clock_type

    @property
    def handle(self):
        return self

    def __repr__(self):
        return 'Clock(clock_type={0})'.format(self.clock_type.name)

    def _now_ns(self):
        if self._clock_type == ClockType.STEADY_TIME:
            return world.steady_ns()
        if self._ros_time_is_active:
            return self._ros_time_override
        return world.system_ns()

    def now(self):
        return Time(nanoseconds=self._now_ns(), clock_type=self._clock_type)

    def create_jump_callback(self, threshold, *, pre_callback=None, post_callback=None):
        return JumpHandle(clock=self, threshold=threshold, pre_callback=pre_callback,
                          post_callback=post_callback)

    def _jump(self, change, delta_ns):
        for handle in list(self._jump_handles):
            if handle._wants(change, delta_ns):
                jump = TimeJump(change, Duration(nanoseconds=delta_ns))
                if handle._pre is not None:
                    handle._pre()
                if handle._post is not None:
                    handle._post(jump)

    # labkit: a wait point that follows this clock (used by Rate and friends)
    def sleep_until(self, until, context=None):
        from labkit.rclpy.utilities import get_default_context
        context = context or get_default_context()
        target = until.nanoseconds
        while context.ok() and self._now_ns() < target:
            left = target - self._now_ns()
            if self._clock_type == ClockType.ROS_TIME and self._ros_time_is_active:
                world.wait(lambda: not context.ok() or self._now_ns() >= target, 1.0)
            else:
                world.wait(lambda: not context.ok(), timeout_ns=left)
        return self._now_ns() >= target

    def sleep_for(self, rel_time, context=None):
        return self.sleep_until(self.now() + rel_time, context)


class ROSClock(Clock):
    def __new__(cls):
        return super().__new__(ROSClock, clock_type=ClockType.ROS_TIME)

    def __init__(self, *args, **kwargs):
        pass

    @property
    def ros_time_is_active(self):
        return self._ros_time_is_active

    def _set_ros_time_is_active(self, enabled):
        if bool(enabled) == self._ros_time_is_active:
            return
        before = self._now_ns()
        self._ros_time_is_active = bool(enabled)
        from labkit.rclpy.timer import TIMER_GEN
        TIMER_GEN[0] += 1                 # executors file timers under their time source
        change = ClockChange.ROS_TIME_ACTIVATED if enabled else ClockChange.ROS_TIME_DEACTIVATED
        self._jump(change, self._now_ns() - before)
        world.notify()

    def set_ros_time_override(self, time):
        from labkit.rclpy.time import Time as _Time
        if not isinstance(time, _Time):
            raise TypeError('Time must be specified as rclpy.time.Time')
        before = self._ros_time_override
        self._ros_time_override = time.nanoseconds
        if self._ros_time_is_active:
            self._jump(ClockChange.ROS_TIME_NO_CHANGE, time.nanoseconds - before)
        world.notify()


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
