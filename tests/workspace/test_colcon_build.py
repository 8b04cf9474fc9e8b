"""colcon build of a facer-like workspace: order, layout, output, then source and run."""
import os

import labkit
from labkit import oslayer
from labkit.ament import colcon, source


def build(command='build'):
    return colcon.run_command(command)


def test_build_order_output_and_layout(facer):
    r = build()
    assert r.returncode == 0, r.text()
    lines = r.stdout.splitlines()
    starts = [line.split()[-1] for line in lines if line.startswith('Starting >>> ')]
    # colcon-parallel-executor: of the ready packages, those with more dependents start
    # first (facer_interfaces: 2, facer_input: 1), then the topological order
    assert starts == ['facer_interfaces', 'facer_input', 'facer_detect', 'facer_bringup']
    assert any(line.startswith('Finished <<< facer_interfaces [') for line in lines)
    assert lines[-2].startswith('Summary: 4 packages finished [')
    # Jammy's setuptools warns in every ament_python package, as on a real Humble machine
    assert lines[-1] == '  3 packages had stderr output: facer_bringup facer_detect facer_input'
    assert without_setuptools_warnings(r.stderr) == ''   # each installs marker and package.xml
    inst = facer / 'install'
    assert (inst / 'facer_input/lib/facer_input/capture_image').is_file()
    assert os.access(inst / 'facer_input/lib/facer_input/capture_image', os.X_OK)
    site = inst / 'facer_input/lib/python3.10/site-packages'
    assert (site / 'facer_input/capture_image.py').is_file()
    assert (site / 'facer_input-0.0.0-py3.10.egg-info/entry_points.txt').read_text() \
        .startswith('[console_scripts]\ncapture_image = facer_input.capture_image:main')
    assert (inst / 'facer_input/share/facer_input/package.xml').is_file()
    assert (inst / 'facer_input/share/ament_index/resource_index/packages/facer_input').exists()
    assert (inst / 'facer_bringup/share/facer_bringup/launch/facer.launch.py').is_file()
    assert (inst / 'facer_bringup/share/facer_bringup/config/facer.yaml').is_file()
    assert (inst / 'facer_interfaces/share/facer_interfaces/srv/FaceResult.srv').is_file()
    assert (inst / 'facer_interfaces/share/facer_interfaces/msg/Face.msg').is_file()
    assert (inst / 'setup.bash').is_file() and (inst / 'local_setup.bash').is_file()
    for folder in ('build', 'install', 'log'):
        assert (facer / folder / 'COLCON_IGNORE').exists()
    latest = facer / 'log' / 'latest_build'
    # a symlink, or where the OS refuses them (Windows without Developer Mode) a copy
    assert oslayer.link_target(str(latest)).startswith('build_')
    assert latest.is_symlink() or oslayer.WINDOWS
    assert (latest / 'facer_input' / 'stdout_stderr.log').is_file()


def test_virtual_times_are_a_deterministic_cost_model(facer):
    first = build().stdout
    second = build().stdout
    assert first == second
    assert 'Finished <<< facer_interfaces [3.15s]' in first     # 1.45 + 2 interfaces * 0.85


def test_format_duration_like_colcon():
    assert colcon.format_duration(0.414) == '0.41s'
    assert colcon.format_duration(12.34) == '12.3s'
    assert colcon.format_duration(65.2) == '1min 5s'
    assert colcon.format_duration(3723) == '1h 2min 3s'


def test_packages_select_and_up_to(facer):
    r = build('build --packages-select facer_interfaces')
    assert [line for line in r.stdout.splitlines() if line.startswith('Starting')] == \
        ['Starting >>> facer_interfaces']
    assert 'Summary: 1 package finished' in r.stdout
    r = build('build --packages-up-to facer_detect --event-handlers console_direct+')
    started = [line.split()[-1] for line in r.stdout.splitlines() if line.startswith('Start')]
    assert started == ['facer_interfaces', 'facer_detect']
    assert '-- Configuring done' in r.stdout          # console_direct+ shows the tool output
    r = build('build --packages-select nosuch')
    assert "ignoring unknown package 'nosuch' in --packages-select" in r.stderr
    assert 'Summary: 0 packages finished' in r.stdout


def test_source_then_run_and_import(facer, capsys):
    assert build('build').returncode == 0
    assert source.run('install/setup.bash') == 0
    prefix = str(facer / 'install' / 'facer_input')
    assert os.environ['AMENT_PREFIX_PATH'].split(os.pathsep)[:4].count(prefix) == 1
    out = labkit.ros2('pkg list').stdout.split()
    assert {'facer_input', 'facer_detect', 'facer_bringup', 'facer_interfaces',
            'turtlesim'} <= set(out)
    assert labkit.ros2('pkg executables facer_input').stdout == 'facer_input capture_image\n'
    assert labkit.ros2('pkg prefix facer_input').stdout.strip() == prefix
    from facer_interfaces.srv import FaceResult
    assert FaceResult.Response().count == 0
    job = labkit.ros2('run facer_detect detect_face')
    job.wait(1.0)
    assert any("fields: ['faces', 'count']" in line for line in job.output), job.output
    from ament_index_python.packages import (PackageNotFoundError,
                                             get_package_share_directory)
    assert get_package_share_directory('facer_bringup') == \
        str(facer / 'install' / 'facer_bringup' / 'share' / 'facer_bringup')
    assert os.path.isdir(get_package_share_directory('turtlesim'))
    try:
        get_package_share_directory('nosuch_pkg')
    except PackageNotFoundError as e:
        assert "package 'nosuch_pkg' not found" in str(e)
    else:
        raise AssertionError('no PackageNotFoundError')


