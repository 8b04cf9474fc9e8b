"""Live mode: real threads, real (short) waits."""
import labkit
from labkit import process
from test_process import talker_main


def test_live_smoke(live, msgs):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    assert labkit.time_mode() == 'live'
    proc = process.start(main=talker_main, name='talker')
    rclpy.init()
    node = Node('listener')
    got = []
    node.create_subscription(msgs.String, 'chatter', lambda m: got.append(m.data), 10)
    end = live.steady_ns() + 1_300_000_000
    while live.steady_ns() < end and len(got) < 2:
        rclpy.spin_once(node, timeout_sec=0.1)
    assert got[:2] == ['Hello World: 0', 'Hello World: 1']
    assert node.get_clock().now().nanoseconds > 1_700_000_000 * 10**9
    proc.stop()
    assert proc.returncode == 0
    assert node.get_node_names() == ['listener']


def test_live_service_and_timer(live, msgs):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init()
    node = Node('n')
    ticks = []
    node.create_timer(0.05, lambda: ticks.append(1))

    def add(req, resp):
        resp.sum = req.a + req.b
        return resp
    node.create_service(msgs.AddTwoInts, 'add', add)
    future = node.create_client(msgs.AddTwoInts, 'add').call_async(
        msgs.AddTwoInts.Request(a=1, b=1))
    rclpy.spin_until_future_complete(node, future, timeout_sec=2.0)
    assert future.result().sum == 2
    rclpy.spin_until_future_complete(node, rclpy.Future(), timeout_sec=0.3)
    assert 3 <= len(ticks) <= 8


def test_live_multithreaded_nested_call(live, msgs):
    import threading
    import labkit.rclpy as rclpy
    from labkit.rclpy.callback_groups import ReentrantCallbackGroup
    from labkit.rclpy.executors import MultiThreadedExecutor
    from labkit.rclpy.node import Node
    rclpy.init()
    node = Node('relay')
    group = ReentrantCallbackGroup()

    def add(req, resp):
        resp.sum = req.a + req.b
        return resp
    node.create_service(msgs.AddTwoInts, 'inner', add, callback_group=group)
    inner = node.create_client(msgs.AddTwoInts, 'inner', callback_group=group)

    def outer(req, resp):
        resp.sum = inner.call(req).sum + 100
        return resp
    node.create_service(msgs.AddTwoInts, 'outer', outer, callback_group=group)
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(node)
    spinner = threading.Thread(target=executor.spin, daemon=True)
    spinner.start()
    caller = Node('caller')
    future = caller.create_client(msgs.AddTwoInts, 'outer').call_async(
        msgs.AddTwoInts.Request(a=1, b=2))
    rclpy.spin_until_future_complete(caller, future, timeout_sec=3.0)
    assert future.result().sum == 103
    rclpy.shutdown()
    spinner.join(2.0)
    assert not spinner.is_alive()


def test_live_stop_interrupts_a_spinning_process(live):
    proc = process.start(main=talker_main, name='talker')
    labkit.sleep(0.2)
    proc.stop()
    assert proc.returncode == 0 and not proc.running
