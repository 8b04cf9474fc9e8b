"""static_transform_publisher, tf2_echo and view_frames as `ros2 run` processes (virtual time)."""
import math
import os

import pytest

import labkit
import labkit.rclpy as rclpy
from labkit import process
from labkit.rclpy.time import Time
from labkit.tf2 import ros as tf2_ros
from labkit.tf2.static_transform_publisher import ParseError, parse_args
from labkit.tf2.tf2_echo import format_transform


def run(*argv):
    return process.start(list(argv), echo=False)


def listen(seconds=0.2):
    rclpy.init()
    node = rclpy.create_node("checker")
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer, node)
    clock = node.get_clock()
    end = clock.now().nanoseconds + int(seconds * 1e9)
    while clock.now().nanoseconds < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    return node, buffer


def text(proc):
    return "\n".join(proc.output)


def test_new_style_flags_with_rpy():
    proc = run("tf2_ros", "static_transform_publisher", "--x", "1", "--y", "2", "--z", "3",
               "--yaw", str(math.pi / 2), "--frame-id", "world", "--child-frame-id", "cam")
    node, buffer = listen()
    t = buffer.lookup_transform("world", "cam", Time())
    assert (t.transform.translation.x, t.transform.translation.y,
            t.transform.translation.z) == (1.0, 2.0, 3.0)
    assert t.transform.rotation.z == pytest.approx(math.sqrt(0.5))
    out = text(proc)
    assert "Spinning until stopped - publishing transform\ntranslation: ('1.000000', " \
           "'2.000000', '3.000000')\nrotation: ('0.000000', '0.000000', '0.707107', " \
           "'0.707107')\nfrom 'world' to 'cam'" in out
    names = [n for n, _ in node.get_node_names_and_namespaces()]
    assert any(n.startswith("static_transform_publisher_") and len(n) == 43 for n in names)
    proc.stop()


def test_quaternion_flags():
    run("tf2_ros", "static_transform_publisher", "--qz", "1", "--qw", "0",
        "--frame-id", "a", "--child-frame-id", "b")
    _, buffer = listen()
    t = buffer.lookup_transform("a", "b", Time())
    assert (t.transform.rotation.z, t.transform.rotation.w) == (1.0, 0.0)


def test_old_style_positional_warns_and_works():
    proc = run("tf2_ros", "static_transform_publisher", "1", "0", "0", "0", "0", "0",
               "world", "laser")
    _, buffer = listen()
    assert buffer.lookup_transform("world", "laser", Time()).transform.translation.x == 1.0
    assert "[WARN]" in text(proc)
    assert ("[]: Old-style arguments are deprecated; see --help for new-style arguments"
            in text(proc))


def test_parse_errors_match_ros():
    def err(*args):
        with pytest.raises(ParseError) as info:
            parse_args(["static_transform_publisher"] + list(args))
        return str(info.value)
    assert err("--x", "abc", "--frame-id", "a", "--child-frame-id", "b") == \
        "Failed to parse --x argument as float"
    assert err("--qx", "1", "--roll", "1", "--frame-id", "a", "--child-frame-id", "b") == \
        "Cannot specify both quaternion and Euler rotations"
    assert err("--child-frame-id", "b") == "Frame id must not be empty"
    assert err("--frame-id", "a") == "Child frame id must not be empty"
    assert err("--frame-id") == "Not enough arguments for --frame-id"
    assert err("1", "2", "--frame-id", "a", "--child-frame-id", "b") == \
        "Extra unparsed arguments on command-line"
    assert parse_args(["p", "--x", "1.5abc", "--frame-id", "a", "--child-frame-id", "b"]
                      )["translation"][0] == 1.5       # std::stod reads the prefix


def test_bad_arguments_print_usage_and_exit_1():
    proc = run("tf2_ros", "static_transform_publisher", "--frame-id", "a")
    labkit.sleep(0.1)
    assert proc.returncode == 1
    out = text(proc)
    assert "[ERROR]" in out and "error parsing command line arguments: Child frame id must " \
                                "not be empty" in out
    assert "usage: static_transform_publisher [--x X]" in out


def test_same_frames_terminate():
    proc = run("tf2_ros", "static_transform_publisher", "--frame-id", "a",
               "--child-frame-id", "a")
    labkit.sleep(0.1)
    assert "cannot publish static transform from 'a' to 'a', exiting" in text(proc)
    assert "what():  child_frame_id cannot equal frame_id" in text(proc)
    assert proc.returncode != 0


