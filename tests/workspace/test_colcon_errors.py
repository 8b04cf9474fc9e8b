"""What goes wrong in a workspace fails like colcon, CMake, rosidl or Python would say."""
import labkit
from labkit.ament import colcon, source


def build(command='build'):
    return colcon.run_command(command)


def edit(path, old, new):
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new))


def test_type_not_in_dependencies_fails_in_rosidl(facer):
    edit(facer / 'src/facer_interfaces/CMakeLists.txt', 'DEPENDENCIES geometry_msgs', '')
    r = build()
    assert r.returncode == 2
    assert '--- stderr: facer_interfaces\n' in r.stderr
    assert ("Message interface 'facer_interfaces/Face' contains an unknown field type: "
            "geometry_msgs/Point center") in r.stderr
    assert 'Failed   <<< facer_interfaces [' in r.stdout
    assert ', exited with code 2]' in r.stdout
    tail = r.stdout.split('Summary: ')[1]
    # facer_input has no dependency on the interfaces: it was built before them
    assert tail.startswith('1 package finished')
    assert '  1 package failed: facer_interfaces' in tail
    assert '  2 packages had stderr output: facer_input facer_interfaces' in tail
    assert '  2 packages not processed' in tail


def test_unknown_type_in_msg(facer):
    (facer / 'src/facer_interfaces/msg/Face.msg').write_text('Pointy center\n')
    r = build('build --packages-select facer_interfaces')
    assert ("contains an unknown field type: facer_interfaces/Pointy center") in r.stderr
    assert r.returncode


def test_dependency_not_found_before_find_package(facer):
    edit(facer / 'src/facer_interfaces/CMakeLists.txt', 'find_package(geometry_msgs REQUIRED)',
         '')
    r = build('build --packages-select facer_interfaces')
    assert 'CMake Error at /opt/ros/humble/share/rosidl_cmake/cmake/' \
        'rosidl_generate_interfaces.cmake:162 (message):\n' in r.stderr
    assert ' '.join(r.stderr.split()).count(
        "rosidl_generate_interfaces() the passed dependency 'geometry_msgs' has not been "
        "found before using find_package()") == 1
    assert 'Call Stack (most recent call first):\n  CMakeLists.txt:8 ' \
        '(rosidl_generate_interfaces)\n' in r.stderr


def test_unknown_package_in_find_package(facer):
    edit(facer / 'src/facer_interfaces/CMakeLists.txt', 'find_package(geometry_msgs REQUIRED)',
         'find_package(geometry_msg REQUIRED)')
    r = build('build --packages-select facer_interfaces')
    assert 'CMake Error at CMakeLists.txt:5 (find_package):' in r.stderr
    assert 'Could not find a package configuration file provided by "geometry_msg"' in r.stderr


def test_missing_generators_and_group(facer):
    cm = facer / 'src/facer_interfaces/CMakeLists.txt'
    edit(cm, 'find_package(rosidl_default_generators REQUIRED)', '')
    r = build('build --packages-select facer_interfaces')
    assert 'Unknown CMake command "rosidl_generate_interfaces".' in r.stderr
    edit(cm, 'find_package(geometry_msgs REQUIRED)',
         'find_package(geometry_msgs REQUIRED)\nfind_package(rosidl_default_generators REQUIRED)')
    edit(facer / 'src/facer_interfaces/package.xml',
         '<member_of_group>rosidl_interface_packages</member_of_group>', '')
    r = build('build --packages-select facer_interfaces')
    assert ("Packages installing interfaces must include "
            "'<member_of_group>rosidl_interface_packages</member_of_group>' in their "
            "package.xml") in ' '.join(r.stderr.split())
    assert 'rosidl_generate_interfaces.cmake:229 (message):' in r.stderr


def test_missing_interface_file(facer):
    (facer / 'src/facer_interfaces/srv/FaceResult.srv').unlink()
    r = build('build --packages-select facer_interfaces')
    assert "rosidl_generate_interfaces() the passed file 'srv/FaceResult.srv' doesn't" \
        in ' '.join(r.stderr.split())
    assert 'rosidl_generate_interfaces.cmake:93 (message):' in r.stderr


def test_without_ament_package_the_index_does_not_know_it(facer):
    edit(facer / 'src/facer_interfaces/CMakeLists.txt', 'ament_package()', '')
    r = build('build --packages-select facer_interfaces')
    assert r.returncode == 0 and r.stderr == ''     # like CMake: no error, nothing registered
    source.run('install/setup.bash')
    from labkit.ament import index
    assert 'facer_interfaces' not in index.package_names()
    from ament_index_python.packages import PackageNotFoundError, get_package_prefix
    try:
        get_package_prefix('facer_interfaces')
    except PackageNotFoundError:
        pass
    else:
        raise AssertionError('found without ament_package()')
    # the interfaces themselves were generated and installed
    from facer_interfaces.msg import Face
    assert Face().radius == 0.0


