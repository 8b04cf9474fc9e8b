"""mcap bags as Humble's rosbag2_storage_mcap writes them: readable by `rosbags` and by the
`mcap` library with `mcap-ros2-support`, message for message; a SIGKILLed recording keeps
its complete chunks and `ros2 bag reindex` repairs it."""
import os
import subprocess
import sys
import textwrap

import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

import labkit
import labkit.interfaces as ifc
from labkit.bag.mcap_file import scan

TWIST = '"{linear: {x: 2.0}, angular: {z: 1.8}}"'


def _labkit_messages(bag):
    """(topic, stamp, CDR bytes) through labkit's rosbag2_py, in bag order."""
    from labkit.bag import rosbag2_py
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri=str(bag)), rosbag2_py.ConverterOptions())
    out = []
    while reader.has_next():
        topic, data, stamp = reader.read_next()
        out.append((topic, stamp, bytes(data)))
    return out


def _record_turtle(storage):
    labkit.ros2('run turtlesim turtlesim_node')
    rec = labkit.ros2(f'bag record -s {storage} -o turtle /turtle1/cmd_vel /turtle1/pose /rosout')
    labkit.ros2(f'topic pub --times 3 /turtle1/cmd_vel geometry_msgs/msg/Twist {TWIST}')
    labkit.sleep(1.0)
    rec.stop()
    return rec


def test_rosbags_and_mcap_read_every_message(bag_dir):
    rec = _record_turtle('mcap')
    assert sorted(os.listdir('turtle')) == ['metadata.yaml', 'turtle_0.mcap']
    # Humble's mcap plugin logs no "Opened database" line; nothing names a file not written
    assert not any('Opened database' in line for line in rec.output)
    ours = _labkit_messages('turtle')
    topics = {t for t, _, _ in ours}
    assert topics == {'/turtle1/cmd_vel', '/turtle1/pose', '/rosout'} and len(ours) > 60

    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader('turtle') as reader:
        for c in reader.connections:     # the types rosbags lacks: from the bag's own schema
            if c.msgtype not in store.fielddefs:
                store.register(get_types_from_msg(c.msgdef.data, c.msgtype))
        theirs = [(c.topic, t, bytes(d)) for c, t, d in reader.messages()]
        qos = {c.topic: c.ext.offered_qos_profiles for c in reader.connections}
        poses = [store.deserialize_cdr(d, c.msgtype) for c, _, d in reader.messages()
                 if c.topic == '/turtle1/pose']
    assert theirs == ours
    assert all(qos[t] and 'history' in str(qos[t][0]) for t in topics)  # (parsed by rosbags)
    assert poses[-1].x != poses[0].x          # the turtle moved, as the decoded values show

    with open('turtle/turtle_0.mcap', 'rb') as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        header = reader.get_header()
        decoded = [(ch.topic, m.log_time, m.data, d)
                   for _, ch, m, d in reader.iter_decoded_messages(log_time_order=True)]
        summary = reader.get_summary()
        metadata = {r.name: r.metadata for r in reader.iter_metadata()}
    assert (header.profile, header.library) == ('ros2', 'libmcap 0.8.0')
    assert metadata == {'rosbag2': {'ROS_DISTRO': 'humble'}}
    assert sorted((t, s, d) for t, s, d, _ in decoded) == sorted(ours)
    assert summary.statistics.message_count == len(ours)
    assert {s.encoding for s in summary.schemas.values()} == {'ros2msg'}
    assert {c.message_encoding for c in summary.channels.values()} == {'cdr'}
    assert all('offered_qos_profiles' in c.metadata for c in summary.channels.values())
    twists = [d for t, _, _, d in decoded if t == '/turtle1/cmd_vel']
    assert [(m.linear.x, round(m.angular.z, 3)) for m in twists] == [(2.0, 1.8)] * 3
    pose = next(d for t, _, _, d in decoded if t == '/turtle1/pose')
    assert round(pose.x, 4) == round(poses[0].x, 4)


def test_schema_is_the_definition_with_its_dependencies():
    from labkit.bag.mcap_file import message_definition
    encoding, text = message_definition('geometry_msgs/msg/PoseStamped')
    assert encoding == 'ros2msg'
    blocks = text.split('=' * 80 + '\n')
    assert blocks[0] == ifc.get_interface_text('geometry_msgs/msg/PoseStamped') + '\n'
    assert [b.splitlines()[0] for b in blocks[1:]] == [
        'MSG: geometry_msgs/Pose', 'MSG: geometry_msgs/Point', 'MSG: geometry_msgs/Quaternion',
        'MSG: std_msgs/Header', 'MSG: builtin_interfaces/Time']


def test_python_api_mcap_bag_is_readable_elsewhere(bag_dir):
    """rosbag2_py's writer (the seed's simple_bag_recorder style) with storage_id='mcap'."""
    from labkit.bag import rosbag2_py
    String = ifc.get_type('std_msgs/msg/String')
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri='api', storage_id='mcap'),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata(
        name='chatter', type='std_msgs/msg/String', serialization_format='cdr'))
    for n in range(50):
        writer.write('chatter', ifc.serialize(String(data=f'hi {n}')), 1000 + n)
    del writer
    with open('api/api_0.mcap', 'rb') as f:
        got = [d.data for _, _, _, d in make_reader(
            f, decoder_factories=[DecoderFactory()]).iter_decoded_messages()]
    assert got == [f'hi {n}' for n in range(50)]
    with Reader('api') as reader:
        assert sum(1 for _ in reader.messages()) == 50


