import pytest


def test_init_twice_and_shutdown_twice(virtual):
    import labkit.rclpy as rclpy
    from labkit.rclpy.exceptions import RCLError
    rclpy.init()
    with pytest.raises(RuntimeError) as exc:
        rclpy.init()
    assert str(exc.value) == 'Context.init() must only be called once'
    ctx = rclpy.get_default_context()
    calls = []
    ctx.on_shutdown(lambda: calls.append('bye'))
    rclpy.shutdown()
    assert calls == ['bye'] and not rclpy.ok()
    with pytest.raises(RCLError) as exc:
        ctx.shutdown()
    assert 'rcl_shutdown already called' in str(exc.value)
    rclpy.try_shutdown()      # harmless
    rclpy.init()              # a fresh default context after shutdown
    assert rclpy.ok()
    rclpy.shutdown()


def test_node_before_init(virtual):
    from labkit.rclpy.exceptions import NotInitializedException
    from labkit.rclpy.node import Node
    with pytest.raises(NotInitializedException) as exc:
        Node('n')
    assert str(exc.value) == "('rclpy.init() has not been called', 'cannot create node')"


def test_context_errors(virtual):
    from labkit.rclpy.context import Context
    ctx = Context()
    assert not ctx.ok()
    with pytest.raises(RuntimeError) as exc:
        ctx.shutdown()
    assert str(exc.value) == 'Context must be initialized before it can be shutdown'
    with pytest.raises(RuntimeError):
        ctx.init(domain_id=-1)
    ctx.init([], domain_id=3)
    assert ctx.get_domain_id() == 3
    ctx.try_shutdown()
    assert not ctx.ok()


def test_create_node_and_destroy(rclpy, msgs):
    node = rclpy.create_node('made', namespace='/x')
    assert node.get_fully_qualified_name() == '/x/made'
    assert node.executor is None
    pub = node.create_publisher(msgs.String, 'a', 10)
    timer = node.create_timer(1.0, lambda: None)
    assert list(node.publishers)[-1] is pub and list(node.timers) == [timer]
    assert node.destroy_timer(timer) and list(node.timers) == []
    node.destroy_node()
    from labkit.rclpy.exceptions import InvalidHandle
    with pytest.raises(InvalidHandle):
        node.get_name()


def test_publish_after_shutdown(rclpy, msgs):
    from labkit.rclpy.exceptions import RCLError
    from labkit.rclpy.node import Node
    pub = Node('n').create_publisher(msgs.String, 'x', 10)
    rclpy.shutdown()
    with pytest.raises(RCLError) as exc:
        pub.publish(msgs.String())
    assert str(exc.value) == "Failed to publish: publisher's context is invalid"