def test_setup_py_that_raises(facer):
    edit(facer / 'src/facer_input/setup.py', "package_name = 'facer_input'",
         "package_name = 'facer_input'\nraise ValueError('oops in setup')")
    r = build('build --packages-select facer_input')
    assert r.returncode == 1
    assert 'File "setup.py", line 6, in <module>' in r.stderr
    assert 'ValueError: oops in setup' in r.stderr
    assert 'Failed   <<< facer_input' in r.stdout


def test_missing_marker_and_manifest_warn_like_colcon_ros(facer):
    edit(facer / 'src/facer_input/setup.py',
         "        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),\n"
         "        ('share/' + package_name, ['package.xml']),\n", '')
    r = build('build --packages-select facer_input')
    assert r.returncode == 0
    assert ("WARNING:colcon.colcon_ros.task.ament_python.build:Package 'facer_input' doesn't "
            "explicitly install a marker in the package index (colcon-ros currently does it "
            "implicitly but that fallback will be removed in the future)") in r.stderr
    assert "doesn't explicitly install the 'package.xml' file" in r.stderr
    assert (facer / 'install/facer_input/share/facer_input/package.xml').is_file()


def test_scripts_without_setup_cfg_land_in_bin(facer):
    (facer / 'src/facer_input/setup.cfg').unlink()
    assert build('build --packages-select facer_input').returncode == 0
    assert (facer / 'install/facer_input/bin/capture_image').is_file()
    source.run('install/setup.bash')
    r = labkit.ros2('run facer_input capture_image')
    assert r.returncode == 1 and r.stderr == 'No executable found\n'


def test_console_script_to_missing_module_fails_at_run_time(facer):
    edit(facer / 'src/facer_input/setup.py', 'facer_input.capture_image:main',
         'facer_input.capture:main')
    assert build('build --packages-select facer_input').returncode == 0
    source.run('install/setup.bash')
    r = labkit.ros2('run facer_input capture_image')
    assert r.returncode == 1
    assert "ModuleNotFoundError: No module named 'facer_input.capture'" in r.stderr


def test_dependency_cycle(facer):
    edit(facer / 'src/facer_interfaces/package.xml', '<depend>geometry_msgs</depend>',
         '<depend>geometry_msgs</depend>\n  <depend>facer_detect</depend>')
    r = build()
    assert r.returncode == 1
    assert 'ERROR:colcon:colcon build: Unable to order packages topologically:\n' \
        "facer_bringup: ['facer_detect', 'facer_interfaces']\n" \
        "facer_detect: ['facer_detect', 'facer_interfaces']\n" in r.stderr


def test_duplicate_package_names(facer):
    import shutil
    shutil.copytree(facer / 'src/facer_input', facer / 'src/copy/facer_input')
    r = build()
    assert r.returncode == 1
    assert 'Duplicate package names not supported:\n- facer_input:\n' in r.stderr


def test_continue_on_error_builds_the_rest(facer):
    edit(facer / 'src/facer_interfaces/CMakeLists.txt', 'DEPENDENCIES geometry_msgs', '')
    r = build('build --continue-on-error')
    started = [line.split()[-1] for line in r.stdout.splitlines() if line.startswith('Start')]
    # more dependents start first; the rest needs the interfaces
    assert started == ['facer_interfaces', 'facer_input']
    assert '  2 packages not processed' in r.stdout


def test_cmake_args_pass_through_and_test_verb_exists(facer):
    r = build('build --cmake-args -DBUILD_TESTING=0 --packages-select facer_interfaces')
    assert r.returncode == 0, r.text()
    r = colcon.run_command('test --packages-select facer_interfaces')    # colcon_test.py
    assert r.returncode == 0 and 'Summary: 1 package finished' in r.stdout
    r = colcon.run_command('')
    assert r.returncode == 1 and r.stderr == 'Error: No verb provided\n'
    assert r.stdout.startswith('usage: colcon')


def test_invalid_manifest_is_skipped_with_colcons_warning(facer):
    path = facer / 'src/facer_detect/package.xml'
    path.write_text(path.read_text() + '<depend>stray</depend>\n')
    r = build('build --packages-up-to facer_detect')
    assert ("WARNING:colcon.colcon_core.package_identification:Failed to parse ROS package "
            "manifest in 'src/facer_detect': Error(s) in package "
            "'src/facer_detect/package.xml':\nThe manifest contains invalid XML:\n"
            "junk after document element: line ") in r.stderr
    assert "ignoring unknown package 'facer_detect' in --packages-up-to" in r.stderr
    assert 'Summary: 0 packages finished' in r.stdout
