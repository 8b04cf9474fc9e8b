"""The meshcat viewer: self-contained snapshots that hold the geometry, animation,
following /tf live, and a live server on 127.0.0.1 only."""
import base64
import gzip
import html
import math
import os
import re
import struct
import subprocess
import urllib.request

import numpy as np
import pytest
import umsgpack

import labkit
from labkit import process, robots
from labkit.viz import meshcat_view

SHARE = robots.share_directory("facer_description")


def scene_commands(page):
    blobs = re.findall(r'unzip\("([A-Za-z0-9+/=]+)"\)', page)
    assert len(blobs) == 2                        # the viewer script, then the scene
    data = gzip.decompress(base64.b64decode(blobs[1]))
    out, i = [], 0
    while i < len(data):
        (n,) = struct.unpack_from("<I", data, i)
        out.append(umsgpack.unpackb(data[i + 4:i + 4 + n]))
        i += 4 + n
    return out


def objects(commands):
    return {c["path"]: c["object"] for c in commands if c["type"] == "set_object"}


def test_snapshot_holds_the_robot_geometry_and_colours():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "05-meshes.urdf"))
    page = view.html()
    objs = objects(scene_commands(page))
    body = objs["/meshcat/robot/base_link/visual_0"]
    chassis = body["geometries"][0]
    assert (chassis["type"], chassis["width"], chassis["height"], chassis["depth"]) == (
        "BoxGeometry", pytest.approx(0.3), pytest.approx(0.2), pytest.approx(0.08))
    assert body["materials"][0]["color"] == 0xF27F19                 # orange 0.95 0.5 0.1
    mast = objs["/meshcat/robot/mast_link/visual_0"]["geometries"][0]
    assert mast["type"] == "CylinderGeometry" and mast["height"] == pytest.approx(0.16)
    ball = objs["/meshcat/robot/caster_link/visual_0"]["geometries"][0]
    assert ball["type"] == "SphereGeometry" and ball["radius"] == pytest.approx(0.025)
    wheel = objs["/meshcat/robot/left_wheel/visual_0"]["geometries"][0]
    assert wheel["type"] == "_meshfile_geometry" and wheel["format"] == "dae"
    assert "<COLLADA" in wheel["data"]
    head = objs["/meshcat/robot/head_link/visual_0"]["geometries"][0]
    assert head["type"] == "_meshfile_geometry" and head["format"] == "stl"
    # every link has a named TF triad
    labels = [o["textures"][0]["text"] for p, o in objs.items() if p.endswith("/label")]
    assert sorted(labels) == sorted(view.model.links)


def test_iframe_is_self_contained_and_small():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "01-one-shape.urdf"))
    frame = view._repr_html_()
    assert frame.startswith('<iframe srcdoc="')
    srcdoc = frame[len('<iframe srcdoc="'):frame.index('" style=')]
    assert '"' not in srcdoc and "<script" not in srcdoc     # escaped for the attribute
    page = html.unescape(srcdoc)
    assert "http://" not in page.replace("http://www.w3.org", "") and "src=" not in page
    assert "MeshCat.Viewer" in page
    assert len(frame) < 400_000                                   # meshcat's page is ~0.9 MB
    assert view.iframe() == frame                                 # deterministic per scene


def test_link_transforms_follow_joint_positions():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "06-pan-joint.urdf"))
    view.set_joint_positions({"head_pan": math.pi / 2})
    cmds = {c["path"]: c for c in view.commands() if c["type"] == "set_transform"}
    m = np.array(cmds["/meshcat/robot/head_link"]["matrix"]).reshape(4, 4).T
    np.testing.assert_allclose(m, view.model.link_poses({"head_pan": math.pi / 2})["head_link"],
                               atol=1e-6)
    assert m[0, 1] == pytest.approx(-1.0)


def test_facer_drive_is_an_animation():
    from labkit.robots import facer
    view = facer.drive_view(seconds=4.0, fps=10)
    cmds = scene_commands(view.html())
    anim = [c for c in cmds if c["type"] == "set_animation"]
    assert len(anim) == 1
    clips = {a["path"]: a["clip"] for a in anim[0]["animations"]}
    assert "/meshcat/robot/head_link" in clips and "/meshcat/frames/odom" in clips
    keys = clips["/meshcat/robot/base_link"]["tracks"][0]["keys"]
    assert len(keys) == 40
    x, y, z = keys[-1]["value"]          # on the 0.6 m circle around (0, 0.6), 5 cm up
    assert math.hypot(x, y - 0.6) == pytest.approx(0.6, abs=1e-5) and z == pytest.approx(0.05)
    assert len(view.iframe()) < 600_000


def test_facer_motion_rolls_without_slipping():
    """The wheel angles are the arc each wheel rolls (inner one on R - track/2) / radius."""
    from labkit.robots import facer
    for t in (0.0, 1.0, 7.5):
        joints = facer.joints_at(t)
        arc = facer.SPEED * t                        # along the centre line
        inner = arc * (facer.RADIUS - facer.TRACK / 2) / facer.RADIUS
        outer = arc * (facer.RADIUS + facer.TRACK / 2) / facer.RADIUS
        assert joints["left_wheel_joint"] * facer.WHEEL_RADIUS == pytest.approx(inner)
        assert joints["right_wheel_joint"] * facer.WHEEL_RADIUS == pytest.approx(outer)
        assert -1.5708 <= joints["head_pan"] <= 1.5708 and 0 <= joints["mast_lift"] <= 0.08
    # the heading is the circle's tangent; turning left (yaw grows), the left wheel is inside
    (x0, y0, _), _ = facer.base_at(1.0)
    (x1, y1, _), yaw = facer.base_at(1.001)
    assert math.atan2(y1 - y0, x1 - x0) == pytest.approx(yaw, abs=1e-3) and yaw > 0


