"""rclpy.timer: Timer (polled by executors against its clock) and Rate."""
import threading

from labkit.graph import world
from labkit.rclpy._clock_type import ClockType

# Bumped when a timer's deadline moves other than by firing (reset, a new period) or a clock
# starts or stops following /clock: executors then file their timers' deadlines again.
TIMER_GEN = [0]


class Timer:
    def __init__(self, callback, callback_group, timer_period_ns, clock, *, context=None):
        from labkit.rclpy.utilities import get_default_context
        self._context = get_default_context() if context is None else context
        if int(timer_period_ns) < 0:       # rcl_timer_init refuses it (rcl/src/rcl/timer.c)
            from labkit.rclpy.exceptions import RCLError
            raise RCLError('failed to create timer: timer period must be non-negative, '
                           'at ./src/rcl/timer.c:139')
        self._clock = clock
        self.callback = callback
        self.callback_group = callback_group
        self._period = int(timer_period_ns)
        self._canceled = False
        self._destroyed = False
        self._executor_event = False
        self._node = None
        now = clock._now_ns()
        self._last_call = now
        self._next_call = now + self._period
        from labkit.rclpy._entity import Handle
        self._handle = Handle(self)

    @property
    def handle(self):
        return self._handle

    @property
    def clock(self):
        return self._clock

    @property
    def timer_period_ns(self):
        return self._period

    @timer_period_ns.setter
    def timer_period_ns(self, value):
        self._period = int(value)
        self.reset()

    def is_ready(self):
        return (not self._canceled and not self._destroyed and
                self._clock._now_ns() >= self._next_call)

    def is_canceled(self):
        return self._canceled

    def cancel(self):
        self._canceled = True

    def reset(self):
        now = self._clock._now_ns()
        self._canceled = False
        self._next_call = now + self._period
        TIMER_GEN[0] += 1
        if self._node is not None:
            self._node._wake_executor()
        world.notify()

    def time_since_last_call(self):
        return self._clock._now_ns() - self._last_call

    def time_until_next_call(self):
        if self._canceled:
            return None
        return self._next_call - self._clock._now_ns()

    def _call(self):
        """rcl_timer_call: advance the schedule (skipping missed periods)."""
        now = self._clock._now_ns()
        self._last_call = now
        nxt = self._next_call + self._period
        if nxt <= now and self._period > 0:
            nxt += ((now - nxt) // self._period + 1) * self._period
        elif self._period == 0:
            nxt = now
        self._next_call = nxt

    def _wait_ns(self):
        """Nanoseconds of world time until due, or None when it follows /clock or is off."""
        if self._canceled or self._destroyed:
            return None
        clock = self._clock
        if clock._clock_type == ClockType.ROS_TIME and clock._ros_time_is_active:
            return None
        return max(0, self._next_call - clock._now_ns())

    def destroy(self):
        if self._node is not None:
            self._node.destroy_timer(self)
        self._destroyed = True

    def _destroy(self):
        self._destroyed = True


class Rate:
    """Sleep at a fixed rate: the rate's timer sets an event (it must be spun by an executor,
    as in rclpy); sleep() returns once the event is set, and the last sleeper clears it."""

    def __init__(self, timer, *, context):
        self._timer = timer
        self._is_shutdown = False
        self._is_destroyed = False
        self._event = False
        self._lock = threading.Lock()
        self._num_sleepers = 0
        timer.callback = self._set
        context.on_shutdown(self._on_shutdown)

    def _set(self):
        self._event = True
        world.notify()

    def _on_shutdown(self):
        self._is_shutdown = True
        self.destroy()

    def destroy(self):
        self._is_destroyed = True
        self._set()

    def _presleep(self):
        from labkit.rclpy.exceptions import InvalidHandle, ROSInterruptException
        if self._is_shutdown:
            raise ROSInterruptException()
        if self._is_destroyed:
            raise RuntimeError('Rate cannot sleep because it has been destroyed')
        if self._timer._destroyed:
            self.destroy()
            raise InvalidHandle('Rate cannot sleep because the timer has been destroyed')
        with self._lock:
            self._num_sleepers += 1

    def _postsleep(self):
        from labkit.rclpy.exceptions import ROSInterruptException
        with self._lock:
            self._num_sleepers -= 1
            if self._num_sleepers == 0:
                self._event = False
        if self._is_shutdown:
            self.destroy()
            raise ROSInterruptException()

    def sleep(self):
        """Block until the timer triggers (a world wait point)."""
        from labkit.rclpy import _wait
        self._presleep()
        try:
            _wait.wait(lambda: self._event)
        finally:
            self._postsleep()


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
