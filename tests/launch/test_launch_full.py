"""The rest of launch: choices, namespaces, commands, event handlers, shutdown reasons."""
import labkit

HEAD = '''from launch import LaunchDescription
from launch.actions import *  # noqa
from launch.conditions import *  # noqa
from launch.event_handlers import *  # noqa
from launch.events import Shutdown
from launch.substitutions import *  # noqa
from launch_ros.actions import Node, PushRosNamespace
'''


def write(tmp_path, body, name='t.launch.py'):
    path = tmp_path / name
    path.write_text(HEAD + '\n\ndef generate_launch_description():\n' + body)
    return path


def finished_lines(result):
    """A launch that fails at once ends like a short command; otherwise it is a job."""
    if hasattr(result, 'wait'):
        result.wait(2.0)
        return result.output
    return result.text().splitlines()


def user_lines(output):
    return [line[len('[INFO] [launch.user]: '):] for line in output
            if line.startswith('[INFO] [launch.user]: ')]


def test_choices_in_show_args_and_refused_value(ws, tmp_path):
    path = write(tmp_path, '''    return LaunchDescription([
        DeclareLaunchArgument('color', default_value='red', choices=['red', 'blue'],
                              description='Pen color'),
        DeclareLaunchArgument('mode', default_value='a', choices=['a', 'b']),
        LogInfo(msg=['color is ', LaunchConfiguration('color')]),
    ])
''')
    r = labkit.ros2(f'launch {path} --show-args')
    assert r.stdout == (
        "Arguments (pass arguments as '<name>:=<value>'):\n\n"
        "    'color':\n        Pen color. Valid choices are: ['red', 'blue']\n"
        "        (default: 'red')\n\n"
        "    'mode':\n        One of: ['a', 'b']\n        (default: 'a')\n")
    out = finished_lines(labkit.ros2(f'launch {path} color:=green'))
    assert out[-2:] == [
        '[ERROR] [launch]: Argument "color" provided value "green" is not valid. Valid options '
        "are: ['red', 'blue']",
        '[ERROR] [launch]: Caught exception in launch (see debug for traceback): Argument '
        '"color" provided value "green" is not valid. Valid options are: [\'red\', \'blue\']']
    job = labkit.ros2(f'launch {path} color:=blue')
    job.wait(1.0)
    assert user_lines(job.output) == ['color is blue']


def test_namespaces_are_scoped_and_nest(ws, tmp_path):
    path = write(tmp_path, '''    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot'),
            Node(package='turtlesim', executable='turtlesim_node', name='a'),
            Node(package='turtlesim', executable='turtlesim_node', name='b', namespace='arm'),
            Node(package='turtlesim', executable='turtlesim_node', name='c',
                 namespace='/top'),
            GroupAction([PushRosNamespace('inner'),
                         Node(package='turtlesim', executable='turtlesim_node', name='d')]),
        ]),
        Node(package='turtlesim', executable='turtlesim_node', name='e'),
    ])
''')
    job = labkit.ros2(f'launch {path}')
    labkit.sleep(0.2)
    assert sorted(labkit.ros2('node list').stdout.split()) == [
        '/e', '/robot/a', '/robot/arm/b', '/robot/inner/d', '/top/c']
    job.stop()


def test_conditions_and_environment(ws, tmp_path):
    path = write(tmp_path, '''    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='sim'),
        SetEnvironmentVariable('LABKIT_LAUNCH_TEST', 'set by launch'),
        GroupAction([
            SetEnvironmentVariable('LABKIT_LAUNCH_TEST', 'in the group'),
            LogInfo(msg=EnvironmentVariable('LABKIT_LAUNCH_TEST')),
        ]),
        LogInfo(msg=EnvironmentVariable('LABKIT_LAUNCH_TEST')),
        LogInfo(msg='if', condition=IfCondition(PythonExpression(["'",
                LaunchConfiguration('mode'), "' == 'sim'"]))),
        LogInfo(msg='unless', condition=UnlessCondition('true')),
        LogInfo(msg='equals', condition=LaunchConfigurationEquals('mode', 'real')),
        LogInfo(msg=PathJoinSubstitution(['a', LaunchConfiguration('mode'), 'c'])),
        LogInfo(msg=LaunchConfiguration('undeclared', default='fallback')),
        LogInfo(msg=TextSubstitution(text='text')),
    ])
''')
    import os
    job = labkit.ros2(f'launch {path}')
    job.wait(1.0)
    # PathJoinSubstitution joins with the OS's separator, as launch's does
    assert user_lines(job.output) == ['in the group', 'set by launch', 'if',
                                      os.path.join('a', 'sim', 'c'),
                                      'fallback', 'text']
    assert 'LABKIT_LAUNCH_TEST' not in os.environ      # the launch's environment ended with it
    job = labkit.ros2(f'launch {path} mode:=real')
    job.wait(1.0)
    assert user_lines(job.output) == ['in the group', 'set by launch', 'equals',
                                      os.path.join('a', 'real', 'c'), 'fallback', 'text']


