"""The tf2 core: chains, static + dynamic, interpolation, exceptions and their texts."""
import math

import pytest

from labkit.interfaces import get_type
from labkit.rclpy.duration import Duration
from labkit.rclpy.time import Time
from labkit.tf2.core import (BufferCore, ConnectivityException, ExtrapolationException,
                             InvalidArgumentException, LookupException, TransformException)
from labkit.tf2.transformations import euler_from_quaternion, quaternion_from_euler

TransformStamped = get_type("geometry_msgs/msg/TransformStamped")
EPOCH = 1704067200


def tf(parent, child, x=0.0, y=0.0, z=0.0, yaw=0.0, sec=EPOCH, nanosec=0):
    t = TransformStamped()
    t.header.frame_id = parent
    t.child_frame_id = child
    t.header.stamp.sec = sec
    t.header.stamp.nanosec = nanosec
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = x, y, z
    q = quaternion_from_euler(0.0, 0.0, yaw)
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = (float(v) for v in q)
    return t


def at(sec, nanosec=0):
    return Time(seconds=sec, nanoseconds=nanosec)


def xyz(t):
    tr = t.transform.translation
    return (tr.x, tr.y, tr.z)


def yaw(t):
    r = t.transform.rotation
    return euler_from_quaternion([r.x, r.y, r.z, r.w])[2]


def test_chain_composes_rotation_then_translation():
    b = BufferCore()
    b.set_transform(tf("world", "base", x=1.0, yaw=math.pi / 2), "test")
    b.set_transform(tf("base", "arm", x=2.0), "test")
    t = b.lookup_transform_core("world", "arm", Time())
    assert xyz(t) == pytest.approx((1.0, 2.0, 0.0))
    assert yaw(t) == pytest.approx(math.pi / 2)
    assert t.header.frame_id == "world" and t.child_frame_id == "arm"
    assert (t.header.stamp.sec, t.header.stamp.nanosec) == (EPOCH, 0)
    back = b.lookup_transform_core("arm", "world", Time())
    assert xyz(back) == pytest.approx((-2.0, 1.0, 0.0))
    assert yaw(back) == pytest.approx(-math.pi / 2)


def test_sibling_branches_meet_at_common_parent():
    b = BufferCore()
    b.set_transform(tf("world", "turtle1", x=5.0, y=5.0), "a")
    b.set_transform(tf("world", "turtle2", x=4.0, y=2.0), "a")
    t = b.lookup_transform_core("turtle2", "turtle1", Time())
    assert xyz(t) == pytest.approx((1.0, 3.0, 0.0))


def test_static_and_dynamic_latest_common_time():
    b = BufferCore()
    b.set_transform_static(tf("world", "map", x=1.0, sec=0), "static")
    b.set_transform(tf("map", "robot", x=1.0, sec=EPOCH), "dyn")
    b.set_transform(tf("map", "robot", x=2.0, sec=EPOCH + 1), "dyn")
    t = b.lookup_transform_core("world", "robot", Time())
    assert xyz(t) == pytest.approx((3.0, 0.0, 0.0))
    assert t.header.stamp.sec == EPOCH + 1
    # static links are valid at every time
    assert xyz(b.lookup_transform_core("world", "map", at(EPOCH + 77))) == pytest.approx(
        (1.0, 0.0, 0.0))
    # a static-only lookup for the latest is stamped 0
    assert b.lookup_transform_core("world", "map", Time()).header.stamp.sec == 0


def test_interpolation_lerps_translation_and_slerps_rotation():
    b = BufferCore()
    b.set_transform(tf("world", "r", x=0.0, yaw=0.0, sec=EPOCH), "a")
    b.set_transform(tf("world", "r", x=10.0, yaw=math.pi / 2, sec=EPOCH + 1), "a")
    t = b.lookup_transform_core("world", "r", at(EPOCH, 250_000_000))
    assert xyz(t) == pytest.approx((2.5, 0.0, 0.0))
    assert yaw(t) == pytest.approx(math.pi / 8)
    r = t.transform.rotation
    assert r.x ** 2 + r.y ** 2 + r.z ** 2 + r.w ** 2 == pytest.approx(1.0)
    assert (t.header.stamp.sec, t.header.stamp.nanosec) == (EPOCH, 250_000_000)


