"""xacro expansion through labkit's package index."""
import io
import os
import contextlib

import pytest

from labkit import robots
from labkit.robots import xacro_support
from labkit.robots.urdf import URDFError

SHARE = robots.share_directory("urdf_tutorial")


def test_macroed_expands_like_physics():
    text = robots.description(os.path.join(SHARE, "urdf", "08-macroed.urdf.xacro"))
    assert "xacro:" not in text and "${" not in text
    macroed = robots.load(text)
    physics = robots.load(os.path.join(SHARE, "urdf", "07-physics.urdf"))
    assert sorted(macroed.links) == sorted(physics.links)
    assert sorted(macroed.joints) == sorted(physics.joints)
    # the macro puts the right leg at -y like the plain URDFs: 0.22 = width + .02
    assert macroed.joints["base_to_right_leg"].origin[1, 3] == pytest.approx(-0.22)


def test_find_resolves_through_package_index(tmp_path):
    path = tmp_path / "find.urdf.xacro"
    path.write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="f">'
        '<xacro:property name="width" value="0.2"/>'
        '<xacro:macro name="leg" params="prefix reflect">'
        '<link name="${prefix}_leg"><visual><geometry><box size="${width*3} 0.1 0.2"/>'
        '</geometry></visual></link></xacro:macro>'
        '<link name="base"><visual><geometry>'
        '<mesh filename="$(find urdf_tutorial)/meshes/l_finger.dae"/></geometry></visual></link>'
        '<xacro:leg prefix="right" reflect="1"/>'
        '<joint name="base_to_right_leg" type="fixed"><parent link="base"/>'
        '<child link="right_leg"/></joint></robot>')
    text = xacro_support.process(str(path))
    assert os.path.join(SHARE, "meshes", "l_finger.dae") in text
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
        code = xacro_support.main(["xacro", os.path.join(SHARE, "urdf", "08-macroed.urdf.xacro")])
    assert code == 0
    assert '<robot name="macroed">' in out.getvalue()
    target = tmp_path / "model.urdf"
    assert xacro_support.main(["xacro", os.path.join(SHARE, "urdf", "08-macroed.urdf.xacro"),
                               "-o", str(target)]) == 0
    assert robots.load(str(target)).name == "macroed"


def test_run_for_launch_command_substitution():
    code, out, err = xacro_support.run("xacro " + os.path.join(SHARE, "urdf", "01-myfirst.urdf"))
    assert (code, err) == (0, "")
    assert robots.load(out).name == "myfirst"
    code, out, err = xacro_support.run("xacro /nonexistent.xacro")
    assert code == 2 and out == "" and "No such file or directory: /nonexistent.xacro" in err
