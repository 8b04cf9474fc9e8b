"""`ros2 bag record|info|play` with turtlesim (virtual time: the same every run)."""
import os

import pytest
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_typestore

import labkit
import labkit.interfaces as ifc
from labkit.rclpy.serialization import deserialize_message

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TWIST = '"{linear: {x: 2.0}, angular: {z: 1.8}}"'


def _pose():
    out = labkit.ros2('topic echo --once /turtle1/pose').stdout
    import yaml
    return yaml.safe_load(out.split('---')[0])


def _record_subset():
    labkit.ros2('run turtlesim turtlesim_node')
    rec = labkit.ros2('bag record -o subset /turtle1/cmd_vel /turtle1/pose')
    labkit.ros2(f'topic pub --times 3 /turtle1/cmd_vel geometry_msgs/msg/Twist {TWIST}')
    labkit.sleep(1.0)
    moved = _pose()
    rec.stop()
    return rec, moved


def test_record_prints_humbles_lines_and_writes_a_real_bag(bag_dir):
    rec, _ = _record_subset()
    lines = [line.split('] ', 2)[-1] for line in rec.output]
    assert lines[:6] == [
        '[rosbag2_recorder]: Press SPACE for pausing/resuming',
        "[rosbag2_storage]: Opened database 'subset/subset_0.db3' for READ_WRITE.",
        '[rosbag2_recorder]: Listening for topics...',
        '[rosbag2_recorder]: Event publisher thread: Starting',
        "[rosbag2_recorder]: Subscribed to topic '/turtle1/pose'",
        '[rosbag2_recorder]: Recording...',
    ]
    assert "[rosbag2_recorder]: Subscribed to topic '/turtle1/cmd_vel'" in lines
    assert '[rosbag2_recorder]: All requested topics are subscribed. Stopping discovery...' \
        in lines
    assert lines[-1] == '[rosbag2_recorder]: Recording stopped'
    assert rec.output[0].startswith('[INFO] [1704067200.')
    assert sorted(os.listdir('subset')) == ['metadata.yaml', 'subset_0.db3']
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader('subset') as reader:
        types = {c.topic: c.msgtype for c in reader.connections}
        twists = [store.deserialize_cdr(d, c.msgtype) for c, _, d in reader.messages()
                  if c.topic == '/turtle1/cmd_vel']
        poses = [d for c, _, d in reader.messages() if c.topic == '/turtle1/pose']
        qos = [c.ext.offered_qos_profiles for c in reader.connections]
    assert types == {'/turtle1/pose': 'turtlesim/msg/Pose',
                     '/turtle1/cmd_vel': 'geometry_msgs/msg/Twist'}
    assert [(t.linear.x, round(t.angular.z, 3)) for t in twists] == [(2.0, 1.8)] * 3
    assert len(poses) > 50  # turtlesim publishes its pose at 62.5 Hz
    # the wire CDR (no rmw padding): deserializes to the same message, re-serializes the same
    Pose = ifc.get_type('turtlesim/msg/Pose')
    assert ifc.serialize(deserialize_message(poses[0], Pose)) == poses[0]
    assert all(q for q in qos)  # the publishers' QoS are kept, as Humble does


def test_info_on_a_recorded_bag(bag_dir):
    _record_subset()
    result = labkit.ros2('bag info subset')
    assert result.returncode == 0
    lines = result.stdout.split('\n')
    assert lines[0] == '' and lines[1] == 'Files:             subset_0.db3'
    assert lines[3] == 'Storage id:        sqlite3'
    assert lines[5].startswith('Start:             Jan  1 2024 00:00:00.')
    assert lines[8].startswith('Topic information: Topic: /turtle1/pose | '
                               'Type: turtlesim/msg/Pose | Count: ')
    assert lines[9] == ('                   Topic: /turtle1/cmd_vel | Type: '
                        'geometry_msgs/msg/Twist | Count: 3 | Serialization Format: cdr')
    assert labkit.ros2('bag info subset').stdout == result.stdout  # deterministic


