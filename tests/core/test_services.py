import pytest


def add(request, response):
    response.sum = request.a + request.b
    return response


def test_call_async_and_spin_until_complete(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    node.create_service(msgs.AddTwoInts, 'add_two_ints', add)
    client = node.create_client(msgs.AddTwoInts, 'add_two_ints')
    assert client.service_is_ready()
    assert client.wait_for_service(timeout_sec=1.0)
    future = client.call_async(msgs.AddTwoInts.Request(a=2, b=3))
    rclpy.spin_until_future_complete(node, future)
    assert future.done() and future.result().sum == 5
    # like Humble, the clean-up is a done-callback task the executor runs on later spins
    assert len(client._pending_requests) == 1
    rclpy.spin_once(node, timeout_sec=0)
    rclpy.spin_once(node, timeout_sec=0)
    assert client._pending_requests == {}


def test_wait_for_service_times_out_in_virtual_time(rclpy, msgs, virtual):
    from labkit.rclpy.node import Node
    node = Node('n')
    client = node.create_client(msgs.AddTwoInts, 'missing')
    t0 = virtual.steady_ns()
    assert client.wait_for_service(timeout_sec=1.0) is False
    assert virtual.steady_ns() - t0 == 1_000_000_000
    with pytest.raises(TypeError):
        client.call_async(msgs.AddTwoInts.Response())


def test_request_without_server_never_completes(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    client = node.create_client(msgs.AddTwoInts, 'missing')
    future = client.call_async(msgs.AddTwoInts.Request())
    rclpy.spin_until_future_complete(node, future, timeout_sec=0.5)
    assert not future.done()
    client.remove_pending_request(future)
    assert client._pending_requests == {}


def test_sync_call_from_main_while_process_serves(virtual, msgs):
    import labkit.rclpy as rclpy
    from labkit import process
    from labkit.rclpy.node import Node

    def server(args=None):
        rclpy.init(args=args)
        node = Node('server')
        node.create_service(msgs.AddTwoInts, 'add', add)
        rclpy.spin(node)

    process.start(main=server, name='server')
    rclpy.init()
    node = Node('client')
    client = node.create_client(msgs.AddTwoInts, 'add')
    assert client.wait_for_service(timeout_sec=0)
    future = client.call_async(msgs.AddTwoInts.Request(a=40, b=2))
    rclpy.spin_until_future_complete(node, future)
    assert future.result().sum == 42
    # the classic pattern: spin in a plain thread, call synchronously from the main one
    import threading
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    assert client.call(msgs.AddTwoInts.Request(a=1, b=2)).sum == 3
    rclpy.shutdown()


def test_sync_call_without_spinner_is_a_deadlock_not_a_hang(rclpy, msgs, virtual):
    from labkit.rclpy.node import Node
    node = Node('n')
    node.create_service(msgs.AddTwoInts, 'add', add)
    client = node.create_client(msgs.AddTwoInts, 'add')
    with pytest.raises(virtual.Deadlock):
        client.call(msgs.AddTwoInts.Request(a=1, b=1))


def test_service_request_header(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    seen = []

    def cb(request, response):
        seen.append(request.a)
        return add(request, response)
    node.create_service(msgs.AddTwoInts, 'add', cb)
    client = node.create_client(msgs.AddTwoInts, 'add')
    futures = [client.call_async(msgs.AddTwoInts.Request(a=i, b=1)) for i in range(3)]
    for f in futures:
        rclpy.spin_until_future_complete(node, f)
    assert seen == [0, 1, 2]
    assert [f.result().sum for f in futures] == [1, 2, 3]
