"""URDF parsing, forward kinematics (checked against pytransform3d) and errors."""
import os

import numpy as np
import pytest

from labkit import robots
from labkit.robots import packages, urdf  # noqa: F401

SHARE = robots.share_directory("facer_description")
STEPS = ["01-one-shape.urdf", "02-shapes.urdf", "03-origins.urdf", "04-materials.urdf",
         "05-meshes.urdf", "06-pan-joint.urdf", "07-physics.urdf", "08-macros.urdf.xacro"]


def model(name):
    return robots.load(os.path.join(SHARE, "urdf", name))


@pytest.mark.parametrize("name, links, joints, movable", [
    ("01-one-shape.urdf", 1, 0, 0),
    ("02-shapes.urdf", 4, 3, 0),
    ("03-origins.urdf", 5, 4, 0),
    ("04-materials.urdf", 7, 6, 0),
    ("05-meshes.urdf", 7, 6, 0),
    ("06-pan-joint.urdf", 7, 6, 4),
    ("07-physics.urdf", 7, 6, 4),
    ("08-macros.urdf.xacro", 7, 6, 4),
])
def test_facer_models(name, links, joints, movable):
    m = model(name)
    assert (m.name, len(m.links), len(m.joints), len(m.movable_joints())) == \
        ("facer", links, joints, movable)
    assert m.root == "base_link"


def test_pan_joint_model_has_each_kind_of_joint():
    m = model("06-pan-joint.urdf")
    kinds = {j.name: j.type for j in m.joints.values()}
    assert kinds == {"left_wheel_joint": "continuous", "right_wheel_joint": "continuous",
                     "mast_lift": "prismatic", "head_pan": "revolute",
                     "caster_joint": "fixed", "camera_joint": "fixed"}
    pan = m.joints["head_pan"]
    assert (pan.limit.lower, pan.limit.upper) == pytest.approx((-1.5708, 1.5708))
    assert m.joints["mast_lift"].limit.upper == pytest.approx(0.08)


def test_wheels_and_caster_touch_the_floor():
    """base_link is at axle height: the wheels' and the ball's bottoms are 5 cm below it."""
    m = model("07-physics.urdf")
    poses = m.link_poses({})
    for wheel in ("left_wheel", "right_wheel"):
        assert poses[wheel][2, 3] - 0.05 == pytest.approx(-0.05)
    assert poses["caster_link"][2, 3] - 0.025 == pytest.approx(-0.05)


def test_meshes_resolve_and_are_small():
    from labkit.robots.packages import resolve_uri
    m = model("05-meshes.urdf")
    files = {v.geometry.filename for link in m.links.values() for v in link.visuals
             if hasattr(v.geometry, "filename")}
    assert files == {"package://facer_description/meshes/head.stl",
                     "package://facer_description/meshes/wheel.dae"}
    for uri in files:
        path = resolve_uri(uri)
        assert os.path.isfile(path) and os.path.getsize(path) < 60_000


def test_meshes_are_what_the_generator_makes(tmp_path):
    from labkit.robots import facer_meshes
    facer_meshes.write(str(tmp_path))
    for name in ("head.stl", "wheel.dae"):
        with open(os.path.join(SHARE, "meshes", name), "rb") as shipped:
            assert shipped.read() == (tmp_path / name).read_bytes(), name


def test_head_mesh_fits_its_collision_box():
    import struct
    from labkit.robots import facer_meshes
    data = facer_meshes.stl_bytes(facer_meshes.head_triangles())
    count = struct.unpack("<I", data[80:84])[0]
    assert len(data) == 84 + 50 * count
    tris = facer_meshes.head_triangles().reshape(-1, 3)
    np.testing.assert_allclose(tris.max(axis=0), (0.045, 0.06, 0.035), atol=1e-9)
    np.testing.assert_allclose(tris.min(axis=0), (-0.045, -0.06, -0.035), atol=1e-9)


def _solid_inertia(geometry, mass):
    """The textbook inertia of a solid shape about its centre, in the shape's own frame."""
    from urdf_parser_py import urdf as u
    if isinstance(geometry, u.Box):
        a, b, c = geometry.size
        return mass / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])
    if isinstance(geometry, u.Cylinder):
        r, h = geometry.radius, geometry.length
        across = mass * (3 * r * r + h * h) / 12
        return np.diag([across, across, mass * r * r / 2])
    if isinstance(geometry, u.Sphere):
        return np.eye(3) * 2 * mass * geometry.radius ** 2 / 5
    raise AssertionError(geometry)