def test_play_redraws_the_recorded_path(bag_dir):
    _, moved = _record_subset()
    labkit.reset()
    labkit.ros2('run turtlesim turtlesim_node')
    start = _pose()
    play = labkit.ros2('bag play subset --topics /turtle1/cmd_vel')
    out = [line.split('] ', 2)[-1] for line in play.output]
    assert out[:3] == ["[rosbag2_storage]: Opened database 'subset/subset_0.db3' for READ_ONLY.",
                       '[rosbag2_player]: Adding keyboard callbacks.',
                       '[rosbag2_player]: Press SPACE for Pause/Resume']
    play.wait()
    assert play.state == 'done' and play.returncode == 0
    labkit.sleep(1.0)
    end = _pose()
    assert (end['x'], end['y']) != (start['x'], start['y'])
    # same commands, same timing: the turtle ends where it ended while recording
    assert end['x'] == pytest.approx(moved['x'], abs=0.05)
    assert end['y'] == pytest.approx(moved['y'], abs=0.05)


def test_play_keeps_the_recorded_timing_and_rate(bag_dir):
    from labkit.bag import rosbag2_py
    String = ifc.get_type('std_msgs/msg/String')
    w = rosbag2_py.SequentialWriter()
    w.open(rosbag2_py.StorageOptions(uri='timed'), rosbag2_py.ConverterOptions())
    w.create_topic(rosbag2_py.TopicMetadata('/chatter', 'std_msgs/msg/String', 'cdr'))
    for k in range(4):
        w.write('/chatter', ifc.serialize(String(data=str(k))), 10**9 * k)
    del w                      # Humble closes a writer in its destructor
    echo = labkit.ros2('topic echo /chatter std_msgs/msg/String')
    t0 = labkit.ros2('run demo_nodes_py listener')  # noqa: F841 (a second subscriber)
    from labkit.graph import world
    start = world.system_ns()
    play = labkit.ros2('bag play timed --rate 2 --start-offset 1 --disable-keyboard-controls')
    play.wait()
    took = (world.system_ns() - start) / 1e9
    assert took == pytest.approx(1.0, abs=0.05)  # 2 s of bag after the offset, at rate 2
    labkit.sleep(0.1)  # the subscribers take the last message
    assert [line for line in echo.output if line.startswith('data')] == \
        ["data: '1'", "data: '2'", "data: '3'"]
    assert not any('Press' in line for line in play.output)


def test_loop_plays_until_stopped(bag_dir):
    from labkit.bag import rosbag2_py
    String = ifc.get_type('std_msgs/msg/String')
    w = rosbag2_py.SequentialWriter()
    w.open(rosbag2_py.StorageOptions(uri='one'), rosbag2_py.ConverterOptions())
    w.create_topic(rosbag2_py.TopicMetadata('/chatter', 'std_msgs/msg/String', 'cdr'))
    w.write('/chatter', ifc.serialize(String(data='again')), 0)
    w.write('/chatter', ifc.serialize(String(data='again')), 5 * 10**8)
    del w                      # Humble closes a writer in its destructor
    echo = labkit.ros2('topic echo /chatter std_msgs/msg/String')
    play = labkit.ros2('bag play one --loop')
    labkit.sleep(2.2)
    assert play.running()
    play.stop()
    assert sum(line == "data: again" for line in echo.output) >= 4


def test_record_all_and_mcap(bag_dir):
    labkit.ros2('run turtlesim turtlesim_node')
    rec = labkit.ros2('bag record -a -s mcap -o everything')
    labkit.sleep(0.5)
    rec.stop()
    assert any(p.endswith('.mcap') for p in os.listdir('everything'))
    with Reader('everything') as reader:
        topics = {c.topic for c in reader.connections}
    assert {'/turtle1/pose', '/turtle1/color_sensor', '/rosout'} <= topics
    assert '/turtle1/cmd_vel' not in topics  # nobody publishes it
    info = labkit.ros2('bag info everything')
    assert 'Storage id:        mcap' in info.stdout


