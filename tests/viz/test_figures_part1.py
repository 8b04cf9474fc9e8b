"""Part 1 figures: drawn from real data, legible at the book's 720 px column."""
import re
import struct

import pytest

from labkit import interfaces
from labkit.viz import figures_part1 as fig


def _fonts(svg):
    return [float(x) for x in re.findall(r'font-size="([\d.]+)"', str(svg))]


def _check_legible(svg):
    s = str(svg)
    assert re.search(r'<svg[^>]* width="720"', s)
    assert 'viewBox="0 0 720 ' in s
    assert min(_fonts(s)) >= 10
    # every label starts inside the picture
    for x in re.findall(r'<text x="([\d.-]+)"', s):
        assert 0 <= float(x) <= 720


def test_field_spans_locate_each_field_in_the_cdr_bytes():
    Pose = interfaces.get_type("turtlesim/msg/Pose")
    msg = Pose(x=5.5, y=-1.25, theta=3.0, linear_velocity=0.5, angular_velocity=-2.0)
    data = interfaces.serialize(msg)
    spans = fig.field_spans(msg)
    assert [s[0] for s in spans] == list(msg.get_fields_and_field_types())
    for name, start, end in spans:
        assert end - start == 4
        assert struct.unpack("<f", data[start:end])[0] == pytest.approx(getattr(msg, name))
    assert spans[-1][2] == len(data)


def test_field_spans_with_padding_strings_and_nesting():
    Spawn = interfaces.get_type("turtlesim/srv/Spawn")
    req = Spawn.Request(x=1.0, y=2.0, theta=0.5, name="turtle7")
    data = interfaces.serialize(req)
    spans = dict((n, (s, e)) for n, s, e in fig.field_spans(req))
    s, e = spans["name"]
    assert struct.unpack("<I", data[s:s + 4])[0] == len("turtle7") + 1
    assert data[s + 4:e] == b"turtle7\x00"
    assert e == len(data)
    # a message whose int64 needs padding after a uint8, and a nested message
    GoalInfo = interfaces.get_type("action_msgs/msg/GoalStatus")
    status = GoalInfo(status=4)
    status.goal_info.stamp.sec = 7
    data = interfaces.serialize(status)
    last = fig.field_spans(status)[-1]
    assert last[0] == "status" and data[last[1]] == 4 and last[2] == len(data)


def test_message_on_the_wire_shows_the_file_the_class_and_every_byte():
    Pose = interfaces.get_type("turtlesim/msg/Pose")
    msg = Pose(x=5.544445, y=5.544445)
    svg = fig.message_on_the_wire(msg)
    _check_legible(svg)
    s = str(svg)
    data = interfaces.serialize(msg)
    cells = re.findall(r'>([0-9a-f]{2})</text>', s)
    assert cells == [f"{b:02x}" for b in data]
    assert "float32 linear_velocity" in s and "class Pose:" in s
    assert "共 24 字节" in s


def test_name_expansion_uses_rcl_rules_and_remapping():
    svg = fig.name_expansion("capture_image", "facer", ["image", "~/status", "/rosout"])
    _check_legible(svg)
    s = str(svg)
    assert "/facer/capture_image" in s
    assert ">/capture_image</text>" in s and ">/status</text>" in s and ">/rosout</text>" in s
    remapped = str(fig.name_expansion("capture_image", "/facer", ["image"],
                                      remaps=["__ns:=/robot1", "image:=camera/raw"]))
    assert "/robot1/capture_image" in remapped
    assert "/robot1/camera/raw" in remapped
    assert "/facer" not in remapped.split("</title>", 1)[1]


def test_workspace_overlays_stack_the_sourced_workspaces(tmp_path, monkeypatch):
    from labkit.ament import source

    def install(ws, names):
        inst = tmp_path / ws / "install"
        for n in names:
            marker = inst / n / "share" / "colcon-core" / "packages" / n
            marker.parent.mkdir(parents=True)
            marker.write_text("")
        return str(inst)

    first = install("base_ws", ["base_pkg"])
    second = install("ros2_ws", ["package_python", "my_robot"])
    monkeypatch.setattr(source, "sourced", lambda: [first, second])
    monkeypatch.setenv("AMENT_PREFIX_PATH", ":".join(
        [second + "/my_robot", second + "/package_python", first + "/base_pkg"]))
    svg = fig.workspace_overlays()
    _check_legible(svg)
    s = str(svg)
    assert s.index("my_robot, package_python") < s.index("base_pkg") < s.index("rclpy")
    assert s.index("overlay（叠加层）") < s.index("underlay（底层）")
    # every prefix of AMENT_PREFIX_PATH is printed whole, the underlay last
    from labkit.ament import index
    printed = "".join(re.findall(r">((?:AMENT_PREFIX_PATH=|  )[^<]*)<", s)).replace(" ", "")
    assert printed == "AMENT_PREFIX_PATH=" + ":".join(index.search_paths_shown()).replace(" ", "")
    assert printed.endswith("/opt/ros/humble")