def test_builtin_time_message_is_accepted_and_bad_time_refused():
    b = BufferCore()
    b.set_transform(tf("world", "r", x=1.0), "a")
    stamp = get_type("builtin_interfaces/msg/Time")(sec=EPOCH)
    assert xyz(b.lookup_transform_core("world", "r", stamp)) == pytest.approx((1, 0, 0))
    with pytest.raises(TypeError, match="time must have sec and nanosec, or nanoseconds."):
        b.lookup_transform_core("world", "r", 3.0)


def test_lookup_exception_texts():
    b = BufferCore()
    b.set_transform(tf("world", "turtle1"), "a")
    with pytest.raises(LookupException) as info:
        b.lookup_transform_core("turtle2", "turtle1", Time())
    assert str(info.value) == ('"turtle2" passed to lookupTransform argument target_frame '
                               'does not exist. ')
    with pytest.raises(LookupException) as info:
        b.lookup_transform_core("world", "nope", Time())
    assert "lookupTransform argument source_frame does not exist" in str(info.value)
    assert isinstance(info.value, TransformException)
    assert type(info.value).__module__ == "tf2"


def test_invalid_argument_texts():
    b = BufferCore()
    b.set_transform(tf("world", "a"), "x")
    with pytest.raises(InvalidArgumentException) as info:
        b.lookup_transform_core("/world", "a", Time())
    assert str(info.value) == ('Invalid argument "/world" passed to lookupTransform argument '
                               "target_frame - in tf2 frame_ids cannot start with a '/'")
    with pytest.raises(InvalidArgumentException, match="cannot be empty"):
        b.lookup_transform_core("world", "", Time())


def test_connectivity_exception_text():
    b = BufferCore()
    b.set_transform(tf("world", "a"), "x")
    b.set_transform(tf("map", "b"), "x")
    with pytest.raises(ConnectivityException) as info:
        b.lookup_transform_core("a", "b", Time())
    assert str(info.value) == ("Could not find a connection between 'a' and 'b' because they "
                               "are not part of the same tree.Tf has two or more unconnected "
                               "trees.")
    ok, msg = b.can_transform_core("a", "b", Time())
    assert not ok and msg.startswith("Could not find a connection")


def test_extrapolation_texts():
    b = BufferCore()
    b.set_transform(tf("world", "r", sec=EPOCH), "a")
    b.set_transform(tf("world", "r", x=1.0, sec=EPOCH + 1), "a")
    with pytest.raises(ExtrapolationException) as info:
        b.lookup_transform_core("world", "r", at(EPOCH + 2))
    assert str(info.value) == (
        "Lookup would require extrapolation into the future.  Requested time 1704067202.000000 "
        "but the latest data is at time 1704067201.000000, when looking up transform from "
        "frame [r] to frame [world]")
    with pytest.raises(ExtrapolationException) as info:
        b.lookup_transform_core("world", "r", at(EPOCH - 1))
    assert str(info.value).startswith(
        "Lookup would require extrapolation into the past.  Requested time 1704067199.000000 "
        "but the earliest data is at time 1704067200.000000")
    one = BufferCore()
    one.set_transform(tf("world", "r", sec=EPOCH), "a")
    with pytest.raises(ExtrapolationException) as info:
        one.lookup_transform_core("world", "r", at(EPOCH + 1))
    assert str(info.value).startswith(
        "Lookup would require extrapolation at time 1704067201.000000, but only time "
        "1704067200.000000 is in the buffer")


def test_can_transform_messages():
    b = BufferCore()
    b.set_transform(tf("world", "turtle1"), "a")
    assert b.can_transform_core("world", "turtle1", Time()) == (True, "")
    ok, msg = b.can_transform_core("turtle1", "turtle2", Time())
    assert not ok
    assert msg == ('Invalid frame ID "turtle2" passed to canTransform argument source_frame - '
                   'frame does not exist')
    # the same frame always works, even unknown
    assert b.can_transform_core("ghost", "ghost", Time())[0]


