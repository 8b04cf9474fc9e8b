"""xacro expansion through labkit's package index."""
import io
import os
import contextlib

import numpy as np
import pytest

from labkit import robots
from labkit.robots import xacro_support
from labkit.robots.urdf import URDFError

SHARE = robots.share_directory("facer_description")


def test_macros_expand_to_the_hand_written_physics_model():
    """08-macros.urdf.xacro is 07-physics.urdf written with xacro: same links, joints,
    shapes, origins, limits, masses and inertias (numbers to 1e-9)."""
    text = robots.description(os.path.join(SHARE, "urdf", "08-macros.urdf.xacro"))
    assert "xacro:" not in text and "${" not in text
    macros = robots.load(text)
    physics = robots.load(os.path.join(SHARE, "urdf", "07-physics.urdf"))
    assert sorted(macros.links) == sorted(physics.links)
    assert sorted(macros.joints) == sorted(physics.joints)
    for name, joint in physics.joints.items():
        other = macros.joints[name]
        assert (other.type, other.parent, other.child) == (joint.type, joint.parent, joint.child)
        np.testing.assert_allclose(other.origin, joint.origin, atol=1e-4, err_msg=name)
        np.testing.assert_allclose(other.axis, joint.axis, err_msg=name)
        if joint.limit is not None:
            assert (other.limit.lower, other.limit.upper) == \
                pytest.approx((joint.limit.lower, joint.limit.upper), abs=1e-4)
    for name, link in physics.links.items():
        other = macros.links[name]
        a, b = link.inertial, other.inertial
        assert b.mass == pytest.approx(a.mass)
        for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
            assert getattr(b.inertia, key) == pytest.approx(getattr(a.inertia, key), rel=1e-4,
                                                            abs=1e-12), (name, key)
        for mine, theirs in ((link.visuals, other.visuals), (link.collisions, other.collisions)):
            assert [type(v.geometry).__name__ for v in mine] == \
                [type(v.geometry).__name__ for v in theirs], name
            for v, w in zip(mine, theirs):
                np.testing.assert_allclose(_origin(w), _origin(v), atol=1e-4, err_msg=name)
        assert [physics.material_rgba(v) for v in link.visuals] == \
            [macros.material_rgba(v) for v in other.visuals], name


def _origin(element):
    from labkit.robots.urdf import pose_matrix
    o = element.origin
    return pose_matrix(o.xyz if o and o.xyz else (0, 0, 0), o.rpy if o and o.rpy else (0, 0, 0))


def test_find_resolves_through_package_index(tmp_path):
    path = tmp_path / "find.urdf.xacro"
    path.write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="f">'
        '<xacro:property name="width" value="0.2"/>'
        '<xacro:macro name="leg" params="prefix reflect">'
        '<link name="${prefix}_leg"><visual><geometry><box size="${width*3} 0.1 0.2"/>'
        '</geometry></visual></link></xacro:macro>'
        '<link name="base"><visual><geometry>'
        '<mesh filename="$(find facer_description)/meshes/wheel.dae"/></geometry></visual></link>'
        '<xacro:leg prefix="right" reflect="1"/>'
        '<joint name="base_to_right_leg" type="fixed"><parent link="base"/>'
        '<child link="right_leg"/></joint></robot>')
    text = xacro_support.process(str(path))
    assert os.path.join(SHARE, "meshes", "wheel.dae") in text
    m = robots.load(text)
    assert m.links["right_leg"].visuals[0].geometry.size == pytest.approx([0.6, 0.1, 0.2])


def test_xacro_arguments(tmp_path):
    path = tmp_path / "arg.xacro"
    path.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="a">'
                    '<xacro:arg name="name" default="marvin"/><link name="$(arg name)s_leg"/>'
                    '</robot>')
    assert '<link name="marvins_leg"/>' in xacro_support.process(str(path))
    assert '<link name="r2s_leg"/>' in xacro_support.process(str(path), {"name": "r2"})


def test_xacro_error_names_file(tmp_path):
    path = tmp_path / "broken.xacro"
    path.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="b">'
                    '<link name="${undefined_width}"/></robot>')
    with pytest.raises(URDFError) as info:
        xacro_support.process(str(path))
    assert "broken.xacro" in str(info.value)
    assert "undefined_width" in str(info.value)


def test_xacro_command_prints_urdf(tmp_path):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = xacro_support.main(["xacro", os.path.join(SHARE, "urdf", "08-macros.urdf.xacro")])
    assert code == 0
    assert '<robot name="facer">' in out.getvalue()
    target = tmp_path / "model.urdf"
    assert xacro_support.main(["xacro", os.path.join(SHARE, "urdf", "08-macros.urdf.xacro"),
                               "-o", str(target)]) == 0
    assert robots.load(str(target)).name == "facer"


def test_run_for_launch_command_substitution():
    code, out, err = xacro_support.run("xacro " + os.path.join(SHARE, "urdf", "01-one-shape.urdf"))
    assert (code, err) == (0, "")
    assert robots.load(out).name == "facer"
    code, out, err = xacro_support.run("xacro /nonexistent.xacro")
    assert code == 2 and out == "" and "No such file or directory: /nonexistent.xacro" in err


def test_bundled_files_are_named_as_installed_under_opt_ros():
    """xacro's banner and errors name a bundled package's file as a Humble machine would
    (/opt/ros/humble/share/...), never labkit's own folder."""
    text = xacro_support.process(os.path.join(SHARE, "urdf", "01-one-shape.urdf"))
    assert ("autogenerated by xacro from "
            "/opt/ros/humble/share/facer_description/urdf/01-one-shape.urdf") in text
    assert SHARE not in text
    code, out, err = xacro_support.run("xacro " + os.path.join(SHARE, "urdf", "nothing.urdf"))
    assert code == 2 and "/opt/ros/humble/share/facer_description/urdf/nothing.urdf" in err
    assert SHARE not in err
