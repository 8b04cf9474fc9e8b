"""Conformance: timers, rates, clocks, Time and Duration.

Plain rclpy: runs unchanged on ROS 2 Humble.
Humble/Jazzy: comparing a Time or Duration with another type (== 1) raises TypeError in
Humble (Jazzy returns NotImplemented, so == is False); the expected file keeps Humble's.
Enum values are printed by .name/int(): Humble's ClockType is a pybind11 enum, Jazzy's an
IntEnum, whose str() differs.
"""
import threading

import rclpy
from builtin_interfaces.msg import Duration as DurationMsg
from builtin_interfaces.msg import Time as TimeMsg
from rclpy.clock import Clock, ClockType
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.time import Time


def attempt(label, fn):
    try:
        value = fn()
        print(f'{label}: ok {value!r}')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print(f'{label}: {type(e).__name__}: {e}')


def main():
    # Time and Duration arithmetic (no context needed)
    t1 = Time(seconds=1, nanoseconds=500000000)
    t2 = Time(seconds=3)
    print(repr(t1), repr(Duration(seconds=2.5)), str(Duration(seconds=1)))
    print('t2 - t1 =', repr(t2 - t1))
    print('t1 + 2s =', repr(t1 + Duration(seconds=2)))
    print('t2 - 1s =', repr(t2 - Duration(seconds=1)))
    print('seconds_nanoseconds:', t1.seconds_nanoseconds(), 'nanoseconds:', t1.nanoseconds)
    print('to_msg:', t1.to_msg(), Duration(seconds=-1.5).to_msg())
    print('from_msg:', repr(Time.from_msg(TimeMsg(sec=7, nanosec=8))),
          repr(Duration.from_msg(DurationMsg(sec=2, nanosec=1))))
    print('compare:', t1 < t2, t1 == Time(nanoseconds=1500000000), Duration(seconds=1) >
          Duration(seconds=0.5))
    print('clock types:', t1.clock_type.name, ClockType.ROS_TIME.name,
          int(ClockType.ROS_TIME), int(ClockType.SYSTEM_TIME), int(ClockType.STEADY_TIME))
    ros_time = Time(seconds=1, clock_type=ClockType.ROS_TIME)
    print('ros time:', repr(ros_time))
    attempt('system time - ros time', lambda: t2 - ros_time)
    attempt('system time < ros time', lambda: t1 < ros_time)
    attempt('system time == ros time', lambda: t1 == ros_time)
    attempt('time + time', lambda: t1 + t2)
    attempt('negative time', lambda: Time(seconds=-1))
    attempt('duration == 1', lambda: Duration(seconds=1) == 1)
    attempt('time == 1', lambda: t1 == 1)
    attempt('Time(seconds=1.25)', lambda: Time(seconds=1.25).nanoseconds)

    rclpy.init()
    node = rclpy.create_node('timekeeper')
    print('node clock type:', node.get_clock().clock_type.name)
    print('now is Time:', type(node.get_clock().now()).__name__,
          node.get_clock().now().clock_type.name)
    print('Clock() type:', Clock().clock_type.name)
    executor = SingleThreadedExecutor()
    executor.add_node(node)

    # one timer: period, count, cancel
    ticks = []
    timer = node.create_timer(0.1, lambda: ticks.append('fast'))
    print('timer period ns:', timer.timer_period_ns, 'canceled:', timer.is_canceled())
    while len(ticks) < 5:
        executor.spin_once(timeout_sec=1.0)
    timer.cancel()
    print('ticks:', len(ticks), 'canceled:', timer.is_canceled())
    for _ in range(3):
        executor.spin_once(timeout_sec=0.1)
    print('after cancel:', len(ticks))
    timer.reset()
    print('reset -> canceled:', timer.is_canceled())
    while len(ticks) < 7:
        executor.spin_once(timeout_sec=1.0)
    print('ticks after reset:', len(ticks))
    node.destroy_timer(timer)

    # two timers interleave by their deadlines
    order = []
    fast = node.create_timer(0.1, lambda: order.append('F'))
    slow = node.create_timer(0.25, lambda: order.append('S'))
    while order.count('F') < 4:
        executor.spin_once(timeout_sec=1.0)
    print('interleaving:', ''.join(order))
    node.destroy_timer(fast)
    node.destroy_timer(slow)

    # time passes by at least the waited period
    start = node.get_clock().now()
    count = []
    timer = node.create_timer(0.2, lambda: count.append(1))
    while not count:
        executor.spin_once(timeout_sec=1.0)
    elapsed = (node.get_clock().now() - start).nanoseconds
    print('first 0.2 s tick after >= 0.2 s:', elapsed >= 200_000_000)
    node.destroy_timer(timer)

    # a Rate used from another thread while the executor spins
    spinner = threading.Thread(target=executor.spin, daemon=True)
    spinner.start()
    rate = node.create_rate(20)
    start = node.get_clock().now()
    for _ in range(5):
        rate.sleep()
    elapsed = (node.get_clock().now() - start).nanoseconds
    print('5 rate sleeps at 20 Hz took >= 0.2 s:', elapsed >= 200_000_000)
    rate.destroy()
    attempt('create_rate(0)', lambda: node.create_rate(0))

    executor.shutdown()
    spinner.join(timeout=5.0)
    node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
