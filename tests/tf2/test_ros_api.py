"""tf2_ros on the graph: broadcasters, listener, timeouts, buffer.transform (virtual time)."""
import math

import pytest

import labkit
import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.duration import Duration
from labkit.rclpy.time import Time
from labkit.tf2 import ros as tf2_ros
from labkit.tf2.transformations import quaternion_from_euler

TransformStamped = get_type("geometry_msgs/msg/TransformStamped")
PointStamped = get_type("geometry_msgs/msg/PointStamped")
PoseStamped = get_type("geometry_msgs/msg/PoseStamped")
Vector3Stamped = get_type("geometry_msgs/msg/Vector3Stamped")


def tf(node, parent, child, x=0.0, y=0.0, yaw=0.0):
    t = TransformStamped()
    t.header.stamp = node.get_clock().now().to_msg()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x = x
    t.transform.translation.y = y
    q = quaternion_from_euler(0.0, 0.0, yaw)
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = (float(v) for v in q)
    return t


@pytest.fixture
def node():
    rclpy.init()
    n = rclpy.create_node("tf_test")
    yield n
    n.destroy_node()
    rclpy.try_shutdown()


def spin_for(node, seconds):
    clock = node.get_clock()
    end = clock.now().nanoseconds + int(seconds * 1e9)
    while clock.now().nanoseconds < end:
        rclpy.spin_once(node, timeout_sec=(end - clock.now().nanoseconds) / 1e9)


def test_static_broadcaster_is_latched_for_late_listeners(node):
    static = tf2_ros.StaticTransformBroadcaster(node)
    static.sendTransform([tf(node, "world", "map", x=1.0), tf(node, "map", "odom", y=2.0)])
    assert static.pub_tf.topic_name == "/tf_static"
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer, node)      # subscribes after the publish
    spin_for(node, 0.1)
    t = buffer.lookup_transform("world", "odom", Time())
    assert (t.transform.translation.x, t.transform.translation.y) == pytest.approx((1.0, 2.0))


def test_listener_follows_tf_and_interpolates(node):
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer, node)
    br = tf2_ros.TransformBroadcaster(node)
    br.sendTransform(tf(node, "world", "robot", x=0.0))
    spin_for(node, 1.0)
    br.sendTransform(tf(node, "world", "robot", x=1.0))
    spin_for(node, 0.1)
    mid = Time(nanoseconds=node.get_clock().now().nanoseconds - int(0.6e9))
    t = buffer.lookup_transform("world", "robot", mid)
    assert t.transform.translation.x == pytest.approx(0.5)
    assert buffer.can_transform("world", "robot", Time())
    assert not buffer.can_transform("world", "nobody", Time())


def test_lookup_with_timeout_waits_for_a_spin_thread():
    rclpy.init()
    listener_node = rclpy.create_node("listener")
    talker = rclpy.create_node("talker")
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer, listener_node, spin_thread=True)
    br = tf2_ros.TransformBroadcaster(talker)
    talker.create_timer(0.5, lambda: br.sendTransform(tf(talker, "world", "late", x=3.0)))
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(talker)
    import threading
    threading.Thread(target=executor.spin, daemon=True).start()
    start = talker.get_clock().now()
    with pytest.raises(tf2_ros.LookupException):
        buffer.lookup_transform("world", "late", Time())
    t = buffer.lookup_transform("world", "late", Time(), timeout=Duration(seconds=2.0))
    assert t.transform.translation.x == pytest.approx(3.0)
    waited = (talker.get_clock().now() - start).nanoseconds / 1e9
    assert 0.4 < waited < 1.5
    # a frame that never comes: the timeout passes, then tf2's exception
    with pytest.raises(tf2_ros.LookupException):
        buffer.lookup_transform("world", "never", Time(), timeout=Duration(seconds=1.0))
    executor.shutdown()
    rclpy.try_shutdown()


def test_wait_for_transform_async_future(node):
    buffer = tf2_ros.Buffer()
    fut = buffer.wait_for_transform_async("world", "x", Time())
    assert not fut.done()
    buffer.set_transform(tf(node, "world", "x", x=1.0), "me")
    assert fut.done() and fut.result() is True