def test_echo_block_format():
    from labkit.interfaces import get_type
    t = get_type("geometry_msgs/msg/TransformStamped")()
    t.header.stamp.sec = 1704067200
    t.transform.translation.x = 2.0
    t.transform.translation.y = -1.5
    t.transform.rotation.z = math.sin(math.pi / 4)
    t.transform.rotation.w = math.cos(math.pi / 4)
    assert format_transform(t) == (
        "At time 1704067200.0\n"
        "- Translation: [2.000, -1.500, 0.000]\n"
        "- Rotation: in Quaternion [0.000, 0.000, 0.707, 0.707]\n"
        "- Rotation: in RPY (radian) [0.000, -0.000, 1.571]\n"
        "- Rotation: in RPY (degree) [0.000, -0.000, 90.000]\n"
        "- Matrix:\n"
        "  0.000 -1.000  0.000  2.000\n"
        "  1.000  0.000  0.000 -1.500\n"
        "  0.000  0.000  1.000  0.000\n"
        "  0.000  0.000  0.000  1.000\n")
    t.header.stamp.nanosec = 50000000          # printed as an integer, not zero-padded
    assert format_transform(t).startswith("At time 1704067200.50000000\n")


def test_echo_process_waits_then_prints():
    echo = run("tf2_ros", "tf2_echo", "world", "cam")
    labkit.sleep(1.5)
    assert ("[tf2_echo]: Waiting for transform world ->  cam: Invalid frame ID \"world\" "
            "passed to canTransform argument target_frame - frame does not exist"
            in text(echo))
    run("tf2_ros", "static_transform_publisher", "--x", "1", "--frame-id", "world",
        "--child-frame-id", "cam")
    labkit.sleep(2.0)
    out = text(echo)
    assert "At time 0.0\n- Translation: [1.000, 0.000, 0.000]" in out
    assert "- Rotation: in RPY (degree) [0.000, -0.000, 0.000]" in out
    nodes = labkit.ros2("node list").stdout.split()
    assert "/tf2_echo" in nodes
    assert any(n.startswith("/transform_listener_impl_") for n in nodes)
    echo.stop()
    assert "/tf2_echo" not in labkit.ros2("node list").stdout.split()


def test_echo_usage():
    proc = run("tf2_ros", "tf2_echo", "world")
    labkit.sleep(0.1)
    assert proc.returncode == 1
    assert "Usage: tf2_echo source_frame target_frame [echo_rate]" in text(proc)
    bad = run("tf2_ros", "tf2_echo", "a", "b", "1.0foo")
    labkit.sleep(0.1)
    assert bad.returncode == 3


def test_view_frames_writes_gv_and_pdf(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    run("tf2_ros", "static_transform_publisher", "--x", "1", "--frame-id", "world",
        "--child-frame-id", "cam")
    proc = run("tf2_tools", "view_frames")
    labkit.sleep(6.0)
    assert proc.returncode == 0, text(proc)
    out = text(proc)
    assert "[view_frames]: Listening to tf data for 5.0 seconds..." in out
    assert "Generating graph in frames.pdf file..." in out
    files = sorted(os.listdir(tmp_path))
    assert files == ["frames_2024-01-01_00.00.05.gv", "frames_2024-01-01_00.00.05.pdf"] or \
        (len(files) == 2 and files[0].endswith(".gv") and files[1].endswith(".pdf"))
    gv = (tmp_path / files[0]).read_text()
    assert gv.startswith('digraph G {\n"world" -> "cam"[label=" Broadcaster: default_authority'
                         '\\nAverage rate: 10000.0\\n')
    assert 'label ="view_frames Result";' in gv
    assert (tmp_path / files[1]).read_bytes().startswith(b"%PDF")


def test_view_frames_svg_for_the_book():
    from labkit.interfaces import get_type
    from labkit.tf2.view_frames import svg
    b = tf2_ros.Buffer()
    t = get_type("geometry_msgs/msg/TransformStamped")()
    t.header.frame_id, t.child_frame_id = "world", "turtle1"
    t.transform.rotation.w = 1.0
    b.set_transform(t, "me")
    pic = svg(b)
    assert pic.lstrip().startswith("<?xml") and "</svg>" in pic
    assert "turtle1" in pic and pic._repr_svg_() == str(pic)
    assert "No tf data received" in svg(tf2_ros.Buffer())


def test_view_frames_svg_listens_when_given_nothing():
    from labkit.tf2.view_frames import svg
    run("tf2_ros", "static_transform_publisher", "--frame-id", "world", "--child-frame-id", "cam")
    pic = svg(wait_time=0.5)
    assert "cam" in pic and "world" in pic
    assert "view_frames" not in labkit.ros2("node list").stdout    # its node is gone again


def test_static_publisher_parameters_are_read_only_like_rclcpp():
    run("tf2_ros", "static_transform_publisher", "--x", "2", "--frame-id", "a",
        "--child-frame-id", "b")
    name = [n for n in labkit.ros2("node list").stdout.split()
            if n.startswith("/static_transform_publisher_")][0]
    params = labkit.ros2(f"param list {name}").stdout.split()
    assert {"translation.x", "rotation.w", "frame_id", "child_frame_id",
            "qos_overrides./tf_static.publisher.durability"} <= set(params)
    assert labkit.ros2(f"param get {name} translation.x").stdout.strip() == \
        "Double value is: 2.0"
    refused = labkit.ros2(f"param set {name} frame_id c")
    assert "parameter 'frame_id' cannot be set because it is read-only" in \
        refused.stdout + refused.stderr