def test_cache_time_prunes_old_data():
    b = BufferCore(Duration(seconds=2))
    for i in range(6):
        b.set_transform(tf("world", "r", x=float(i), sec=EPOCH + i), "a")
    with pytest.raises(ExtrapolationException, match="into the past"):
        b.lookup_transform_core("world", "r", at(EPOCH))
    assert xyz(b.lookup_transform_core("world", "r", at(EPOCH + 4))) == pytest.approx((4, 0, 0))


def test_rejected_inputs_are_reported(capsys):
    b = BufferCore()
    assert b.set_transform(tf("a", "a"), "me") is False
    bad = tf("world", "r")
    bad.transform.rotation.w = 2.0
    assert b.set_transform(bad, "me") is False
    err = capsys.readouterr().err
    assert 'TF_SELF_TRANSFORM: Ignoring transform from authority "me"' in err
    assert "TF_DENORMALIZED_QUATERNION" in err
    assert not b._frameExists("r")


def test_time_travel_with_fixed_frame():
    b = BufferCore()
    b.set_transform(tf("world", "turtle1", x=0.0, sec=EPOCH), "a")
    b.set_transform(tf("world", "turtle1", x=5.0, sec=EPOCH + 5), "a")
    b.set_transform(tf("world", "turtle2", x=1.0, sec=EPOCH), "a")
    b.set_transform(tf("world", "turtle2", x=1.0, sec=EPOCH + 5), "a")
    # where turtle1 was 5 s ago, seen from turtle2 now
    t = b.lookup_transform_full_core("turtle2", at(EPOCH + 5), "turtle1", at(EPOCH), "world")
    assert xyz(t) == pytest.approx((-1.0, 0.0, 0.0))
    ok, _ = b.can_transform_full_core("turtle2", at(EPOCH + 5), "turtle1", at(EPOCH), "world")
    assert ok


def test_frames_yaml_and_string():
    b = BufferCore()
    b.set_transform_static(tf("world", "map", sec=0), "static_pub")
    b.set_transform(tf("map", "r", sec=EPOCH), "dyn")
    b.set_transform(tf("map", "r", sec=EPOCH + 1), "dyn")
    text = b.all_frames_as_string()
    assert "Frame map exists with parent world.\n" in text
    assert "Frame r exists with parent map.\n" in text
    yaml_text = b.all_frames_as_yaml()
    assert "map: \n  parent: 'world'\n  broadcaster: 'static_pub'\n  rate: 10000.000\n" in yaml_text
    assert "  most_recent_transform: 1704067201.000000\n" in yaml_text
    assert "r: \n  parent: 'map'\n  broadcaster: 'dyn'\n  rate: 2.000\n" in yaml_text
    assert BufferCore().all_frames_as_yaml() == "[]"


def test_long_chain_matches_matrix_product():
    import numpy as np
    from labkit.tf2.tree import matrix
    rng = np.random.default_rng(7)
    b = BufferCore()
    product = np.identity(4)
    prefixes = [product]
    for i in range(10):
        x, y, z = rng.uniform(-2, 2, 3)
        q = quaternion_from_euler(*rng.uniform(-3, 3, 3))
        t = tf("f%d" % i, "f%d" % (i + 1), x, y, z)
        r = t.transform.rotation
        r.x, r.y, r.z, r.w = (float(v) for v in q)
        b.set_transform(t, "a")
        product = product @ matrix((x, y, z), q)
        prefixes.append(product)
    got = b.lookup_transform_core("f0", "f10", Time())
    tr, ro = got.transform.translation, got.transform.rotation
    m = matrix((tr.x, tr.y, tr.z), (ro.x, ro.y, ro.z, ro.w))
    assert np.allclose(m, product)
    back = b.lookup_transform_core("f10", "f3", Time())
    tr, ro = back.transform.translation, back.transform.rotation
    m = matrix((tr.x, tr.y, tr.z), (ro.x, ro.y, ro.z, ro.w))
    expected = np.linalg.inv(product) @ prefixes[3]
    assert np.allclose(m, expected)