KILLED = textwrap.dedent('''
    import sys, labkit, rclpy
    from std_msgs.msg import String
    rclpy.init()
    node = rclpy.create_node('talker')
    pub = node.create_publisher(String, '/data', 10)
    rec = labkit.ros2('bag record -s STORAGE -o killed /data')
    n = 0
    def tick():
        global n
        if pub.get_subscription_count() == 0:
            return
        pub.publish(String(data=str(n)))
        n += 1
        print(n, flush=True)          # the test reads how many were published so far
    node.create_timer(0.01, tick)
    rclpy.spin(node)
''')


def _published_lines(proc):
    for line in proc.stdout:
        line = line.strip()
        if line.isdigit():
            yield int(line)


@pytest.mark.parametrize('storage', ['mcap', 'sqlite3'])
def test_sigkilled_recording_keeps_what_came_before_and_reindex_repairs_it(tmp_path, storage):
    script = tmp_path / 'record.py'
    script.write_text(KILLED.replace('STORAGE', storage))
    env = dict(os.environ, LABKIT_DDS='off', TZ='UTC',
               PYTHONPATH=os.path.dirname(os.path.dirname(os.path.dirname(__file__))))
    proc = subprocess.Popen([sys.executable, '-m', 'labkit', 'exec', '--time', 'live',
                             str(script)], cwd=tmp_path, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, text=True)
    try:
        counts = _published_lines(proc)
        # at 100 Hz: note how many were out at 2 s, kill 150 messages (1.5 s) later
        safe = next(n for n in counts if n >= 200)
        next(n for n in counts if n >= safe + 150)
        proc.kill()                      # SIGKILL (TerminateProcess on Windows)
        proc.wait(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(timeout=30)
    bag = tmp_path / 'killed'
    assert not (bag / 'metadata.yaml').exists() or storage == 'sqlite3'
    r = labkit.ros2(f'bag reindex {bag}')
    assert (r.returncode, r.stderr) == (0, '')
    got = [int(ifc.deserialize(d, ifc.get_type('std_msgs/msg/String')).data)
           for _, _, d in _labkit_messages(bag)]
    assert got[:safe] == list(range(safe))          # nothing from before the last 1.5 s lost
    assert got == list(range(len(got)))
    info = labkit.ros2(f'bag info {bag}')
    assert f'Messages:          {len(got)}\n' in info.stdout
    if storage == 'mcap':
        assert scan(str(bag / 'killed_0.mcap')).complete
        with open(bag / 'killed_0.mcap', 'rb') as f:
            n = sum(1 for _ in make_reader(f).iter_messages())
        with Reader(bag) as reader:
            assert sum(1 for _ in reader.messages()) == n == len(got)


def test_info_on_a_killed_mcap_without_metadata_reads_the_file(bag_dir):
    """No metadata.yaml and a cut file: info on the folder says what Humble's
    rosbag2_cpp::Info says; on the file itself it reads what is whole."""
    from labkit.bag.metadata import TopicMetadata
    from labkit.bag.storage import BagWriter
    String = ifc.get_type('std_msgs/msg/String')
    bag = BagWriter('cut', 'mcap')
    bag.create_topic(TopicMetadata('/data', 'std_msgs/msg/String', 'cdr', ''))
    for n in range(30):
        bag.write('/data', ifc.serialize(String(data=str(n))), 1000 + n)
    bag.flush()                          # one complete chunk on disk
    for n in range(30, 40):
        bag.write('/data', ifc.serialize(String(data=str(n))), 1000 + n)
    bag.file.writer.file.flush()         # the open chunk never made it: as after a SIGKILL
    r = labkit.ros2('bag info cut')
    assert (r.returncode, r.stderr) == (1, 'Could not find metadata in bag directory cut\n')
    r = labkit.ros2('bag info cut/cut_0.mcap')
    assert r.returncode == 0, r.stderr
    assert 'Messages:          30\n' in r.stdout and 'reindex' not in r.stderr


def test_split_mcap_by_duration_like_sqlite3(bag_dir):
    from labkit.bag.metadata import read_metadata
    String = ifc.get_type('std_msgs/msg/String')
    from labkit.bag import rosbag2_py
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri='split', storage_id='mcap',
                                          max_bagfile_duration=1),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata('/c', 'std_msgs/msg/String', 'cdr'))
    for k in range(8):  # 0.0 .. 3.5 s
        writer.write('/c', ifc.serialize(String(data=str(k))), k * 500_000_000)
    del writer                 # Humble closes a writer in its destructor
    m = read_metadata('split')
    assert m.relative_file_paths == ['split_0.mcap', 'split_1.mcap', 'split_2.mcap']
    assert [f.message_count for f in m.files] == [3, 3, 2]
    with Reader('split') as reader:
        assert [ifc.deserialize(d, String).data for _, _, d in reader.messages()] == \
            [str(k) for k in range(8)]
    for k, name in enumerate(m.relative_file_paths):
        with open(os.path.join('split', name), 'rb') as f:
            assert len(list(make_reader(f).iter_messages())) == [3, 3, 2][k]
