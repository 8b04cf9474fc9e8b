"""An overlay package hides the underlay's executables of the same package.

ros2pkg's get_executable_paths walks <prefix>/lib/<pkg> of the ONE prefix that
ament's get_package_prefix returns (the first on AMENT_PREFIX_PATH that has the
package); ros2run finds executables the same way. So after sourcing a workspace
that builds examples_rclpy_minimal_publisher with one entry point, neither
`ros2 pkg executables` nor `ros2 run` knows publisher_old_school any more.
"""
import facer_ws

import labkit
from labkit.ament import colcon


def _overlay_publisher(ws):
    src = str(ws / 'src')
    facer_ws.python_package(
        src, 'examples_rclpy_minimal_publisher',
        [('publisher_member_function',
          'examples_rclpy_minimal_publisher.publisher_member_function:main')],
        deps=[('exec_depend', 'rclpy')],
        modules={'publisher_member_function': 'def main(args=None):\n    return 0\n'})
    r = colcon.run_command('build --allow-overriding examples_rclpy_minimal_publisher')
    assert r.returncode == 0, r.stderr
    labkit.source('install/setup.bash')


def test_pkg_executables_lists_only_the_overlay_prefix(ws):
    before = labkit.ros2('pkg executables examples_rclpy_minimal_publisher').stdout
    assert 'publisher_old_school' in before
    _overlay_publisher(ws)
    r = labkit.ros2('pkg executables examples_rclpy_minimal_publisher')
    assert r.stdout == 'examples_rclpy_minimal_publisher publisher_member_function\n'
    full = labkit.ros2('pkg executables --full-path examples_rclpy_minimal_publisher').stdout
    assert full.strip().endswith(
        'install/examples_rclpy_minimal_publisher/lib/examples_rclpy_minimal_publisher/'
        'publisher_member_function')
    # the listing of all packages agrees; another underlay package is untouched
    everything = labkit.ros2('pkg executables').stdout.splitlines()
    assert 'examples_rclpy_minimal_publisher publisher_old_school' not in everything
    assert 'examples_rclpy_minimal_subscriber subscriber_old_school' in everything


def test_ros2_run_of_an_underlay_only_executable_fails(ws):
    _overlay_publisher(ws)
    r = labkit.ros2('run examples_rclpy_minimal_publisher publisher_old_school')
    assert r.returncode == 1
    assert r.stderr == 'No executable found\n'
    labkit.reset()
