"""Chapter 21's launch files, taken from the notebook's %%writefile cells and run as the
book runs them: checked through the graph (nodes, namespaces, remappings, parameters)
and through the lines `ros2 launch` prints.
"""
import json
import os
import re

import pytest

import labkit

HERE = os.path.dirname(os.path.abspath(__file__))
NOTEBOOK = os.path.join(HERE, '..', '..', 'book', 'part3_tools', 'ch21_launch.ipynb')


def written_files():
    """{path as written: text} of every %%writefile cell (a later cell wins, as on disk)."""
    with open(NOTEBOOK, encoding='utf-8') as handle:
        cells = json.load(handle)['cells']
    files = {}
    for cell in cells:
        source = ''.join(cell['source'])
        if cell['cell_type'] == 'code' and source.startswith('%%writefile '):
            first, _, body = source.partition('\n')
            files[first.split()[1]] = body + '\n'
    return files


@pytest.fixture
def lab(ws, monkeypatch):
    """launch_lab as colcon installs it (launch/, config/, the index marker), sourced."""
    prefix = ws / 'install' / 'launch_lab'
    share = prefix / 'share' / 'launch_lab'
    for path, text in written_files().items():
        path = path[len('src/'):] if path.startswith('src/') else path
        if path.startswith('launch_lab/'):
            target = share / path[len('launch_lab/'):]
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(text, encoding='utf-8')
    marker = prefix / 'share' / 'ament_index' / 'resource_index' / 'packages'
    marker.mkdir(parents=True)
    (marker / 'launch_lab').write_text('')
    monkeypatch.setenv('AMENT_PREFIX_PATH', str(prefix))
    monkeypatch.setenv('USER', 'student')
    return share


def launch(command):
    job = labkit.ros2(command)
    assert hasattr(job, 'wait'), job.stderr      # a launch that failed at once is no job
    return job


def nodes():
    return sorted(labkit.ros2('node list').stdout.split())


def param(node, name):
    return labkit.ros2(f'param get {node} {name}').stdout.strip()


def started(output):
    """'[INFO] [turtlesim_node-1]: process started with pid [N]' -> ['turtlesim_node-1', ...]"""
    return [m.group(1) for line in output
            for m in [re.match(r'\[INFO\] \[(.+)\]: process started with pid \[\d+\]$', line)]
            if m]


def user_lines(output):
    return [line[len('[INFO] [launch.user]: '):] for line in output
            if line.startswith('[INFO] [launch.user]: ')]


def test_the_notebook_writes_every_file():
    files = written_files()
    assert {'mimic_launch.py', 'chatter_bringup/launch/chatter_launch.py',
            'launch_lab/launch/pond.launch.py', 'launch_lab/launch/pond_main.launch.py',
            'launch_lab/launch/pond_events.launch.py', 'launch_lab/launch/big_pond.launch.py',
            'launch_lab/config/colors.yaml', 'launch_lab/config/frames.rviz'} <= set(files)


def test_mimic_launch_by_path(tmp_path, monkeypatch):
    (tmp_path / 'mimic_launch.py').write_text(written_files()['mimic_launch.py'], encoding='utf-8')
    monkeypatch.chdir(tmp_path)
    job = launch('launch mimic_launch.py')
    labkit.sleep(0.5)
    assert started(job.output) == ['turtlesim_node-1', 'turtlesim_node-2', 'mimic-3']
    assert nodes() == ['/mimic', '/turtlesim1/sim', '/turtlesim2/sim']
    mimic = labkit.ros2('node info /mimic').stdout
    assert '/turtlesim1/turtle1/pose: turtlesim/msg/Pose' in mimic
    assert '/turtlesim2/turtle1/cmd_vel: geometry_msgs/msg/Twist' in mimic
    labkit.ros2('topic pub --once /turtlesim1/turtle1/cmd_vel geometry_msgs/msg/Twist '
                '"{linear: {x: 2.0}}"')
    labkit.sleep(1.5)
    pose = labkit.ros2('topic echo --once /turtlesim2/turtle1/pose').stdout
    assert float(re.search(r'^x: (\S+)', pose, re.M).group(1)) > 6.0, pose
    job.stop()
    assert nodes() == []


def test_pond_arguments_and_condition(lab):
    shown = labkit.ros2('launch launch_lab pond.launch.py --show-args').stdout
    assert "    'pond':\n        no description given\n        (default: 'turtlesim1')\n" in shown
    job = launch('launch launch_lab pond.launch.py')        # use_red False: stays purple
    labkit.sleep(3.0)
    assert nodes() == ['/turtlesim1/sim']
    assert '/turtlesim1/turtle2/pose' in labkit.ros2('topic list').stdout.split()
    assert param('/turtlesim1/sim', 'background_r') == 'Integer value is: 120'
    assert len(started(job.output)) == 3
    job.stop()
    labkit.reset()
    job = launch('launch launch_lab pond.launch.py pond:=turtlesim5 use_red:=True red:=50')
    labkit.sleep(3.0)
    assert param('/turtlesim5/sim', 'background_r') == 'Integer value is: 50'
    assert 'sim background_r 50-4' in started(job.output)
    job.stop()
    labkit.reset()
    job = launch('launch launch_lab pond.launch.py use_red:=True red:=300')   # not a colour
    labkit.sleep(3.0)
    assert param('/turtlesim1/sim', 'background_r') == 'Integer value is: 120'
    job.stop()


