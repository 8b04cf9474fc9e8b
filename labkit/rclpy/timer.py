"""rclpy.timer: Timer (polled by executors against its clock) and Rate."""
import threading

from labkit.graph import world
from labkit.rclpy.clock_type import ClockType


class Timer:
    def __init__(self, callback, callback_group, timer_period_ns, clock, *, context=None):
        from labkit.rclpy.utilities import get_default_context
        self._context = get_default_context() if context is None else context
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
    """A convenience class for sleeping in a loop at a specified rate (needs a spinning executor)."""

    def __init__(self, timer, *, context):
        self._timer = timer
        self._presleep_event = None
        self._lock = threading.Lock()
        self._num_sleepers = 0
        self._fired = 0
        self._context = context
        self._is_shutdown = False
        timer.callback = self._timer_callback
        context.on_shutdown(self._on_shutdown)

    def _timer_callback(self):
        self._fired += 1

    def _on_shutdown(self):
        self._is_shutdown = True
        self.destroy()

    def destroy(self):
        self._is_shutdown = True
        self._timer.cancel()
        world.notify()

    def _presleep(self):
        if self._is_shutdown:
            from labkit.rclpy.exceptions import ROSInterruptException
            raise ROSInterruptException()

    def sleep(self):
        """Block until the next timer period (the timer fires in the executor that spins it)."""
        self._presleep()
        from labkit.rclpy import _wait
        target = self._fired + 1
        _wait.wait(lambda: self._fired >= target or self._is_shutdown)
        if self._is_shutdown:
            from labkit.rclpy.exceptions import ROSInterruptException
            raise ROSInterruptException()
