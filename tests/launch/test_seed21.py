"""Chapter 21's launch files (tests/launch/seed21), run as the book runs them.

Each one is checked through the graph (nodes, namespaces, remappings, parameters)
and through the console lines `ros2 launch` prints.
"""
import re

import labkit


def launch(command):
    job = labkit.ros2(command)
    assert hasattr(job, 'wait'), job.stderr      # a launch that failed at once is no job
    return job


def nodes():
    return labkit.ros2('node list').stdout.split()


def param(node, name):
    return labkit.ros2(f'param get {node} {name}').stdout.strip()


def info(node):
    return labkit.ros2(f'node info {node}').stdout


def started(output):
    """'[INFO] [turtlesim_node-1]: process started with pid [N]' -> ['turtlesim_node-1', ...]"""
    return [m.group(1) for line in output
            for m in [re.match(r'\[INFO\] \[(.+)\]: process started with pid \[\d+\]$', line)]
            if m]


def user_lines(output):
    return [line[len('[INFO] [launch.user]: '):] for line in output
            if line.startswith('[INFO] [launch.user]: ')]


def test_turtlesim_mimic_launch_by_path(tutorial, monkeypatch):
    monkeypatch.chdir(tutorial + '/launch')
    job = launch('launch turtlesim_mimic_launch.py')
    labkit.sleep(0.5)
    assert job.output[1] == '[INFO] [launch]: Default logging verbosity is set to INFO'
    assert started(job.output) == ['turtlesim_node-1', 'turtlesim_node-2', 'mimic-3']
    assert sorted(nodes()) == ['/mimic', '/turtlesim1/sim', '/turtlesim2/sim']
    mimic = info('/mimic')
    assert '/turtlesim1/turtle1/pose: turtlesim/msg/Pose' in mimic
    assert '/turtlesim2/turtle1/cmd_vel: geometry_msgs/msg/Twist' in mimic
    # driving turtle 1 moves turtle 2 through the mimic
    labkit.ros2('topic pub --once /turtlesim1/turtle1/cmd_vel geometry_msgs/msg/Twist '
                '"{linear: {x: 2.0}}"')
    labkit.sleep(1.5)
    pose = labkit.ros2('topic echo --once /turtlesim2/turtle1/pose').stdout
    x = float(re.search(r'^x: (\S+)', pose, re.M).group(1))
    assert x > 6.0, pose
    job.stop()
    assert job.output.count('[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)') == 1
    assert nodes() == []


def test_my_script_launch_talker(tutorial):
    job = launch('launch launch_tutorial my_script_launch.py')
    labkit.sleep(1.5)
    assert started(job.output) == ['talker-1']
    assert nodes() == ['/talker']
    assert '/chatter: std_msgs/msg/String' in info('/talker')
    job.stop()


def test_example_main_includes_substitutions(tutorial):
    job = launch('launch launch_tutorial example_main.launch.py')
    labkit.sleep(1.0)
    assert nodes() == ['/turtlesim2/sim']
    assert started(job.output) == ['turtlesim_node-1', 'Spawn "{x: 2, y: 2, theta: 0.2}"-2',
                                   'sim background_r 120-3']
    # the ExecuteProcess commands ran: a second turtle, a purple background
    assert '/turtlesim2/turtle2/pose' in labkit.ros2('topic list').stdout.split()
    assert param('/turtlesim2/sim', 'background_r') == 'Integer value is: 120'
    labkit.sleep(1.5)       # the TimerAction's 2 s have passed: the conditioned command
    assert param('/turtlesim2/sim', 'background_r') == 'Integer value is: 200'
    assert 'sim background_r 200-4' in started(job.output)
    assert any(line.startswith('[INFO] [sim background_r 200-4]: process has finished cleanly')
               for line in job.output)
    job.stop()


def test_example_substitutions_arguments(tutorial):
    r = labkit.ros2('launch launch_tutorial example_substitutions.launch.py --show-args')
    assert r.stdout == (
        "Arguments (pass arguments as '<name>:=<value>'):\n\n"
        "    'turtlesim_ns':\n        no description given\n        (default: 'turtlesim1')\n\n"
        "    'use_provided_red':\n        no description given\n        (default: 'False')\n\n"
        "    'new_background_r':\n        no description given\n        (default: '200')\n")
    # defaults: use_provided_red is False, so the background stays at 120
    job = launch('launch launch_tutorial example_substitutions.launch.py')
    labkit.sleep(3.0)
    assert nodes() == ['/turtlesim1/sim']
    assert param('/turtlesim1/sim', 'background_r') == 'Integer value is: 120'
    assert len(started(job.output)) == 3
    job.stop()
    labkit.reset()
    job = launch("launch launch_tutorial example_substitutions.launch.py "
                 "turtlesim_ns:='turtlesim3' use_provided_red:='True' new_background_r:=200")
    labkit.sleep(3.0)
    assert nodes() == ['/turtlesim3/sim']
    assert param('/turtlesim3/sim', 'background_r') == 'Integer value is: 200'
    job.stop()


