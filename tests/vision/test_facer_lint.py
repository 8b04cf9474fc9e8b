"""The facer sources pass what `colcon test` runs on Humble: ament_flake8 and ament_pep257.

ament_python packages made by `ros2 pkg create` test themselves with ament_flake8
(flake8 + flake8-import-order, google style, 99 columns) and ament_pep257 (pydocstyle
with the "ament" convention) over every .py file of the package. The settings below
are those of ament_lint's humble branch (ament_flake8/configuration/ament_flake8.ini,
ament_pep257/main.py `_ament_ignore`). A Chinese summary line ending in '。' fails
D400; imports out of google order fail I100/I101.
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..',
                   'book', 'part2_facer', 'facer_src', 'src')
PACKAGES = ('facer_input', 'facer_handle', 'facer_output')

AMENT_FLAKE8_INI = """[flake8]
extend-ignore = B902,C816,D100,D101,D102,D103,D104,D105,D106,D107,D203,D212,D404,I202
import-order-style = google
max-line-length = 99
"""
AMENT_PEP257_IGNORE = 'D100,D101,D102,D103,D104,D105,D106,D107,D203,D212,D404'


def _have(module):
    try:
        __import__(module)
    except ImportError:
        return False
    return True


@pytest.mark.skipif(not _have('flake8'), reason='flake8 is not installed')
@pytest.mark.parametrize('pkg', PACKAGES)
def test_ament_flake8(pkg, tmp_path):
    config = tmp_path / 'ament_flake8.ini'
    config.write_text(AMENT_FLAKE8_INI, encoding='utf-8')
    r = subprocess.run([sys.executable, '-m', 'flake8', '--config', str(config), '.'],
                       cwd=os.path.join(SRC, pkg), capture_output=True, text=True,
                       encoding='utf-8')
    assert r.returncode == 0, r.stdout + r.stderr


def test_flake8_import_order_is_active(tmp_path):
    """The I100 check above is real: flake8-import-order is loaded and judges google order."""
    if not (_have('flake8') and _have('flake8_import_order')):
        pytest.skip('flake8-import-order is not installed')
    config = tmp_path / 'ament_flake8.ini'
    config.write_text(AMENT_FLAKE8_INI, encoding='utf-8')
    bad = tmp_path / 'bad.py'
    bad.write_text('import rclpy\nfrom cv_bridge import CvBridge\n\n'
                   'print(rclpy, CvBridge)\n', encoding='utf-8')
    r = subprocess.run([sys.executable, '-m', 'flake8', '--config', str(config), str(bad)],
                       capture_output=True, text=True, encoding='utf-8')
    assert 'I100' in r.stdout


@pytest.mark.skipif(not _have('pydocstyle'), reason='pydocstyle is not installed')
@pytest.mark.parametrize('pkg', PACKAGES)
def test_ament_pep257(pkg):
    r = subprocess.run([sys.executable, '-m', 'pydocstyle', '--ignore', AMENT_PEP257_IGNORE,
                        '.'], cwd=os.path.join(SRC, pkg), capture_output=True, text=True,
                       encoding='utf-8')
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.skipif(not _have('pydocstyle'), reason='pydocstyle is not installed')
def test_a_chinese_full_stop_fails_d400(tmp_path):
    (tmp_path / 'm.py').write_text('"""打开摄像头。"""\n', encoding='utf-8')
    r = subprocess.run([sys.executable, '-m', 'pydocstyle', '--ignore', AMENT_PEP257_IGNORE,
                        'm.py'], cwd=tmp_path, capture_output=True, text=True,
                       encoding='utf-8')
    assert 'D400' in r.stdout


def test_bringup_launch_package_depends_on_the_nodes_it_starts():
    root = ET.parse(os.path.join(SRC, 'facer_input', 'package.xml')).getroot()
    deps = {e.text for e in root.findall('exec_depend')}
    assert {'facer_handle', 'facer_output', 'ros2launch'} <= deps


def test_action_server_aborts_its_goal_on_the_shutdown_path():
    import ast
    path = os.path.join(SRC, 'facer_input', 'facer_input', 'capture_image.py')
    tree = ast.parse(open(path, encoding='utf-8').read())
    execute = next(n for n in ast.walk(tree)
                   if isinstance(n, ast.FunctionDef) and n.name == 'execute_callback')
    # the loop's `if not rclpy.ok():` branch calls goal_handle.abort() before it returns
    for node in ast.walk(execute):
        if isinstance(node, ast.If) and 'rclpy.ok' in ast.unparse(node.test):
            calls = [ast.unparse(n) for stmt in node.body for n in ast.walk(stmt)
                     if isinstance(n, ast.Call)]
            assert 'goal_handle.abort()' in calls, calls
            assert isinstance(node.body[-1], ast.Return)
            break
    else:
        pytest.fail('execute_callback never checks rclpy.ok()')
