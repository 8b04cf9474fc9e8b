"""colcon build's executors: which package starts and ends when (virtual time, 2 cores)."""
import facer_ws

from labkit.ament import colcon


def starts_and_ends(result):
    return [line.split(' [')[0] for line in result.stdout.splitlines()
            if line.startswith(('Starting >>> ', 'Finished <<< ', 'Failed   <<< ',
                                'Aborted  <<< '))]


def two_independent(ws, broken=None):
    src = str(ws / 'src')
    for name in ('pkg_a', 'pkg_b'):
        facer_ws.python_package(src, name, [], deps=[('depend', 'rclpy')])
    if broken:
        facer_ws.write(str(ws / 'src' / broken), 'setup.py', 'this is not python\n')


def test_parallel_executor_starts_independent_packages_together(ws):
    two_independent(ws)
    r = colcon.run_command('build')
    assert r.returncode == 0, r.text()
    assert starts_and_ends(r) == ['Starting >>> pkg_a', 'Starting >>> pkg_b',
                                  'Finished <<< pkg_a', 'Finished <<< pkg_b']
    # both ran at the same time: the whole build took about as long as one package
    times = [line.split('[')[1].rstrip(']') for line in r.stdout.splitlines()
             if line.startswith('Finished')]
    assert times[0] == times[1]
    summary = float(r.stdout.split('Summary: 2 packages finished [')[1].split('s]')[0])
    assert summary < 2 * float(times[0].rstrip('s'))


def test_sequential_executor_and_one_worker_keep_one_at_a_time(ws):
    two_independent(ws)
    one_by_one = ['Starting >>> pkg_a', 'Finished <<< pkg_a',
                  'Starting >>> pkg_b', 'Finished <<< pkg_b']
    assert starts_and_ends(colcon.run_command('build --executor sequential')) == one_by_one
    assert starts_and_ends(colcon.run_command('build --parallel-workers 1')) == one_by_one


def test_more_dependents_start_first_and_dependents_wait(facer):
    r = colcon.run_command('build')
    assert starts_and_ends(r) == [
        'Starting >>> facer_interfaces', 'Starting >>> facer_input',
        'Finished <<< facer_input', 'Finished <<< facer_interfaces',
        'Starting >>> facer_detect', 'Finished <<< facer_detect',
        'Starting >>> facer_bringup', 'Finished <<< facer_bringup']


def test_a_failure_aborts_the_package_running_beside_it(ws):
    two_independent(ws, broken='pkg_a')
    r = colcon.run_command('build')
    assert r.returncode != 0
    assert starts_and_ends(r) == ['Starting >>> pkg_a', 'Starting >>> pkg_b',
                                  'Failed   <<< pkg_a', 'Aborted  <<< pkg_b']
    assert '  1 package failed: pkg_a\n  1 package aborted: pkg_b\n' in r.stdout
    r = colcon.run_command('build --continue-on-error')
    assert starts_and_ends(r) == ['Starting >>> pkg_a', 'Starting >>> pkg_b',
                                  'Failed   <<< pkg_a', 'Finished <<< pkg_b']


def test_desktop_examples_are_overridden_with_a_warning(ws):
    # ros-humble-desktop depends on examples_rclpy_minimal_*: building one warns
    src = str(ws / 'src')
    for name in ('examples_rclpy_minimal_publisher', 'examples_rclpy_minimal_subscriber'):
        facer_ws.python_package(src, name, [], deps=[('exec_depend', 'rclpy')])
    r = colcon.run_command('build')
    assert r.returncode == 0
    assert ("WARNING:colcon.colcon_core.package_selection:Some selected packages are "
            "already built in one or more underlay workspaces:\n"
            "\t'examples_rclpy_minimal_publisher' is in: /opt/ros/humble\n"
            "\t'examples_rclpy_minimal_subscriber' is in: /opt/ros/humble\n") in r.stderr
    assert ('\n\t--allow-overriding examples_rclpy_minimal_publisher '
            'examples_rclpy_minimal_subscriber\n') in r.stderr
    r = colcon.run_command('build --allow-overriding examples_rclpy_minimal_publisher '
                           'examples_rclpy_minimal_subscriber')
    assert 'underlay workspaces' not in r.stderr


def test_desktop_examples_run_from_the_binary_install():
    import labkit
    r = labkit.ros2('pkg executables examples_rclpy_minimal_publisher')
    assert r.stdout.splitlines() == [
        'examples_rclpy_minimal_publisher publisher_local_function',
        'examples_rclpy_minimal_publisher publisher_member_function',
        'examples_rclpy_minimal_publisher publisher_old_school']
    assert labkit.ros2('pkg prefix examples_rclpy_minimal_subscriber').stdout == \
        '/opt/ros/humble\n'
    pub = labkit.ros2('run examples_rclpy_minimal_publisher publisher_member_function')
    sub = labkit.ros2('run examples_rclpy_minimal_subscriber subscriber_lambda')
    labkit.sleep(1.6)
    assert any(line.endswith('[minimal_publisher]: Publishing: "Hello World: 1"')
               for line in pub.output), pub.output
    assert any(line.endswith('[minimal_subscriber]: I heard: "Hello World: 1"')
               for line in sub.output), sub.output
    pub.stop()
    sub.stop()
    labkit.reset()