def test_execute_process_forms_and_idle_shutdown(ws, tmp_path):
    path = write(tmp_path, '''    talker = ExecuteProcess(cmd=['ros2', 'run', 'demo_nodes_py', 'talker'],
                            name='my_talker',
                            output='screen')
    topics = ExecuteProcess(cmd=[[FindExecutable(name='ros2'), ' topic list']], shell=True,
                            output='screen')
    return LaunchDescription([
        talker,
        RegisterEventHandler(OnProcessStart(target_action=talker, on_start=[
            TimerAction(period=1.5, actions=[topics])])),
        RegisterEventHandler(OnExecutionComplete(target_action=topics, on_completion=[
            LogInfo(msg='listed'), EmitEvent(event=Shutdown(reason='enough'))])),
        RegisterEventHandler(OnProcessExit(target_action=talker, on_exit=lambda event, ctx:
            LogInfo(msg='talker exited with {}'.format(event.returncode)))),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(
            msg=['shutdown: ', LocalSubstitution('event.reason')])])),
    ])
''')
    job = labkit.ros2(f'launch {path}')
    labkit.sleep(2.0)
    assert not job.running()
    out = job.output
    assert out[2].startswith('[INFO] [my_talker-1]: process started with pid [')
    # the name of a shell command is the basename of its first piece, as launch makes it
    assert any(line.startswith('[INFO] [ros2 topic list-2]: process started') for line in out)
    assert '[ros2 topic list-2] /chatter' in out
    assert any(line.startswith('[my_talker-1] [INFO] [') and 'Publishing: "Hello World: 0"'
               in line for line in out), out
    assert user_lines(out) == ['listed', 'shutdown: enough', 'talker exited with 0']
    # a Shutdown event (not Ctrl-C): launch itself sends SIGINT, and says so
    assert "[INFO] [my_talker-1]: sending signal 'SIGINT' to process[my_talker-1]" in out
    assert out.index("[INFO] [my_talker-1]: sending signal 'SIGINT' to process[my_talker-1]") \
        < out.index('[INFO] [launch.user]: talker exited with 0')
    assert labkit.ros2('node list').stdout == ''
    # a launch with nothing left to run ends by itself: shutdown reason 'idle'
    path = write(tmp_path, '''    return LaunchDescription([
        LogInfo(msg='only a log'),
        RegisterEventHandler(OnShutdown(on_shutdown=lambda event, context: LogInfo(
            msg='reason: ' + event.reason))),
    ])
''', name='idle.launch.py')
    job = labkit.ros2(f'launch {path}')
    job.wait(1.0)
    assert user_lines(job.output) == ['only a log', 'reason: idle']


def test_execute_process_refuses_unknown_programs(ws, tmp_path):
    path = write(tmp_path, '''    return LaunchDescription([
        ExecuteProcess(cmd=['gedit', 'notes.txt']),
    ])
''')
    out = finished_lines(labkit.ros2(f'launch {path}'))
    assert any("Caught exception in launch (see debug for traceback): labkit can only "
               "launch `ros2 ...` commands and ROS executables, not 'gedit notes.txt'" in line
               for line in out), out


def test_process_io_targets_only_its_action(ws, tmp_path):
    path = write(tmp_path, '''    one = ExecuteProcess(cmd=['ros2', 'param', 'list', '/nobody'])
    two = ExecuteProcess(cmd=['ros2', 'node', 'list'], name='lister')
    return LaunchDescription([
        one, two,
        RegisterEventHandler(OnProcessIO(target_action=one, on_stderr=lambda event: LogInfo(
            msg='one said: ' + event.text.decode().strip()))),
        RegisterEventHandler(OnProcessIO(target_action=two, on_stdout=lambda event: LogInfo(
            msg='two said: [' + event.text.decode().strip() + ']'))),
    ])
''')
    job = labkit.ros2(f'launch {path}')
    job.wait(2.0)
    lines = user_lines(job.output)
    assert lines == ['one said: Node not found'], job.output
    died = [line for line in job.output if 'process has died' in line]
    assert len(died) == 1 and died[0].startswith('[ERROR] [ros2-1]: process has died [pid ')
    assert died[0].endswith(", exit code 1, cmd 'ros2 param list /nobody'].")
    assert any(line.startswith('[INFO] [lister-2]: process started') for line in job.output)


def test_execute_process_runs_an_executable_by_path(ws, tmp_path):
    path = write(tmp_path, '''    return LaunchDescription([
        ExecuteProcess(cmd=['/opt/ros/humble/lib/demo_nodes_py/listener'], output='screen'),
        ExecuteProcess(cmd=['/opt/ros/humble/lib/demo_nodes_cpp/talker', '--ros-args', '-r',
                            '__node:=speaker']),
    ])
''')
    job = labkit.ros2(f'launch {path}')
    labkit.sleep(1.5)
    assert sorted(labkit.ros2('node list').stdout.split()) == ['/listener', '/speaker']
    assert any(line.startswith('[listener-1] [INFO] [') and 'I heard: [Hello World: 1]' in line
               for line in job.output), job.output
    job.stop()