def test_pond_main_includes_with_arguments(lab):
    job = launch('launch launch_lab pond_main.launch.py')
    labkit.sleep(1.0)
    assert nodes() == ['/turtlesim2/sim']
    assert param('/turtlesim2/sim', 'background_r') == 'Integer value is: 120'
    labkit.sleep(1.5)       # the TimerAction's 2 s have passed
    assert param('/turtlesim2/sim', 'background_r') == 'Integer value is: 200'
    job.stop()


def test_pond_events_in_order_and_the_window_closing(lab):
    job = launch('launch launch_lab pond_events.launch.py pond:=turtlesim3 use_red:=True '
                 'red:=200')
    labkit.sleep(1.0)
    lines = user_lines(job.output)
    assert lines[0] == 'turtlesim is up: spawning a turtle'
    assert lines[1].startswith('spawn says: requester: making request: ')
    assert lines[-1] == 'spawn done: turning the pond purple'
    out = job.output
    # the spawn command started only once turtlesim had
    assert out.index('[INFO] [launch.user]: turtlesim is up: spawning a turtle') < \
        [i for i, line in enumerate(out) if 'process started' in line and 'Spawn' in line][0]
    labkit.sleep(2.5)
    assert param('/turtlesim3/sim', 'background_r') == 'Integer value is: 200'
    from labkit import process
    next(p for p in process.processes() if p.name == 'turtlesim_node-1').stop()
    job.wait(1.0)
    assert not job.running()
    assert user_lines(job.output)[-2:] == ['student closed the turtlesim window',
                                           'launch is shutting down: the window is gone']
    assert nodes() == []


def test_big_pond(lab):
    shown = labkit.ros2('launch launch_lab big_pond.launch.py --show-args').stdout
    # the included files' arguments are listed: their paths need no launch configuration
    assert "    'target':\n        The frame turtle2 chases.\n        (default: 'turtle1')\n" \
        in shown
    assert "    'background_r':\n        no description given\n        (default: '30')\n" \
        in shown
    assert "    'node_prefix':\n        Text put in front of the node name.\n" \
        "        (default: EnvVar('USER') + '_')\n" in shown
    job = launch('launch launch_lab big_pond.launch.py')
    labkit.sleep(1.0)
    assert started(job.output) == [
        'turtlesim_node-1', 'turtlesim_node-2', 'pose_to_tf-3', 'pose_to_tf-4', 'chaser-5',
        'mimic-6', 'carrot-7', 'rviz2-8']
    assert nodes() == ['/chaser', '/mimic', '/rviz2', '/sim', '/student_carrot',
                       '/turtle1_tf', '/turtle2_tf', '/turtlesim2/sim']
    assert [param('/sim', f'background_{c}') for c in 'rgb'] == [
        'Integer value is: 30', 'Integer value is: 60', 'Integer value is: 110']
    assert [param('/turtlesim2/sim', f'background_{c}') for c in 'rgb'] == [
        'Integer value is: 20', 'Integer value is: 110', 'Integer value is: 80']
    assert param('/chaser', 'target') == 'String value is: carrot1'
    mimic = labkit.ros2('node info /mimic').stdout
    assert '/turtle2/pose: turtlesim/msg/Pose' in mimic
    assert '/turtlesim2/turtle1/cmd_vel: geometry_msgs/msg/Twist' in mimic
    labkit.sleep(1.0)
    from labkit.viz import meshcat_view
    assert sorted(meshcat_view.current().tf_poses()) == ['carrot1', 'turtle1', 'turtle2', 'world']
    job.stop()
    assert nodes() == []


def test_world_3_wildcard_yaml(lab):
    job = launch('launch launch_lab world_3.launch.py')
    labkit.sleep(0.3)
    assert nodes() == ['/turtlesim3/sim']
    assert param('/turtlesim3/sim', 'background_g') == 'Integer value is: 110'
    job.stop()


def test_show_args_skips_an_include_whose_path_needs_a_configuration(lab, tmp_path):
    (tmp_path / 'which.launch.py').write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution\n"
        "from launch_ros.substitutions import FindPackageShare\n\n\n"
        "def generate_launch_description():\n"
        "    chosen = PathJoinSubstitution([FindPackageShare('launch_lab'), 'launch',\n"
        "                                   LaunchConfiguration('file')])\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('file', default_value='pond.launch.py'),\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource(chosen)),\n"
        "    ])\n")
    shown = labkit.ros2(f'launch {tmp_path}/which.launch.py --show-args').stdout
    assert "'file'" in shown and "'pond'" not in shown
