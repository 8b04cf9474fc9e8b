"""The seed's chapter 2-7 terminal session against turtlesim, in virtual time."""
import subprocess
import sys
import textwrap

import pytest

import labkit
from labkit.cli.ros2 import run_command


def ok(command):
    result = run_command(command)
    assert result.returncode == 0, (result.stdout, result.stderr)
    return result.stdout


@pytest.fixture
def turtlesim():
    job = labkit.ros2('run turtlesim turtlesim_node')
    assert job.returncode is None, job.output
    yield job
    labkit.reset()


def test_node_and_topic_verbs(turtlesim):
    assert ok('node list') == '/turtlesim\n'
    info = ok('node info /turtlesim')
    assert info.startswith('/turtlesim\n  Subscribers:\n')
    assert '    /turtle1/cmd_vel: geometry_msgs/msg/Twist\n' in info
    assert '  Action Servers:\n    /turtle1/rotate_absolute: turtlesim/action/RotateAbsolute\n' \
        in info
    assert '/turtle1/pose [turtlesim/msg/Pose]\n' in ok('topic list -t')
    assert ok('topic info /turtle1/cmd_vel') == \
        'Type: geometry_msgs/msg/Twist\nPublisher count: 0\nSubscription count: 1\n'
    pose = ok('topic echo --once /turtle1/pose')
    assert pose.startswith('x: 5.544444561004639\ny: 5.544444561004639\ntheta: 0.0\n')
    assert pose.endswith('---\n')


def test_service_and_action_verbs(turtlesim):
    assert '/spawn [turtlesim/srv/Spawn]\n' in ok('service list -t')
    assert ok('service type /clear') == 'std_srvs/srv/Empty\n'
    assert ok('service find std_srvs/srv/Empty') == '/clear\n/reset\n'
    out = ok('service call /spawn turtlesim/srv/Spawn "{x: 2, y: 2, theta: 0.2, name: \'\'}"')
    assert out == ("requester: making request: turtlesim.srv.Spawn_Request(x=2.0, y=2.0, "
                   "theta=0.2, name='')\n\nresponse:\n"
                   "turtlesim.srv.Spawn_Response(name='turtle2')\n\n")
    assert ok('action list -t') == (
        '/turtle1/rotate_absolute [turtlesim/action/RotateAbsolute]\n'
        '/turtle2/rotate_absolute [turtlesim/action/RotateAbsolute]\n')
    assert ok('action info /turtle1/rotate_absolute') == (
        'Action: /turtle1/rotate_absolute\nAction clients: 0\nAction servers: 1\n'
        '    /turtlesim\n')
    out = ok('action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute '
             '"{theta: -1.57}"')
    assert out.startswith('Waiting for an action server to become available...\n'
                          'Sending goal:\n     theta: -1.57\n\nGoal accepted with ID: ')
    assert out.endswith('\nGoal finished with status: SUCCEEDED\n')


def test_same_goal_ids_on_every_run():
    ids = []
    for _ in range(2):
        labkit.reset()
        from labkit.rclpy.action import _common
        _common.reset_virtual_uuids()
        labkit.ros2('run turtlesim turtlesim_node')
        out = ok('action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute '
                 '"{theta: 1.0}"')
        ids.append([line for line in out.splitlines() if 'Goal accepted' in line])
    labkit.reset()
    assert ids[0] == ids[1] and len(ids[0]) == 1


def test_param_verbs(turtlesim, tmp_path):
    out = ok('param list')
    assert out.startswith('/turtlesim:\n  background_b\n  background_g\n  background_r\n')
    assert ok('param get /turtlesim background_g') == 'Integer value is: 86\n'
    assert ok('param set /turtlesim background_r 150') == 'Set parameter successful\n'
    dump = ok('param dump /turtlesim')
    assert dump.startswith('/turtlesim:\n  ros__parameters:\n    background_b: 255\n'
                           '    background_g: 86\n    background_r: 150\n')
    (tmp_path / 'turtlesim.yaml').write_text(dump.replace('150', '20'))
    out = ok(f'param load /turtlesim {tmp_path / "turtlesim.yaml"}')
    assert 'Set parameter background_r successful\n' in out
    assert ok('param get /turtlesim background_r') == 'Integer value is: 20\n'
    assert ok('param describe /turtlesim background_r').startswith(
        'Parameter name: background_r\n  Type: integer\n')


def test_pub_moves_the_turtle(turtlesim):
    labkit.ros2('topic pub --rate 1 /turtle1/cmd_vel geometry_msgs/msg/Twist '
                '"{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 1.8}}"')
    labkit.sleep(2.0)
    pose = ok('topic echo --once /turtle1/pose --field x')
    assert float(pose.split('\n')[0]) != 5.544444561004639


def test_the_cli_works_in_live_time_too():
    code = textwrap.dedent('''
        import time, labkit
        job = labkit.ros2('run demo_nodes_cpp talker')
        print(labkit.ros2('node list').stdout, end='')
        print(labkit.ros2('topic echo --once /chatter').stdout, end='')
        labkit.ros2('jobs stop all')
        print(repr(labkit.ros2('node list')))
    ''')
    done = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                          timeout=60, env={'LABKIT_TIME': 'live', 'PATH': '/usr/bin:/bin'})
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == '/talker'
    assert lines[1].startswith("data: 'Hello World: ") and lines[2] == '---'
    assert lines[3] == ''


def test_param_load_output_keeps_the_terminal_order(turtlesim, tmp_path):
    labkit.ros2('run turtlesim turtle_teleop_key')
    path = tmp_path / 'turtlesim.yaml'
    path.write_text(ok('param dump /turtlesim'))
    r = run_command(f'param load /turtlesim {path}')
    lines = repr(r).splitlines()
    assert lines[:3] == [f'Set parameter background_{c} successful' for c in 'bgr']
    assert all(line.startswith('Set parameter qos_overrides./parameter_events.publisher.')
               and ' failed: ' in line for line in lines[3:7])
    assert lines[7] == 'Set parameter use_sim_time successful'
    assert r.stderr.count('\n') == 4 and r.stdout.count('\n') == 4
