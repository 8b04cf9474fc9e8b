"""Timers fire in rclpy's order under labkit's deadline heaps: among the timers due at the
same instant, node order then creation order; a deadline moved by reset(), a new period,
cancel() or /clock is honoured at once (virtual time)."""
from labkit.rclpy.executors import SingleThreadedExecutor
from labkit.rclpy.node import Node
from labkit.rclpy.time import Time


def spin_for(executor, node, seconds):
    clock = node.get_clock()
    end = clock.now().nanoseconds + int(seconds * 1e9)
    while clock.now().nanoseconds < end:
        executor.spin_once(timeout_sec=(end - clock.now().nanoseconds) / 1e9)


def test_same_instant_fires_in_node_then_creation_order(rclpy):
    first, second = Node('first'), Node('second')
    start = first.get_clock().now().nanoseconds
    fired = []

    def record(name):
        return lambda: fired.append((round((first.get_clock().now().nanoseconds - start) / 1e8),
                                     name))
    periods = {'a': 0.3, 'b': 0.1, 'c': 0.2}
    for name, period in periods.items():
        second.create_timer(period, record('2' + name))
    for name, period in periods.items():
        first.create_timer(period, record('1' + name))
    executor = SingleThreadedExecutor()
    executor.add_node(first)
    executor.add_node(second)
    spin_for(executor, first, 0.65)
    expected = []
    for tick in range(1, 7):
        for node in '12':
            for name, period in periods.items():
                if tick % round(period * 10) == 0:
                    expected.append((tick, node + name))
    assert fired == expected


def test_a_shorter_period_and_reset_take_effect_at_once(rclpy):
    node = Node('n')
    clock = node.get_clock()
    start = clock.now().nanoseconds
    fired = []
    timer = node.create_timer(1.0, lambda: fired.append((clock.now().nanoseconds - start) // 10**8))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    spin_for(executor, node, 0.25)
    timer.timer_period_ns = 2 * 10**8          # resets: next at 0.25 + 0.2
    spin_for(executor, node, 0.5)
    assert fired == [4, 6]
    timer.cancel()
    spin_for(executor, node, 0.5)
    assert fired == [4, 6]
    timer.reset()                              # at 1.25: next at 1.45
    spin_for(executor, node, 0.3)
    assert fired == [4, 6, 14]


def test_a_timer_on_sim_time_follows_the_clock_back_and_forth(rclpy):
    node = Node('n')
    clock = node.get_clock()
    fired = []
    timer = node.create_timer(1.0, lambda: fired.append(clock.now().nanoseconds // 10**9))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    clock._set_ros_time_is_active(True)
    clock.set_ros_time_override(Time(seconds=0))
    timer.reset()                              # next at 1 s of /clock
    executor.spin_once(timeout_sec=0)
    assert fired == []
    clock.set_ros_time_override(Time(seconds=1))
    executor.spin_once(timeout_sec=0)
    assert fired == [1]
    clock.set_ros_time_override(Time(seconds=5))   # missed periods are skipped
    executor.spin_once(timeout_sec=0)
    executor.spin_once(timeout_sec=0)
    assert fired == [1, 5]
    clock.set_ros_time_override(Time(seconds=2))   # back in time: not due until 6 s
    executor.spin_once(timeout_sec=0)
    assert fired == [1, 5]
    clock.set_ros_time_override(Time(seconds=6))
    executor.spin_once(timeout_sec=0)
    assert fired == [1, 5, 6]