@pytest.mark.parametrize("name", ["07-physics.urdf", "08-macros.urdf.xacro"])
def test_inertia_is_the_collision_solids(name):
    """Each link's inertia tensor is its collision solid's (turned into the link frame)
    and the centre of mass is the solid's centre."""
    m = model(name)
    for link_name, link in m.links.items():
        assert link.inertial is not None and len(link.collisions) == 1, link_name
        col = link.collisions[0]
        origin = urdf.pose_matrix(col.origin.xyz if col.origin and col.origin.xyz else (0, 0, 0),
                                  col.origin.rpy if col.origin and col.origin.rpy else (0, 0, 0))
        rot = origin[:3, :3]
        expected = rot @ _solid_inertia(col.geometry, link.inertial.mass) @ rot.T
        i = link.inertial.inertia
        got = np.array([[i.ixx, i.ixy, i.ixz], [i.ixy, i.iyy, i.iyz], [i.ixz, i.iyz, i.izz]])
        np.testing.assert_allclose(got, expected, rtol=1e-4, atol=1e-9, err_msg=link_name)
        com = link.inertial.origin.xyz if link.inertial.origin and link.inertial.origin.xyz \
            else (0, 0, 0)
        np.testing.assert_allclose(com, origin[:3, 3], atol=1e-12, err_msg=link_name)


def test_materials_resolve_named_colours():
    m = model("04-materials.urdf")
    assert m.material_rgba(m.links["base_link"].visuals[0]) == (0.95, 0.5, 0.1, 1.0)
    assert m.material_rgba(m.links["camera_link"].visuals[0]) == (0.1, 0.3, 0.9, 1.0)
    assert m.material_rgba(m.links["left_wheel"].visuals[0]) == (0.08, 0.08, 0.08, 1.0)


def _pytransform3d_poses(text, positions, root):
    from pytransform3d.urdf import UrdfTransformManager
    tm = UrdfTransformManager()
    tm.load_urdf(text)
    for name, q in positions.items():
        tm.set_joint(name, q)
    return lambda link: tm.get_transform(link, root)


@pytest.mark.parametrize("path", [os.path.join(SHARE, "urdf", n) for n in STEPS[1:7]])
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
    m = model("06-pan-joint.urdf")
    xyz, q = m.joints["head_pan"].transform(np.pi / 2)
    assert xyz == pytest.approx((0.0, 0.0, 0.16))
    assert q == pytest.approx((0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)))
    xyz, q = m.joints["mast_lift"].transform(0.05)
    assert xyz == pytest.approx((-0.08, 0.0, 0.12))


def test_camera_position_after_a_pan_and_a_lift():
    """The lens is 5 cm ahead of the pan axis: panning a quarter turn left moves it to +y."""
    m = model("06-pan-joint.urdf")
    lens = m.link_poses({"head_pan": np.pi / 2, "mast_lift": 0.08})["camera_link"]
    np.testing.assert_allclose(lens[:3, 3], (-0.08, 0.05, 0.07 + 0.08 + 0.16 + 0.035),
                               atol=1e-9)
    np.testing.assert_allclose(lens[:3, 0], (0, 1, 0), atol=1e-9)     # looks to the left


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
    if not message.startswith(("Failed to build tree: ", "Failed to find root link: ")):
        assert "bad.urdf" in message      # urdfdom's tree errors do not name the file
    assert where in message


def test_missing_file():
    with pytest.raises(urdf.URDFError, match="Failed to open URDF file: /nonexistent.urdf"):
        urdf.load("/nonexistent.urdf")


def test_check_urdf_prints_the_tree_like_urdfdom():
    code, text = urdf.check_urdf(os.path.join(SHARE, "urdf", "07-physics.urdf"))
    assert code == 0
    assert text.splitlines() == [
        "robot name is: facer",
        "---------- Successfully Parsed XML ---------------",
        "root Link: base_link has 4 child(ren)",
        "    child(1):  caster_link",
        "    child(2):  left_wheel",
        "    child(3):  mast_link",
        "        child(1):  head_link",
        "            child(1):  camera_link",
        "    child(4):  right_wheel"]


def test_check_urdf_failures(tmp_path):
    code, text = urdf.check_urdf(str(tmp_path / "missing.urdf"))
    assert code == 255 and text == f"Could not open file [{tmp_path / 'missing.urdf'}] for parsing."
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='x'><link name='a'/><link name='b'/></robot>")
    code, text = urdf.check_urdf(str(bad))
    assert code == 255 and text.endswith("ERROR: Model Parsing the xml failed")