def test_view_follows_tf_from_robot_state_publisher():
    from labkit.interfaces import get_type
    from labkit.robots import facer
    import labkit.rclpy as rclpy
    view = meshcat_view.RobotView(facer.model_path())
    view.follow()
    with open(facer.model_path()) as handle:
        facer.start_robot_state_publisher(handle.read(), echo=False)
    JointState = get_type("sensor_msgs/msg/JointState")
    rclpy.init()
    node = rclpy.create_node("feeder")
    pub = node.create_publisher(JointState, "joint_states", 10)
    labkit.sleep(0.1)
    msg = JointState(name=["head_pan", "mast_lift"], position=[math.pi / 2, 0.05])
    msg.header.stamp = node.get_clock().now().to_msg()
    pub.publish(msg)
    labkit.sleep(0.3)
    poses = view.tf_poses()
    assert {"base_link", "head_link", "camera_link", "caster_link"} <= set(poses)
    np.testing.assert_allclose(poses["camera_link"][:3, 3],
                               (-0.08, 0.05, 0.07 + 0.05 + 0.16 + 0.035), atol=1e-9)
    view.stop()
    assert all(p.name != "labkit_meshcat_view" or p.returncode is not None
               for p in process.processes())


def test_live_server_binds_loopback_only():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "01-one-shape.urdf"))
    url = view.serve()
    try:
        port = int(url.rsplit(":", 1)[1])
        listening = subprocess.run(["ss", "-Hltn"], capture_output=True, text=True).stdout
        sockets = [line.split()[3] for line in listening.splitlines()
                   if line.split()[3].endswith(f":{port}")]
        assert sockets == [f"127.0.0.1:{port}"]
        with urllib.request.urlopen(url + "/") as reply:
            assert b"MeshCat.Viewer" in reply.read()
        view.set_joint_positions({})
        with urllib.request.urlopen(url + "/updates?since=0") as reply:
            seq = int(reply.headers["X-Seq"])
            assert reply.headers["Access-Control-Allow-Origin"] is None   # no other page reads it
            assert len(reply.read()) > 0 and seq > 0
        with urllib.request.urlopen(url + f"/updates?since={seq}") as reply:
            assert reply.read() == b""
    finally:
        view.stop()
    listening = subprocess.run(["ss", "-Hltn"], capture_output=True, text=True).stdout
    assert f":{port} " not in listening


def test_display_starts_the_facer_description_graph():
    procs = robots.display("urdf/06-pan-joint.urdf", gui=False, echo=False)
    labkit.sleep(0.3)
    nodes = labkit.ros2("node list").stdout.split()
    assert nodes == ["/joint_state_publisher", "/robot_state_publisher", "/rviz2"]
    view = meshcat_view.current()
    assert view.model is not None and view.model.name == "facer"
    assert {"base_link", "head_link", "right_wheel", "camera_link"} <= set(view.tf_poses())
    assert len(procs) == 3


def test_display_launch_file_takes_models_inside_the_package():
    """`ros2 launch facer_description display.launch.py model:=urdf/...` from any folder."""
    out = labkit.ros2("launch facer_description display.launch.py --show-args").stdout
    assert "'model':" in out and "(default: 'urdf/01-one-shape.urdf')" in out
    job = labkit.ros2("launch facer_description display.launch.py "
                      "model:=urdf/08-macros.urdf.xacro gui:=false")
    labkit.sleep(0.5)
    nodes = labkit.ros2("node list").stdout.split()
    assert nodes == ["/joint_state_publisher", "/robot_state_publisher", "/rviz2"]
    text = labkit.ros2("param get /robot_state_publisher robot_description").stdout
    assert "autogenerated by xacro" in text and 'name="left_wheel_joint"' in text
    job.stop()


def test_quaternions_match_scipy():
    from scipy.spatial.transform import Rotation
    from labkit.robots.urdf import quaternion_from_matrix
    for r in Rotation.random(50, random_state=3):
        q = np.array(quaternion_from_matrix(r.as_matrix()))
        ref = r.as_quat()
        ref = ref if ref[3] >= 0 else -ref
        np.testing.assert_allclose(q, ref, atol=1e-9)


def test_hide_labels_keeps_the_axes_and_drops_the_names():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "06-pan-joint.urdf"))
    assert any(p.endswith("/label") for p in objects(view.commands()))
    assert view.hide_labels() is view
    paths = objects(view.commands())
    assert not any(p.endswith("/label") for p in paths)
    assert sum(p.endswith("/triad") for p in paths) == 7
    view.set_frame_poses({"odom": np.eye(4)})          # a frame seen later gets no name either
    paths = objects(view.commands())
    assert "/meshcat/frames/odom/triad" in paths and "/meshcat/frames/odom/label" not in paths
