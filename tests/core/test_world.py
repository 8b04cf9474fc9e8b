"""The virtual-time scheduler (labkit/graph/world.py) on its own."""
import threading

import pytest


def test_sleep_advances_exactly(virtual):
    assert virtual.steady_ns() == 0
    assert virtual.system_ns() == virtual.VIRTUAL_EPOCH_NS
    virtual.sleep(0.1)
    virtual.sleep(0.2)
    assert virtual.steady_ns() == 300_000_000


def test_threads_run_one_at_a_time_in_creation_order(virtual):
    log = []

    def worker(name, period):
        for _ in range(3):
            virtual.sleep(period)
            log.append((name, virtual.steady_ns()))

    virtual.start_thread(worker, args=('a', 0.2))
    virtual.start_thread(worker, args=('b', 0.1))
    virtual.sleep(1.0)
    assert log == [('b', 100_000_000), ('a', 200_000_000), ('b', 200_000_000),
                   ('b', 300_000_000), ('a', 400_000_000), ('a', 600_000_000)]


def test_wait_predicate_and_timeout(virtual):
    box = []
    virtual.start_thread(lambda: (virtual.sleep(0.5), box.append(1)))
    assert virtual.wait(lambda: box, 2.0) is True
    assert virtual.steady_ns() == 500_000_000
    assert virtual.wait(lambda: False, 0.25) is False
    assert virtual.steady_ns() == 750_000_000


def test_settle_runs_ready_threads_without_time(virtual):
    box = []
    flag = []
    virtual.start_thread(lambda: (virtual.wait(lambda: flag), box.append('ran')))
    flag.append(1)
    assert box == []
    virtual.settle()
    assert box == ['ran'] and virtual.steady_ns() == 0


def test_deadlock_is_raised_in_the_waiting_thread(virtual):
    with pytest.raises(virtual.Deadlock):
        virtual.wait(lambda: False)
    # and the world still works afterwards
    virtual.sleep(0.1)
    assert virtual.steady_ns() == 100_000_000


def test_spinning_threads_are_world_threads(virtual, msgs):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init()
    node = Node('n')
    ticks = []
    node.create_timer(0.25, lambda: ticks.append(virtual.steady_ns()))
    t = threading.Thread(target=rclpy.spin, args=(node,))
    t.start()
    virtual.sleep(1.0)
    assert ticks == [250_000_000, 500_000_000, 750_000_000, 1_000_000_000]
    rclpy.shutdown()
    t.join()
    assert not t.is_alive()


def test_a_plain_thread_joins_the_world_at_its_first_wait(virtual):
    out = []
    started = threading.Event()

    def plain():
        started.set()
        virtual.sleep(1.0)
        out.append(virtual.steady_ns())
    t = threading.Thread(target=plain)
    t.start()
    started.wait()
    virtual.wait(lambda: virtual._by_ident.get(t.ident) is not None, 0.001)
    virtual.sleep(2.0)
    t.join(1.0)
    assert out and not t.is_alive()


def test_restart_clock(virtual):
    virtual.sleep(5.0)
    virtual.restart_clock()
    assert virtual.steady_ns() == 0


def test_reset_with_a_spinning_thread_in_main(virtual):
    import labkit
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init()
    node = Node('n')
    node.create_timer(0.3, lambda: None)
    t = threading.Thread(target=rclpy.spin, args=(node,))
    t.start()
    virtual.sleep(1.0)
    labkit.reset()
    assert virtual.steady_ns() == 0
    t.join(1.0)
    assert not t.is_alive()
