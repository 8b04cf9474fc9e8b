"""Conformance: executors, futures and tasks, coroutine callbacks, guard conditions,
exceptions raised in callbacks, and the init/shutdown life cycle.

Plain rclpy: runs unchanged on ROS 2 Humble.
Humble/Jazzy: NotInitializedException's text (Humble: a tuple text
"('rclpy.init() has not been called', 'cannot create node')"); the expected file keeps
Humble's.
"""
import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.context import Context
from rclpy.exceptions import NotInitializedException
from rclpy.executors import SingleThreadedExecutor
from rclpy.task import Future
from std_srvs.srv import Trigger


def attempt(label, fn):
    try:
        value = fn()
        print(f'{label}: ok {value!r}')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print(f'{label}: {type(e).__name__}: {e}')


def main():
    # Futures without an executor
    future = Future()
    calls = []
    future.add_done_callback(lambda f: calls.append(('early', f.result())))
    print('future done:', future.done(), 'result:', future.result(), 'cancelled:',
          future.cancelled())
    future.set_result(42)
    future.add_done_callback(lambda f: calls.append(('late', f.result())))
    print('future done:', future.done(), 'result:', future.result(), 'callbacks:', calls)
    failed = Future()
    failed.set_exception(ValueError('boom'))
    print('exception:', repr(failed.exception()), failed.done())
    attempt('result() of failed future', failed.result)
    cancelled = Future()
    cancelled.cancel()
    print('cancelled:', cancelled.cancelled(), cancelled.done())

    print('ok before init:', rclpy.ok())
    attempt('create_node before init', lambda: rclpy.create_node('early'))
    rclpy.init(args=[])
    print('ok after init:', rclpy.ok())
    attempt('init twice', lambda: rclpy.init(args=[]))

    node = rclpy.create_node('exec_node')
    executor = SingleThreadedExecutor()
    print('add_node:', executor.add_node(node), 'again:', executor.add_node(node))
    print('nodes:', [n.get_name() for n in executor.get_nodes()],
          'node.executor is executor:', node.executor is executor)
    print('spin_once with nothing to do returns:', executor.spin_once(timeout_sec=0.0))

    # a task made of a coroutine
    async def add(a, b):
        return a + b

    task = executor.create_task(add, 2, 3)
    print('task done before spin:', task.done())
    executor.spin_until_future_complete(task, timeout_sec=1.0)
    print('task result:', task.result())

    # spin_until_future_complete gives up after its timeout
    never = Future()
    executor.spin_until_future_complete(never, timeout_sec=0.2)
    print('never done after timeout:', never.done())

    # a coroutine service callback that awaits another service
    node.create_service(Trigger, 'inner', lambda req, resp: Trigger.Response(
        success=True, message='inner ok'))
    inner = node.create_client(Trigger, 'inner')

    async def outer_callback(request, response):
        result = await inner.call_async(Trigger.Request())
        response.success = result.success
        response.message = 'outer saw: ' + result.message
        return response

    node.create_service(Trigger, 'outer', outer_callback,
                        callback_group=ReentrantCallbackGroup())
    outer = node.create_client(Trigger, 'outer')
    outer.wait_for_service(timeout_sec=5.0)
    inner.wait_for_service(timeout_sec=5.0)
    future = outer.call_async(Trigger.Request())
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    print('coroutine service:', future.result())

    # a coroutine timer callback; a mutually exclusive group stays busy until the
    # coroutine ends, so the client it awaits must be in another group
    ticks = []
    helper_group = MutuallyExclusiveCallbackGroup()
    node.create_service(Trigger, 'helper', lambda req, resp: Trigger.Response(
        success=True, message='helper ok'), callback_group=helper_group)
    helper = node.create_client(Trigger, 'helper', callback_group=helper_group)
    helper.wait_for_service(timeout_sec=5.0)

    async def timer_callback():
        result = await helper.call_async(Trigger.Request())
        ticks.append(result.message)

    timer = node.create_timer(0.05, timer_callback)
    for _ in range(100):
        if ticks:
            break
        executor.spin_once(timeout_sec=0.1)
    timer.cancel()
    print('coroutine timer:', ticks[:1])

    # guard conditions wake the executor and run their callback
    fired = []
    guard = node.create_guard_condition(lambda: fired.append('guard'))
    guard.trigger()
    for _ in range(20):
        if fired:
            break
        executor.spin_once(timeout_sec=0.1)
    print('guard condition:', fired)

    # an exception raised in a callback comes out of spin_once
    def bad_callback():
        raise RuntimeError('callback failed')

    bad = node.create_timer(0.01, bad_callback)
    try:
        for _ in range(20):
            executor.spin_once(timeout_sec=0.1)
        print('raising callback: nothing raised')
    except RuntimeError as e:
        print('raising callback: spin_once raised', type(e).__name__, e)
    node.destroy_timer(bad)

    executor.remove_node(node)
    print('nodes after remove:', executor.get_nodes())
    print('rclpy.spin_once(node):', rclpy.spin_once(node, timeout_sec=0.0))

    node.destroy_node()
    rclpy.shutdown()
    print('ok after shutdown:', rclpy.ok())
    attempt('shutdown twice', rclpy.shutdown)
    print('try_shutdown:', rclpy.try_shutdown())
    attempt('create_node after shutdown', lambda: rclpy.create_node('late'))
    # a context of one's own, with an on_shutdown callback
    context = Context()
    shutdown_calls = []
    context.init(args=[])
    context.on_shutdown(lambda: shutdown_calls.append('on_shutdown'))
    own = rclpy.create_node('own_context_node', context=context)
    print('own context ok:', context.ok(), rclpy.ok(), rclpy.ok(context=context))
    own.destroy_node()
    context.shutdown()
    print('own context after shutdown:', context.ok(), shutdown_calls)
    print('NotInitializedException is Exception:', issubclass(NotInitializedException,
                                                             Exception))
    print('done')


if __name__ == '__main__':
    main()
