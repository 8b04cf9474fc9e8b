import pytest

import labkit
from labkit import process


def add(request, response):
    response.sum = request.a + request.b
    return response


def test_coroutine_callback_awaits_a_client(rclpy, msgs):
    from labkit.rclpy.callback_groups import MutuallyExclusiveCallbackGroup
    from labkit.rclpy.node import Node
    node = Node('n')
    # as in Humble, awaiting inside the default (mutually exclusive) group would deadlock:
    # the service and the client's response need groups of their own
    node.create_service(msgs.AddTwoInts, 'add', add,
                        callback_group=MutuallyExclusiveCallbackGroup())
    client = node.create_client(msgs.AddTwoInts, 'add',
                                callback_group=MutuallyExclusiveCallbackGroup())
    results = []

    async def on_msg(msg):
        response = await client.call_async(msgs.AddTwoInts.Request(a=msg.data, b=1))
        results.append(response.sum)
    node.create_subscription(msgs.Int32, 'x', on_msg, 10)
    node.create_publisher(msgs.Int32, 'x', 10).publish(msgs.Int32(data=41))
    for _ in range(10):
        rclpy.spin_once(node, timeout_sec=0)
    assert results == [42]


def test_create_task_and_async_timer(rclpy, msgs):
    from labkit.rclpy.executors import SingleThreadedExecutor
    from labkit.rclpy.node import Node
    node = Node('n')
    ex = SingleThreadedExecutor()
    ex.add_node(node)
    task = ex.create_task(lambda a, b: a + b, 2, 3)
    ex.spin_until_future_complete(task)
    assert task.result() == 5
    ticks = []

    async def tick():
        ticks.append(node.get_clock().now().nanoseconds)
    node.create_timer(0.5, tick)
    ex.spin_until_future_complete(ex.create_task(_never), timeout_sec=1.0)
    assert len(ticks) == 2


async def _never():
    from labkit.rclpy.task import Future
    await Future()


def test_exception_in_callback_propagates_from_spin(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    node.create_subscription(msgs.Int32, 'x', lambda m: 1 / 0, 10)
    node.create_publisher(msgs.Int32, 'x', 10).publish(msgs.Int32())
    with pytest.raises(ZeroDivisionError):
        rclpy.spin_once(node, timeout_sec=0)


def test_mutually_exclusive_group_and_reentrant_group():
    from labkit.rclpy.callback_groups import (MutuallyExclusiveCallbackGroup,
                                              ReentrantCallbackGroup)
    g = MutuallyExclusiveCallbackGroup()
    assert g.beginning_execution('a')
    assert not g.can_execute('b') and not g.beginning_execution('b')
    g.ending_execution('a')
    assert g.can_execute('b')
    r = ReentrantCallbackGroup()
    assert r.beginning_execution('a') and r.beginning_execution('b')


def test_multithreaded_executor_allows_a_nested_service_call(virtual, msgs):
    """A service callback that calls another service synchronously needs a
    MultiThreadedExecutor and a reentrant group, exactly as in real rclpy."""
    import labkit.rclpy as rclpy
    from labkit.rclpy.callback_groups import ReentrantCallbackGroup
    from labkit.rclpy.executors import MultiThreadedExecutor
    from labkit.rclpy.node import Node

    def main(args=None):
        rclpy.init(args=args)
        node = Node('relay')
        group = ReentrantCallbackGroup()
        inner = node.create_client(msgs.AddTwoInts, 'inner', callback_group=group)
        node.create_service(msgs.AddTwoInts, 'inner', add, callback_group=group)

        def outer(request, response):
            response.sum = inner.call(request).sum * 10
            return response
        node.create_service(msgs.AddTwoInts, 'outer', outer, callback_group=group)
        executor = MultiThreadedExecutor(num_threads=3)
        executor.add_node(node)
        try:
            executor.spin()
        finally:
            executor.shutdown()

    process.start(main=main, name='relay')
    rclpy.init()
    node = Node('caller')
    client = node.create_client(msgs.AddTwoInts, 'outer')
    future = client.call_async(msgs.AddTwoInts.Request(a=1, b=2))
    rclpy.spin_until_future_complete(node, future, timeout_sec=5.0)
    assert future.done() and future.result().sum == 30


def test_multithreaded_executor_runs_timers(rclpy, msgs):
    from labkit.rclpy.executors import MultiThreadedExecutor
    from labkit.rclpy.node import Node
    node = Node('n')
    ticks = []
    node.create_timer(0.1, lambda: ticks.append(1))
    ex = MultiThreadedExecutor(num_threads=2)
    ex.add_node(node)
    end = labkit.graph.world.steady_ns() + 1_000_000_000
    while labkit.graph.world.steady_ns() < end:
        ex.spin_once(timeout_sec=0.05)
    ex.shutdown()
    assert 9 <= len(ticks) <= 10


def test_spin_on_shutdown_context_and_external_shutdown(rclpy, msgs):
    from labkit.rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
    from labkit.rclpy.node import Node
    node = Node('n')
    ex = SingleThreadedExecutor()
    ex.add_node(node)
    node.create_timer(0.5, lambda: rclpy.shutdown())
    ex.spin()                       # shut down inside a callback: spin just returns
    assert not rclpy.ok()
    # shut down by someone else while the executor waits: Humble raises
    rclpy.init()
    node = Node('m')
    ex = SingleThreadedExecutor()
    ex.add_node(node)
    import threading

    def later():
        labkit.sleep(0.5)
        rclpy.shutdown()
    threading.Thread(target=later).start()
    with pytest.raises(ExternalShutdownException):
        ex.spin()
    assert not rclpy.ok()


def test_guard_condition_and_custom_waitable(rclpy):
    from labkit.rclpy.node import Node
    from labkit.rclpy.waitable import Waitable
    node = Node('n')
    fired = []
    gc = node.create_guard_condition(lambda: fired.append('gc'))
    rclpy.spin_once(node, timeout_sec=0)
    assert fired == []
    gc.trigger()
    rclpy.spin_once(node, timeout_sec=0)
    assert fired == ['gc']

    class Countdown(Waitable):
        def __init__(self, group, n):
            super().__init__(group)
            self.n = n

        def is_ready(self, wait_set):
            return self.n > 0

        def take_data(self):
            self.n -= 1
            return self.n

        async def execute(self, taken_data):
            fired.append(taken_data)
    node.add_waitable(Countdown(node.default_callback_group, 2))
    for _ in range(4):
        rclpy.spin_once(node, timeout_sec=0)
    assert fired == ['gc', 1, 0]


def test_future_api():
    from labkit.rclpy.task import Future
    f = Future()
    seen = []
    f.add_done_callback(lambda fut: seen.append(fut.result()))
    assert not f.done()
    f.set_result(3)
    assert seen == [3] and f.done() and not f.cancelled()
    f.add_done_callback(lambda fut: seen.append('late'))
    assert seen == [3, 'late']
    g = Future()
    g.cancel()
    assert g.cancelled()
    h = Future()
    h.set_exception(ValueError('x'))
    with pytest.raises(ValueError):
        h.result()