def test_rebuild_and_resource_picks_up_changed_code(facer):
    build('build')
    source.run('install/setup.bash')
    job = labkit.ros2('run facer_input capture_image')
    job.wait(1.0)
    assert any('VERSION 1 camera=cam0' in line for line in job.output), job.output
    path = facer / 'src/facer_input/facer_input/capture_image.py'
    path.write_text(path.read_text().replace('VERSION 1', 'VERSION 2'))
    # without a rebuild, the installed copy still runs the old code
    source.run('install/setup.bash')
    job = labkit.ros2('run facer_input capture_image --new')
    job.wait(1.0)
    assert any('VERSION 1' in line for line in job.output), job.output
    build('build --packages-select facer_input')
    source.run('install/setup.bash')
    job = labkit.ros2('run facer_input capture_image --new')
    job.wait(1.0)
    assert any('VERSION 2' in line for line in job.output), job.output


def test_symlink_install_runs_the_sources(facer):
    r = build('build --symlink-install')
    assert r.returncode == 0, r.text()
    site = facer / 'install/facer_input/lib/python3.10/site-packages'
    assert (site / 'facer_input.egg-link').is_file()
    assert (facer / 'build/facer_input/facer_input').is_symlink()
    assert (facer / 'install/facer_bringup/share/facer_bringup/launch/facer.launch.py') \
        .is_symlink()
    source.run('install/setup.bash')
    path = facer / 'src/facer_input/facer_input/capture_image.py'
    path.write_text(path.read_text().replace('VERSION 1', 'VERSION 3'))
    source.run('install/setup.bash')    # no rebuild needed with --symlink-install
    job = labkit.ros2('run facer_input capture_image')
    job.wait(1.0)
    assert any('VERSION 3' in line for line in job.output), job.output


def test_overlay_wins(facer, tmp_path):
    build('build')
    source.run('install/setup.bash')
    import facer_ws
    overlay = tmp_path / 'overlay_ws'
    facer_ws.python_package(str(overlay / 'src'), 'facer_input',
                            [('capture_image', 'facer_input.capture_image:main')],
                            deps=[('depend', 'rclpy')],
                            modules={'capture_image': facer_ws.CAPTURE.replace(
                                'VERSION 1', 'OVERLAY')})
    os.chdir(overlay)
    r = build('build')
    assert r.returncode == 0
    # facer_bringup (underlay) needs facer_input: colcon-override-check warns
    assert "WARNING:colcon.colcon_core.package_selection:Some selected packages are already " \
        "built in one or more underlay workspaces:\n\t'facer_input' is in: " in r.stderr
    assert '\t--allow-overriding facer_input\n' in r.stderr
    assert without_setuptools_warnings(build('build --allow-overriding facer_input').stderr) == ''
    source.run('install/setup.bash')
    assert labkit.ros2('pkg prefix facer_input').stdout.strip() == \
        str(overlay / 'install' / 'facer_input')
    assert labkit.ros2('pkg prefix facer_detect').stdout.strip() == \
        str(facer / 'install' / 'facer_detect')
    job = labkit.ros2('run facer_input capture_image')
    job.wait(1.0)
    assert any('OVERLAY' in line for line in job.output), job.output


def test_source_missing_file(ws, capsys):
    assert source.run('install/setup.bash') == 1
    assert capsys.readouterr().err == 'bash: install/setup.bash: No such file or directory\n'


def test_colcon_list(facer):
    r = colcon.run_command('list -t -n')
    names = r.stdout.split()
    assert names.index('facer_interfaces') < names.index('facer_detect')
    r = colcon.run_command('list')
    assert 'facer_input\tsrc/facer_input\t(ros.ament_python)' in r.stdout


def test_override_warnings_like_colcon_override_check(facer):
    build('build')
    source.run('install/setup.bash')
    assert without_setuptools_warnings(build('build').stderr) == ''   # overrides nothing
    r = build('build --packages-select facer_input')
    assert "'facer_input' is in: " + str(facer / 'install' / 'facer_input') in r.stderr
    assert without_setuptools_warnings(
        build('build --packages-select facer_bringup').stderr) == ''   # a leaf: no warning


def test_overriding_a_bundled_package(ws):
    import facer_ws
    facer_ws.python_package(str(ws / 'src'), 'turtlesim', [])
    r = build('build')
    assert "\t'turtlesim' is in: /opt/ros/humble\n" in r.stderr
    assert r.stdout.endswith(
        'Finished <<< turtlesim [0.78s]\n\nSummary: 1 package finished [1.03s]\n'
        '  1 package had stderr output: turtlesim\n')


