"""URDF parsing, forward kinematics (checked against pytransform3d) and errors."""
import os

import numpy as np
import pytest

from labkit import robots
from labkit.robots import packages, urdf  # noqa: F401

SHARE = robots.share_directory("urdf_tutorial")
R2D2 = robots.packages.R2D2_URDF


def model(name):
    return robots.load(os.path.join(SHARE, "urdf", name))


@pytest.mark.parametrize("name, robot, links, joints, movable", [
    ("01-myfirst.urdf", "myfirst", 1, 0, 0),
    ("02-multipleshapes.urdf", "multipleshapes", 2, 1, 0),
    ("03-origins.urdf", "origins", 2, 1, 0),
    ("04-materials.urdf", "materials", 3, 2, 0),
    ("05-visual.urdf", "visual", 16, 15, 0),
    ("06-flexible.urdf", "visual", 16, 15, 8),
    ("07-physics.urdf", "physics", 16, 15, 8),
    ("08-macroed.urdf.xacro", "macroed", 16, 15, 8),
])
def test_tutorial_models(name, robot, links, joints, movable):
    m = model(name)
    assert (m.name, len(m.links), len(m.joints), len(m.movable_joints())) == \
        (robot, links, joints, movable)
    assert m.root == "base_link"


def test_r2d2_model():
    m = robots.load(R2D2)
    assert m.root == "axis"
    assert sorted(j.name for j in m.movable_joints()) == ["periscope", "swivel", "tilt"]
    assert sorted(j.name for j in m.fixed_joints()) == ["boxconnect", "leg1connect",
                                                         "leg2connect"]


def test_materials_resolve_named_colours():
    m = model("04-materials.urdf")
    assert m.material_rgba(m.links["base_link"].visuals[0]) == (0.0, 0.0, 0.8, 1.0)
    assert m.material_rgba(m.links["right_leg"].visuals[0]) == (1.0, 1.0, 1.0, 1.0)


def _pytransform3d_poses(text, positions, root):
    from pytransform3d.urdf import UrdfTransformManager
    tm = UrdfTransformManager()
    tm.load_urdf(text)
    for name, q in positions.items():
        tm.set_joint(name, q)
    return lambda link: tm.get_transform(link, root)


@pytest.mark.parametrize("path", [os.path.join(SHARE, "urdf", "06-flexible.urdf"), R2D2])
def test_forward_kinematics_matches_pytransform3d(path):
    with open(path) as handle:
        text = handle.read()
    m = robots.load(path)
    rng = np.random.default_rng(7)
    for _ in range(5):
        positions = {}
        for j in m.movable_joints():
            low, high = (j.limit.lower, j.limit.upper) if j.limit and j.type != "continuous" \
                else (-3.0, 3.0)
            positions[j.name] = float(rng.uniform(low, high))
        ours = m.link_poses(positions)
        theirs = _pytransform3d_poses(text, positions, m.root)
        for link in m.links:
            np.testing.assert_allclose(ours[link], theirs(link), atol=1e-9, err_msg=link)


def test_joint_transform_is_quaternion_xyzw():
    m = robots.load(R2D2)
    xyz, q = m.joints["swivel"].transform(np.pi / 2)
    assert xyz == pytest.approx((0.0, 0.0, 0.1))
    assert q == pytest.approx((0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)))
    xyz, q = m.joints["periscope"].transform(-0.25)
    assert xyz == pytest.approx((0.12, 0.0, -0.1))


BAD = [
    ("<robot name='x'><link name='a'>", "line 1"),
    ("<robot name='x'><link name='a'><visual><geometry><box/></geometry></visual></link></robot>",
     "geometry"),
    ("<robot name='x'><link name='a'/><link name='b'/><joint name='j' type='wobbly'>"
     "<parent link='a'/><child link='b'/></joint></robot>", "joint[@name='j']"),
    ("<robot name='x'><link name='a'/><joint name='j' type='fixed'>"
     "<parent link='a'/><child link='ghost'/></joint></robot>", "ghost"),
    ("<robot name='x'><link name='a'/><link name='b'/></robot>", "root link"),
    ("<robot name='x'><link name='a'/><link name='b'/><joint name='j' type='revolute'>"
     "<parent link='a'/><child link='b'/></joint></robot>", "<limit>"),
    ("<sdf version='1.6'/>", "robot"),
]


@pytest.mark.parametrize("text, where", BAD)
def test_malformed_urdf_names_file_and_element(tmp_path, text, where):
    path = tmp_path / "bad.urdf"
    path.write_text(text)
    with pytest.raises(urdf.URDFError) as info:
        robots.load(str(path))
    message = str(info.value)
    assert "bad.urdf" in message
    assert where in message


def test_missing_file():
    with pytest.raises(urdf.URDFError, match="Failed to open URDF file: /nonexistent.urdf"):
        urdf.load("/nonexistent.urdf")