def test_buffer_transform_geometry_types(node):
    import labkit.tf2.tf2_geometry_msgs as tgm
    buffer = tf2_ros.Buffer()
    buffer.set_transform(tf(node, "world", "base", x=1.0, yaw=math.pi / 2), "me")
    p = PointStamped()
    p.header.frame_id = "base"
    p.point.x = 1.0
    out = buffer.transform(p, "world")
    assert out.header.frame_id == "world"
    assert (out.point.x, out.point.y, out.point.z) == pytest.approx((1.0, 1.0, 0.0))
    v = Vector3Stamped()
    v.header.frame_id = "base"
    v.vector.x = 1.0
    vout = buffer.transform(v, "world")
    assert (vout.vector.x, vout.vector.y) == pytest.approx((0.0, 1.0))   # no translation
    pose = PoseStamped()
    pose.header.frame_id = "base"
    pose.pose.orientation.w = 1.0
    pout = buffer.transform(pose, "world")
    assert pout.pose.position.x == pytest.approx(1.0)
    assert pout.pose.orientation.z == pytest.approx(math.sin(math.pi / 4))
    t = buffer.lookup_transform("world", "base", Time())
    assert tgm.do_transform_pose(pose.pose, t).position.x == pytest.approx(1.0)


def test_buffer_transform_unknown_type_raises_type_exception(node):
    buffer = tf2_ros.Buffer()
    with pytest.raises(tf2_ros.TypeException, match="is not loaded or supported"):
        buffer.transform(TransformStamped(), "world")


def test_tf2_frames_service(node):
    buffer = tf2_ros.Buffer(node=node)
    buffer.set_transform(tf(node, "world", "a"), "me")
    FrameGraph = get_type("tf2_msgs/srv/FrameGraph")
    client = node.create_client(FrameGraph, "tf2_frames")
    assert client.wait_for_service(timeout_sec=1.0)
    fut = client.call_async(FrameGraph.Request())
    rclpy.spin_until_future_complete(node, fut, timeout_sec=1.0)
    assert "a: \n  parent: 'world'\n  broadcaster: 'me'" in fut.result().frame_yaml


def test_snapshot_gives_4x4_in_the_root(node):
    from labkit.tf2 import snapshot
    buffer = tf2_ros.Buffer()
    buffer.set_transform(tf(node, "world", "base", x=1.0, yaw=math.pi / 2), "me")
    buffer.set_transform(tf(node, "base", "arm", x=2.0), "me")
    snap = snapshot(buffer)
    assert set(snap) == {"world", "base", "arm"}
    assert snap["arm"][:3, 3] == pytest.approx([1.0, 2.0, 0.0])
    assert snap["arm"][:2, :2].ravel() == pytest.approx([0.0, -1.0, 1.0, 0.0])
    assert snapshot(buffer, "base")["world"][:3, 3] == pytest.approx([0.0, 1.0, 0.0])


def test_import_aliases_resolve():
    from labkit import compat, plugins
    plugins.register_all()
    was_active = compat.is_active()
    compat.activate()
    import importlib
    assert importlib.import_module("tf2_ros").Buffer is tf2_ros.Buffer
    assert importlib.import_module("tf2_ros.buffer").Buffer is tf2_ros.Buffer
    assert hasattr(importlib.import_module("tf2_geometry_msgs"), "do_transform_point")
    tft = importlib.import_module("tf_transformations")
    assert tft.quaternion_from_euler(0, 0, math.pi)[2] == pytest.approx(1.0)
    assert importlib.import_module("tf2_py").LookupException is tf2_ros.LookupException
    if not was_active:
        compat.deactivate()


def test_time_travel_keywords_as_in_the_tutorial(node):
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer, node)
    br = tf2_ros.TransformBroadcaster(node)
    for i in range(7):
        br.sendTransform([tf(node, "world", "turtle1", x=float(i)),
                          tf(node, "world", "turtle2", y=1.0)])
        spin_for(node, 1.0)
    now = node.get_clock().now()
    # the newest data is up to a second old: ask for the latest, and for 5 s before it
    latest = buffer.get_latest_common_time("world", "turtle1")
    when = latest - Duration(seconds=5.0)
    t = buffer.lookup_transform_full(target_frame="turtle2", target_time=latest,
                                     source_frame="turtle1", source_time=when,
                                     fixed_frame="world", timeout=Duration(seconds=0.05))
    assert (t.transform.translation.x, t.transform.translation.y) == pytest.approx((1.0, -1.0))
    with pytest.raises(tf2_ros.ExtrapolationException, match="extrapolation into the future"):
        buffer.lookup_transform("turtle2", "turtle1", now + Duration(seconds=1.0))