SETUPTOOLS_WARNING = (
    '/usr/lib/python3/dist-packages/setuptools/command/install.py:34: '
    'SetuptoolsDeprecationWarning: setup.py install is deprecated. Use build and pip and '
    'other standards-based tools.\n  warnings.warn(\n')


def without_setuptools_warnings(stderr):
    """colcon's stderr less the `--- stderr: pkg` blocks that hold only Jammy's warning."""
    import re
    return re.sub(r'--- stderr: \S+\n' + re.escape(SETUPTOOLS_WARNING) + '---\n', '', stderr)


def test_setuptools_deprecation_warning_like_jammy(ws):
    import facer_ws
    facer_ws.python_package(str(ws / 'src'), 'facer_output', [])
    r = build('build')
    assert r.returncode == 0
    assert r.stderr == '--- stderr: facer_output\n' + SETUPTOOLS_WARNING + '---\n'
    assert r.stdout.splitlines()[-1] == '  1 package had stderr output: facer_output'
    # --symlink-install runs `setup.py develop`: easy_install's warning comes first
    r = build('build --symlink-install')
    assert r.stderr.splitlines()[1] == (
        '/usr/lib/python3/dist-packages/setuptools/command/easy_install.py:158: '
        'EasyInstallDeprecationWarning: easy_install command is deprecated. Use build and pip '
        'and other standards-based tools.')
    assert r.stderr.endswith(SETUPTOOLS_WARNING + '---\n')


def test_copied_setup_py_with_the_wrong_package_name_fails_to_copy_its_marker(ws):
    import facer_ws
    facer_ws.python_package(str(ws / 'src'), 'facer_input', [])
    setup = ws / 'src' / 'facer_input' / 'setup.py'
    text = setup.read_text()
    assert "package_name = 'facer_input'" in text and 'find_packages' in text
    setup.write_text(text.replace("package_name = 'facer_input'", "package_name = 'facer_handle'"))
    r = build('build')
    assert r.returncode == 1
    assert r.stderr.endswith(SETUPTOOLS_WARNING + "error: can't copy 'resource/facer_handle': "
                             "doesn't exist or not a regular file\n---\n")
    assert 'Failed   <<< facer_input [' in r.stdout


def test_magics_are_registered_and_print_like_a_terminal(facer, capsys):
    from labkit.cli import magics
    assert {'colcon', 'source', 'rosdep'} <= set(magics.MAGICS)
    magics.MAGICS['colcon']('build --packages-select facer_input')
    out = capsys.readouterr().out
    assert out.startswith('Starting >>> facer_input\n')
    magics.MAGICS['source']('install/setup.bash')
    assert labkit.ros2('pkg executables facer_input').stdout == 'facer_input capture_image\n'
    magics.MAGICS['rosdep']('install -i --from-path src --rosdistro humble -y')
    assert capsys.readouterr().out.endswith('#All required rosdeps installed successfully\n')


MIXED_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(ws_mixed)
find_package(ament_cmake REQUIRED)
find_package(ament_cmake_python REQUIRED)
find_package(rclpy REQUIRED)
ament_python_install_package(${PROJECT_NAME})
install(PROGRAMS scripts/hello.py DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""

HELLO = """#!/usr/bin/env python3
import rclpy
from ws_mixed.words import WORD


def main():
    rclpy.init()
    node = rclpy.create_node('hello')
    node.get_logger().info(WORD)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
"""


def test_ament_cmake_python_package_and_installed_script(ws):
    import facer_ws
    root = str(ws / 'src' / 'ws_mixed')
    facer_ws.write(root, 'package.xml', facer_ws.PACKAGE_XML.format(
        name='ws_mixed', build_type='ament_cmake', deps=facer_ws.deps_xml([
            ('buildtool_depend', 'ament_cmake'), ('buildtool_depend', 'ament_cmake_python'),
            ('exec_depend', 'rclpy')])))
    facer_ws.write(root, 'CMakeLists.txt', MIXED_CMAKE)
    facer_ws.write(root, 'ws_mixed/__init__.py', '')
    facer_ws.write(root, 'ws_mixed/words.py', "WORD = 'mixed hello'\n")
    facer_ws.write(root, 'launch/empty.launch.py', '')
    os.chmod(facer_ws.write(root, 'scripts/hello.py', HELLO), 0o755)
    r = build()
    assert r.returncode == 0, r.text()
    assert (ws / 'install/ws_mixed/lib/python3.10/site-packages/ws_mixed/words.py').is_file()
    assert (ws / 'install/ws_mixed/share/ws_mixed/launch/empty.launch.py').is_file()
    source.run('install/setup.bash')
    assert labkit.ros2('pkg executables ws_mixed').stdout == 'ws_mixed hello.py\n'
    job = labkit.ros2('run ws_mixed hello.py')
    job.wait(1.0)
    assert any(line.endswith('[hello]: mixed hello') for line in job.output), job.output
