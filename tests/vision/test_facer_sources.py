"""The facer sources are a real colcon workspace: manifests, setup.py and launch file agree."""
import ast
import os
import xml.etree.ElementTree as ET

import pytest

SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..',
                   'book', 'part2_facer', 'facer_src', 'src')
PYTHON_PACKAGES = {'facer_input': 'capture_image', 'facer_handle': 'identify_image',
                   'facer_output': 'visual_interaction'}


def _manifest(pkg):
    return ET.parse(os.path.join(SRC, pkg, 'package.xml')).getroot()


def _setup_call(pkg):
    tree = ast.parse(open(os.path.join(SRC, pkg, 'setup.py'), encoding='utf-8').read())
    names = {t.id: n.value.value for n in tree.body if isinstance(n, ast.Assign)
             for t in n.targets if isinstance(t, ast.Name) and isinstance(n.value, ast.Constant)}
    call = next(n.value for n in tree.body
                if isinstance(n, ast.Expr) and isinstance(n.value, ast.Call))
    return names, {k.arg: k.value for k in call.keywords}


def test_interfaces_package():
    root = _manifest('facer_interfaces')
    assert root.findtext('name') == 'facer_interfaces'
    assert root.findtext('export/build_type') == 'ament_cmake'
    assert root.findtext('member_of_group') == 'rosidl_interface_packages'
    cmake = open(os.path.join(SRC, 'facer_interfaces', 'CMakeLists.txt')).read()
    assert '"srv/FaceResult.srv"' in cmake and '"action/CameraState.action"' in cmake
    assert cmake.rstrip().endswith('ament_package()')  # the seed forgot it


@pytest.mark.parametrize('pkg, executable', sorted(PYTHON_PACKAGES.items()))
def test_python_package(pkg, executable):
    root = _manifest(pkg)
    assert root.findtext('name') == pkg
    assert root.findtext('export/build_type') == 'ament_python'
    deps = [e.text for e in root.findall('exec_depend')]
    assert 'rclpy' in deps and 'facer_interfaces' in deps
    assert 'python3-opencv' in deps and 'python-opencv' not in deps
    names, kwargs = _setup_call(pkg)
    assert names['package_name'] == pkg
    assert kwargs['description'].value == root.findtext('description')
    scripts = ast.literal_eval(kwargs['entry_points'])['console_scripts']
    assert scripts == [f'{executable} = {pkg}.{executable}:main']
    assert os.path.isfile(os.path.join(SRC, pkg, 'resource', pkg))
    assert os.path.isfile(os.path.join(SRC, pkg, pkg, f'{executable}.py'))
    setup_cfg = open(os.path.join(SRC, pkg, 'setup.cfg')).read()
    assert f'install_scripts=$base/lib/{pkg}' in setup_cfg


def test_launch_file_sets_timer_period():
    path = os.path.join(SRC, 'facer_input', 'launch', 'python_parameters_launch.py')
    tree = ast.parse(open(path, encoding='utf-8').read())
    node = next(n for n in ast.walk(tree) if isinstance(n, ast.Call)
                and getattr(n.func, 'id', None) == 'Node')
    kwargs = {k.arg: ast.literal_eval(k.value) for k in node.keywords}
    assert kwargs['package'] == 'facer_input' and kwargs['executable'] == 'capture_image'
    assert kwargs['parameters'] == [{'timer_period': 1.0}]