def test_record_mistakes_are_one_line(bag_dir):
    r = labkit.ros2('bag record')
    assert r.returncode == 1
    assert r.stderr == \
        '[ERROR] [ros2bag]: Invalid choice: Must specify topic(s), --regex or --all\n'
    os.mkdir('taken')
    r = labkit.ros2('bag record -o taken /chatter')
    assert r.returncode == 1 and "Output folder 'taken' already exists." in r.stderr
    r = labkit.ros2('bag record -a /chatter')
    assert 'Specify either --all or topics' in r.stderr
    r = labkit.ros2('bag info nowhere')
    assert r.returncode == 2
    assert "Bag path 'nowhere' does not exist!" in r.stderr
    r = labkit.ros2('bag play nowhere')
    assert r.returncode == 2


def test_default_bag_name_uses_the_clock(bag_dir):
    labkit.ros2('run turtlesim turtlesim_node')
    rec = labkit.ros2('bag record /turtle1/pose')
    rec.stop()
    assert os.listdir('.') == ['rosbag2_2024_01_01-00_00_00']


def _recorded_topics(bag):
    with Reader(bag) as reader:
        return {c.topic for c in reader.connections}


def test_hidden_regex_and_exclude_filters(bag_dir):
    labkit.ros2('run turtlesim turtlesim_node')
    jobs = [labkit.ros2('bag record -a -o plain'),
            labkit.ros2('bag record -a --include-hidden-topics -o hidden'),
            labkit.ros2('bag record -e turtle1 -x color -o regex')]
    labkit.sleep(0.3)
    for job in jobs:
        job.stop()
    plain, hidden, regex = (_recorded_topics(b) for b in ('plain', 'hidden', 'regex'))
    assert not any('/_action/' in t for t in plain)
    assert '/turtle1/rotate_absolute/_action/status' in hidden
    assert regex == {'/turtle1/pose'}


def test_recorder_is_a_node_in_the_graph(bag_dir):
    labkit.ros2('run turtlesim turtlesim_node')
    rec = labkit.ros2('bag record /turtle1/pose')
    assert '/rosbag2_recorder' in labkit.ros2('node list').stdout.split()
    rec.stop()
    assert '/rosbag2_recorder' not in labkit.ros2('node list').stdout.split()


def test_record_and_play_in_live_time(tmp_path):
    import subprocess
    import sys
    import textwrap
    code = textwrap.dedent('''
        import time, labkit
        labkit.ros2('run turtlesim turtlesim_node')
        rec = labkit.ros2('bag record -o live /turtle1/pose')
        time.sleep(0.3)
        rec.stop()
        info = labkit.ros2('bag info live').stdout
        play = labkit.ros2('bag play live --rate 4')
        play.wait(10)
        print(info.split(chr(10))[8])
        print(play.state, play.returncode)
        labkit.reset()
    ''')
    done = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                          timeout=60, cwd=tmp_path,
                          env={'LABKIT_TIME': 'live', 'PATH': '/usr/bin:/bin', 'TZ': 'UTC',
                               # labkit where it is not installed (Windows job), and Windows'
                               # own variable its Python needs
                               'PYTHONPATH': os.pathsep.join(
                                   p for p in (REPO, os.environ.get('PYTHONPATH')) if p),
                               **{k: os.environ[k] for k in ('SYSTEMROOT',) if k in os.environ}})
    assert done.returncode == 0, done.stderr
    topic_line, state = done.stdout.splitlines()
    assert topic_line.startswith('Topic information: Topic: /turtle1/pose | '
                                 'Type: turtlesim/msg/Pose | Count: ')
    assert int(topic_line.split('Count: ')[1].split(' ')[0]) > 0
    assert state == 'done 0'
