import pytest

import labkit
from labkit import process


def ticker(period, counts, name='ticker'):
    def main(args=None):
        import labkit.rclpy as rclpy
        from labkit.rclpy.node import Node
        rclpy.init(args=args)
        node = Node(name)

        def tick():
            counts.append(node.get_clock().now().nanoseconds)
        node.create_timer(period, tick)
        rclpy.spin(node)
    return main


def test_timer_fires_exactly_ten_times_in_one_second(virtual):
    counts = []
    process.start(main=ticker(0.1, counts), name='ticker')
    labkit.sleep(1.0)
    assert len(counts) == 10
    epoch = 1704067200 * 10**9
    assert counts == [epoch + i * 100_000_000 for i in range(1, 11)]
    labkit.sleep(0.55)
    assert len(counts) == 15


def test_virtual_clocks(virtual):
    import labkit.rclpy as rclpy
    from labkit.rclpy.clock import Clock, ClockType
    rclpy.init()
    from labkit.rclpy.node import Node
    node = Node('n')
    assert node.get_clock().now().nanoseconds == 1704067200 * 10**9
    assert node.get_clock().clock_type == ClockType.ROS_TIME
    steady = Clock(clock_type=ClockType.STEADY_TIME)
    assert steady.now().nanoseconds == 0
    labkit.sleep(2.5)
    assert steady.now().nanoseconds == 2_500_000_000
    assert Clock().now().seconds_nanoseconds() == (1704067202, 500_000_000)
    assert labkit.time_mode() == 'virtual'


def test_time_and_duration_api():
    from labkit.rclpy.clock import ClockType
    from labkit.rclpy.duration import Duration, Infinite
    from labkit.rclpy.time import Time
    t = Time(seconds=1.5, clock_type=ClockType.ROS_TIME)
    assert t.nanoseconds == 1_500_000_000
    assert repr(t) == 'Time(nanoseconds=1500000000, clock_type=ROS_TIME)'
    assert (t + Duration(seconds=1)).nanoseconds == 2_500_000_000
    assert (t - Time(seconds=1, clock_type=ClockType.ROS_TIME)) == Duration(nanoseconds=5 * 10**8)
    assert str(Duration(seconds=2)) == '2000000000 nanoseconds'
    assert str(Infinite) == 'Infinite'
    with pytest.raises(TypeError):
        t == Time(seconds=1)          # different clock types
    with pytest.raises(ValueError):
        Time(seconds=-1)
    msg = t.to_msg()
    assert (msg.sec, msg.nanosec) == (1, 500_000_000)
    assert Time.from_msg(msg) == t
    d = Duration(seconds=3, nanoseconds=5).to_msg()
    assert (d.sec, d.nanosec) == (3, 5)


def test_rate_in_a_process(virtual):
    stamps = []

    def main(args=None):
        import threading
        import labkit.rclpy as rclpy
        from labkit.rclpy.node import Node
        rclpy.init(args=args)
        node = Node('looper')
        threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
        rate = node.create_rate(2)
        while rclpy.ok():
            stamps.append(node.get_clock().now().nanoseconds)
            rate.sleep()

    proc = process.start(main=main, name='looper')
    labkit.sleep(2.0)
    assert len(stamps) == 5
    proc.stop()
    assert not proc.running


def test_sim_time_follows_clock_topic(virtual, msgs):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    from labkit.rclpy.time import Time
    rclpy.init(args=['--ros-args', '-p', 'use_sim_time:=true'])
    node = Node('sim')
    assert node.get_parameter('use_sim_time').value is True
    assert node.get_clock().ros_time_is_active
    assert node.get_clock().now().nanoseconds == 0
    pub = Node('clock_pub', use_global_arguments=False).create_publisher(
        msgs.Clock, '/clock', 10)
    pub.publish(msgs.Clock(clock=Time(seconds=42).to_msg()))
    rclpy.spin_once(node, timeout_sec=0)
    assert node.get_clock().now().nanoseconds == 42 * 10**9


def test_deadlock_instead_of_hanging(rclpy, virtual):
    from labkit.rclpy.node import Node
    from labkit.rclpy.task import Future
    node = Node('n')
    with pytest.raises(virtual.Deadlock):
        rclpy.spin_until_future_complete(node, Future())


def test_spin_once_timeout_advances_virtual_time(rclpy, virtual):
    from labkit.rclpy.node import Node
    node = Node('n')
    rclpy.spin_once(node, timeout_sec=0.25)
    assert virtual.steady_ns() == 250_000_000


def test_settle_runs_new_work_without_time_passing(virtual, msgs):
    got = []

    def main(args=None):
        import labkit.rclpy as rclpy
        from labkit.rclpy.node import Node
        rclpy.init(args=args)
        node = Node('echo')
        node.create_subscription(msgs.String, 'in', lambda m: got.append(m.data), 10)
        rclpy.spin(node)

    process.start(main=main, name='echo')
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init()
    Node('src').create_publisher(msgs.String, 'in', 10).publish(msgs.String(data='x'))
    assert got == []
    virtual.settle()
    assert got == ['x']
    assert virtual.steady_ns() == 0


def test_rate_with_spin_once_loop_like_state_publisher(virtual):
    """The r2d2 state_publisher pattern: `while ok: spin_once; ...; rate.sleep()`."""
    stamps = []

    def main(args=None):
        import labkit.rclpy as rclpy
        from labkit.rclpy.node import Node
        rclpy.init(args=args)
        node = Node('state_publisher')
        rate = node.create_rate(10)
        while rclpy.ok():
            rclpy.spin_once(node)
            stamps.append(node.get_clock().now().nanoseconds - 1704067200 * 10**9)
            rate.sleep()

    process.start(main=main, name='sp')
    labkit.sleep(0.5)
    assert stamps == [100_000_000, 200_000_000, 300_000_000, 400_000_000, 500_000_000]
