"""ros2 launch: python launch files run unchanged, nodes start as labkit processes."""
import os

import labkit
from labkit.ament import colcon, source

SPIN_LAUNCH = '''from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, LogInfo, TimerAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='sim'),
        DeclareLaunchArgument('with_talker', default_value='true'),
        Node(package='turtlesim', executable='turtlesim_node', name='sim',
             namespace=LaunchConfiguration('ns'),
             parameters=[{'background_r': 10}],
             remappings=[('turtle1/cmd_vel', 'cmd')]),
        GroupAction([
            Node(package='demo_nodes_py', executable='talker', output='screen'),
        ], condition=IfCondition(LaunchConfiguration('with_talker'))),
        TimerAction(period=1.0, actions=[LogInfo(msg='one second later')]),
    ])
'''


def finished_lines(result):
    """A launch that fails at once ends like a short command; otherwise it is a job."""
    if hasattr(result, 'wait'):
        result.wait(2.0)
        return result.output
    return result.text().splitlines()


def built(facer):
    assert colcon.run_command('build').returncode == 0
    assert source.run('install/setup.bash') == 0


def test_launch_package_file_with_arguments_and_parameters(facer):
    built(facer)
    job = labkit.ros2('launch facer_bringup facer.launch.py camera:=usb1')
    job.wait(2.0)
    out = job.output
    # virtual time: the log folder's date is the simulated clock's, the host 'labkit'
    assert out[0].startswith('[INFO] [launch]: All log files can be found below ')
    assert out[0].endswith(os.path.join('', '.ros', 'log',
                                        f'2024-01-01-00-00-00-000000-labkit-{job.pid}'))
    assert out[1] == '[INFO] [launch]: Default logging verbosity is set to INFO'
    pid1 = out[2].split('[')[-1].rstrip(']')
    assert out[2] == f'[INFO] [capture_image-1]: process started with pid [{pid1}]'
    assert out[3].startswith('[INFO] [detect_face-2]: process started with pid [')
    # the command-line argument beats the YAML file, which beats the declared default
    assert any(line.startswith('[capture_image-1] [INFO] [') and
               line.endswith('[capture_image]: VERSION 1 camera=usb1') for line in out), out
    assert f'[INFO] [capture_image-1]: process has finished cleanly [pid {pid1}]' in out
    assert job.returncode == 0


def test_yaml_parameters_when_argument_not_given(facer):
    built(facer)
    path = facer / 'src/facer_bringup/launch/facer.launch.py'
    path.write_text(path.read_text().replace(", {'camera': LaunchConfiguration('camera')}", ''))
    assert colcon.run_command('build --packages-select facer_bringup').returncode == 0
    job = labkit.ros2('launch facer_bringup facer.launch.py')
    job.wait(2.0)
    assert any(line.endswith('camera=from_yaml') for line in job.output), job.output


def test_launch_a_path_runs_until_stopped(ws, tmp_path):
    launch_file = tmp_path / 'sim.launch.py'
    launch_file.write_text(SPIN_LAUNCH)
    job = labkit.ros2(f'launch {launch_file} ns:=lab')
    assert job.running()
    labkit.sleep(0.5)
    nodes = labkit.ros2('node list').stdout.split()
    assert '/lab/sim' in nodes and '/talker' in nodes
    topics = labkit.ros2('topic list').stdout.split()
    assert '/lab/cmd' in topics                       # the remapping applied
    param = labkit.ros2('param get /lab/sim background_r').stdout
    assert param == 'Integer value is: 10\n'
    assert not any('one second later' in line for line in job.output)
    labkit.sleep(1.0)
    assert '[INFO] [launch.user]: one second later' in job.output
    assert any(line.startswith('[talker-2] [INFO] [') for line in job.output)
    job.stop()
    out = job.output
    assert '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)' in out
    assert any(line.startswith('[INFO] [turtlesim_node-1]: process has finished cleanly')
               for line in out), out
    assert labkit.ros2('node list').stdout == ''


def test_condition_false_skips_group(ws, tmp_path):
    launch_file = tmp_path / 'sim.launch.py'
    launch_file.write_text(SPIN_LAUNCH)
    job = labkit.ros2(f'launch {launch_file} with_talker:=false')
    labkit.sleep(0.2)
    assert '/talker' not in labkit.ros2('node list').stdout.split()
    job.stop()


def test_show_args_and_errors(facer):
    built(facer)
    r = labkit.ros2('launch facer_bringup facer.launch.py --show-args')
    assert r.stdout == ("Arguments (pass arguments as '<name>:=<value>'):\n\n"
                        "    'camera':\n        no description given\n"
                        "        (default: 'cam0')\n")
    r = labkit.ros2('launch facer_bringup nosuch.launch.py')
    assert r.returncode == 1
    assert r.stderr.startswith("file 'nosuch.launch.py' was not found in the share directory "
                               "of package 'facer_bringup' which is at '")
    r = labkit.ros2('launch nosuch_pkg x.launch.py')
    assert r.stderr.startswith("Package 'nosuch_pkg' not found: \"package 'nosuch_pkg' not "
                               "found, searching: [")


