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

SHARE = robots.share_directory("urdf_tutorial")


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
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "05-visual.urdf"))
    page = view.html()
    objs = objects(scene_commands(page))
    body = objs["/meshcat/robot/base_link/visual_0"]
    assert body["geometries"][0]["type"] == "CylinderGeometry"
    assert body["geometries"][0]["radiusTop"] == pytest.approx(0.2)
    assert body["geometries"][0]["height"] == pytest.approx(0.6)
    assert body["materials"][0]["color"] == 0x0000CC                 # blue 0 0 0.8
    leg = objs["/meshcat/robot/right_leg/visual_0"]["geometries"][0]
    assert (leg["type"], leg["width"], leg["height"], leg["depth"]) == (
        "BoxGeometry", pytest.approx(0.6), pytest.approx(0.1), pytest.approx(0.2))
    assert objs["/meshcat/robot/head/visual_0"]["geometries"][0]["type"] == "SphereGeometry"
    finger = objs["/meshcat/robot/left_gripper/visual_0"]["geometries"][0]
    assert finger["type"] == "_meshfile_geometry" and finger["format"] == "dae"
    assert "<COLLADA" in finger["data"]
    # every link has a named TF triad
    labels = [o["textures"][0]["text"] for p, o in objs.items() if p.endswith("/label")]
    assert sorted(labels) == sorted(view.model.links)


def test_iframe_is_self_contained_and_small():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "01-myfirst.urdf"))
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
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "06-flexible.urdf"))
    view.set_joint_positions({"head_swivel": math.pi / 2})
    cmds = {c["path"]: c for c in view.commands() if c["type"] == "set_transform"}
    m = np.array(cmds["/meshcat/robot/head"]["matrix"]).reshape(4, 4).T
    np.testing.assert_allclose(m, view.model.link_poses({"head_swivel": math.pi / 2})["head"],
                               atol=1e-6)
    assert m[0, 1] == pytest.approx(-1.0)


def test_r2d2_walk_is_an_animation():
    view = meshcat_view.r2d2_walk(seconds=4.0, fps=10)
    cmds = scene_commands(view.html())
    anim = [c for c in cmds if c["type"] == "set_animation"]
    assert len(anim) == 1
    clips = {a["path"]: a["clip"] for a in anim[0]["animations"]}
    assert "/meshcat/robot/head" in clips and "/meshcat/frames/odom" in clips
    keys = clips["/meshcat/robot/axis"]["tracks"][0]["keys"]
    assert len(keys) == 40
    x, y, z = keys[-1]["value"]
    assert math.hypot(x, y) == pytest.approx(2.0, abs=1e-5) and z == pytest.approx(0.7)


def test_view_follows_tf_from_robot_state_publisher():
    from labkit.robots import r2d2
    view = meshcat_view.RobotView(r2d2.urdf_path())
    view.follow()
    r2d2.start_demo(echo=False)
    labkit.sleep(0.5)
    poses = view.tf_poses()
    assert {"odom", "axis", "leg1", "head", "box"} <= set(poses)
    xyz = poses["axis"][:3, 3]
    assert math.hypot(xyz[0], xyz[1]) == pytest.approx(2.0) and xyz[2] == pytest.approx(0.7)
    view.stop()
    assert all(p.name != "labkit_meshcat_view" or p.returncode is not None
               for p in process.processes())


def test_live_server_binds_loopback_only():
    view = meshcat_view.RobotView(os.path.join(SHARE, "urdf", "01-myfirst.urdf"))
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


def test_display_starts_the_urdf_tutorial_graph():
    procs = robots.display("urdf/06-flexible.urdf", gui=False, echo=False)
    labkit.sleep(0.3)
    nodes = labkit.ros2("node list").stdout.split()
    assert nodes == ["/joint_state_publisher", "/robot_state_publisher", "/rviz2"]
    view = meshcat_view.current()
    assert view.model is not None and view.model.name == "visual"
    assert {"base_link", "head", "right_front_wheel"} <= set(view.tf_poses())
    assert len(procs) == 3


def test_quaternions_match_scipy():
    from scipy.spatial.transform import Rotation
    from labkit.robots.urdf import quaternion_from_matrix
    for r in Rotation.random(50, random_state=3):
        q = np.array(quaternion_from_matrix(r.as_matrix()))
        ref = r.as_quat()
        ref = ref if ref[3] >= 0 else -ref
        np.testing.assert_allclose(q, ref, atol=1e-9)