def test_event_handlers_fire_in_order(tutorial):
    job = launch("launch launch_tutorial example_event_handlers.launch.py "
                 "turtlesim_ns:='turtlesim3' use_provided_red:='True' new_background_r:=200")
    labkit.sleep(1.0)
    assert user_lines(job.output) == [
        'Turtlesim started, spawning turtle',
        'Spawn request says "requester: making request: turtlesim.srv.Spawn_Request(x=2.0, '
        "y=2.0, theta=0.2, name='')\"",
        'Spawn request says "response:',
        'Spawn finished',
    ]
    out = job.output
    # a message of two lines: the second one as it is, like a terminal shows it
    assert out[out.index('[INFO] [launch.user]: Spawn request says "response:') + 1] == \
        "turtlesim.srv.Spawn_Response(name='turtle2')\""
    # the spawn command started only once turtlesim had, and the param set after it ended
    assert out.index('[INFO] [launch.user]: Turtlesim started, spawning turtle') < \
        [i for i, line in enumerate(out) if 'Spawn "{x: 2, y: 2, theta: 0.2}"-2]: process '
         'started' in line][0]
    assert param('/turtlesim3/sim', 'background_r') == 'Integer value is: 120'
    labkit.sleep(2.0)
    assert param('/turtlesim3/sim', 'background_r') == 'Integer value is: 200'
    # closing the window (the turtlesim process ends): OnProcessExit asks for a shutdown
    from labkit import process
    sim = next(p for p in process.processes() if p.name == 'turtlesim_node-1')
    sim.stop()
    job.wait(1.0)
    assert not job.running()
    assert user_lines(job.output)[-2:] == ['student closed the turtlesim window',
                                           'Launch was asked to shutdown: Window closed']
    assert '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)' not in job.output
    assert not any('sending signal' in line for line in job.output)   # nothing left to stop
    assert nodes() == []


def test_event_handlers_ctrl_c_reason(tutorial):
    job = launch('launch launch_tutorial example_event_handlers.launch.py')
    labkit.sleep(0.5)
    job.stop()
    lines = user_lines(job.output)
    # OnShutdown first; then turtlesim, stopped by the shutdown, exits and its OnProcessExit
    # handler still runs (its own Shutdown event is ignored: the launch is shutting down)
    assert lines[-2:] == ['Launch was asked to shutdown: ctrl-c (SIGINT)',
                          'student closed the turtlesim window']
    assert not job.running()
    assert not any('sending signal' in line for line in job.output)   # Ctrl-C reached them


def test_large_project(tutorial):
    r = labkit.ros2('launch launch_tutorial launch_turtlesim.launch.py --show-args')
    assert "    'target_frame':\n        Target frame name.\n        (default: 'turtle1')\n" \
        in r.stdout
    assert "    'node_prefix':\n        prefix for node name\n" \
        "        (default: EnvVar('USER') + '_')\n" in r.stdout
    job = launch('launch launch_tutorial launch_turtlesim.launch.py')
    labkit.sleep(0.5)
    assert started(job.output) == [
        'turtlesim_node-1', 'turtlesim_node-2', 'turtle_tf2_broadcaster-3',
        'turtle_tf2_broadcaster-4', 'turtle_tf2_listener-5', 'mimic-6',
        'fixed_frame_tf2_broadcaster-7', 'rviz2-8']
    assert sorted(nodes()) == ['/broadcaster1', '/broadcaster2', '/listener', '/mimic',
                               '/rviz2', '/sim', '/student_fixed_broadcaster',
                               '/turtlesim2/sim']
    # world 1: parameters from launch arguments (text read as YAML: integers)
    assert [param('/sim', f'background_{c}') for c in 'rgb'] == [
        'Integer value is: 0', 'Integer value is: 84', 'Integer value is: 122']
    # world 2: the YAML file's /** section, under the pushed namespace
    assert [param('/turtlesim2/sim', f'background_{c}') for c in 'rgb'] == [
        'Integer value is: 150', 'Integer value is: 86', 'Integer value is: 255']
    # the include's launch_arguments beat the declared default
    assert param('/listener', 'target_frame') == 'String value is: carrot1'
    assert param('/broadcaster2', 'turtlename') == 'String value is: turtle2'
    mimic = info('/mimic')
    assert '/turtle2/pose: turtlesim/msg/Pose' in mimic
    assert '/turtlesim2/turtle1/cmd_vel: geometry_msgs/msg/Twist' in mimic
    # the listener spawned turtle2 in world 1 and follows carrot1
    labkit.sleep(2.0)
    assert '/turtle2/cmd_vel' in labkit.ros2('topic list').stdout.split()
    job.stop()
    assert nodes() == []


def test_world_3_wildcard_yaml(tutorial):
    job = launch('launch launch_tutorial turtlesim_world_3.launch.py')
    labkit.sleep(0.3)
    assert nodes() == ['/turtlesim3/sim']
    assert param('/turtlesim3/sim', 'background_r') == 'Integer value is: 150'
    job.stop()