def test_missing_executable_and_required_argument(ws, tmp_path):
    bad = tmp_path / 'bad.launch.py'
    bad.write_text(SPIN_LAUNCH.replace("executable='turtlesim_node'", "executable='nope'"))
    result = labkit.ros2(f'launch {bad}')
    out = finished_lines(result)
    assert any("[ERROR] [launch]: Caught exception in launch (see debug for traceback): "
               "executable 'nope' not found on the libexec directory "
               "'/opt/ros/humble/lib/turtlesim'" in line for line in out), out
    assert result.returncode == 1
    required = tmp_path / 'req.launch.py'
    required.write_text(SPIN_LAUNCH.replace("DeclareLaunchArgument('ns', default_value='sim')",
                                            "DeclareLaunchArgument('ns')"))
    out = finished_lines(labkit.ros2(f'launch {required}'))
    assert any("Included launch description missing required argument 'ns'" in line
               for line in out), out


def test_find_package_share_and_include(facer, tmp_path):
    built(facer)
    top = tmp_path / 'top.launch.py'
    top.write_text('''from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(PathJoinSubstitution(
                [FindPackageShare('facer_bringup'), 'launch', 'facer.launch.py'])),
            launch_arguments={'camera': 'included'}.items()),
    ])
''')
    job = labkit.ros2(f'launch {top}')
    job.wait(2.0)
    assert any(line.endswith('camera=included') for line in job.output), job.output


def test_died_process_is_reported(facer):
    path = facer / 'src/facer_input/facer_input/capture_image.py'
    path.write_text(path.read_text().replace('    node.destroy_node()',
                                             '    raise SystemExit(3)'))
    built(facer)
    job = labkit.ros2('launch facer_bringup facer.launch.py')
    job.wait(2.0)
    died = [line for line in job.output if 'process has died' in line]
    assert len(died) == 1 and died[0].startswith('[ERROR] [capture_image-1]: process has died '
                                                 '[pid ')
    assert ', exit code 3, cmd \'' in died[0]
    # the executable's real path, written as the OS writes it
    assert os.path.join('', 'install', 'facer_input', 'lib', 'facer_input', 'capture_image') + \
        ' --ros-args -r __node:=capture_image --params-file ' in died[0]


COMMAND_LAUNCH = '''from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('word', default_value='42'),
        Node(package='turtlesim', executable='turtlesim_node',
             parameters=[{'background_r': Command(['lk_shout ', LaunchConfiguration('word')]),
                          'background_g': ParameterValue(Command('lk_shout 7'))}]),
    ])
'''


def shout(args=None):
    word = args[1]
    if word == 'fail':
        import sys
        sys.stderr.write('no\n')
        return 3
    print(word.upper(), end='')
    return 0


def test_command_substitution_and_parameter_value(ws, tmp_path, monkeypatch):
    from labkit import executables
    monkeypatch.setitem(executables._extra, ('lk_tools', 'lk_shout'),
                        'test_launch:shout')
    launch_file = tmp_path / 'cmd.launch.py'
    launch_file.write_text(COMMAND_LAUNCH)
    job = labkit.ros2(f'launch {launch_file}')
    labkit.sleep(0.2)
    # a command's output is read as YAML: '42' becomes an integer parameter
    assert labkit.ros2('param get /turtlesim background_r').stdout == 'Integer value is: 42\n'
    assert labkit.ros2('param get /turtlesim background_g').stdout == 'Integer value is: 7\n'
    job.stop()
    # value_type=str keeps the text as it is
    from launch import LaunchContext
    from launch.substitutions import Command
    from launch_ros.parameter_descriptions import ParameterValue

    class Service:
        pass
    context = LaunchContext()
    context.launch_service = Service()
    assert ParameterValue(Command('lk_shout 007'), value_type=str).evaluate(context) == '007'
    assert ParameterValue(Command('lk_shout 007')).evaluate(context) == 7
    out = finished_lines(labkit.ros2(f'launch {launch_file} word:=fail'))
    assert any('executed command failed. Command: lk_shout fail' in line for line in out), out


def test_bundled_prefixes_and_shown_paths(ws):
    from labkit.ament import index
    from ament_index_python.packages import get_package_share_directory
    share = get_package_share_directory('turtlesim')
    assert share.replace(os.sep, '/').endswith('/labkit/ament/prefix/share/turtlesim')
    assert index.shown(share) == '/opt/ros/humble/share/turtlesim'
    assert index.shown(get_package_share_directory('std_msgs')) == \
        '/opt/ros/humble/share/std_msgs'
