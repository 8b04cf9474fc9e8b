"""rosbag2_py and the bag files: Humble's layout, readable by `rosbags`."""
import os
import sqlite3
import subprocess
import sys
import textwrap

import pytest
import yaml
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_typestore

import labkit.interfaces as ifc
from labkit.bag import rosbag2_py
from labkit.bag.metadata import format_bag_metadata, format_file_size, read_metadata
from labkit.rclpy.serialization import deserialize_message, serialize_message

EPOCH = 1704067200_000_000_000
String = ifc.get_type('std_msgs/msg/String')
Twist = ifc.get_type('geometry_msgs/msg/Twist')


def _write(uri, storage_id='sqlite3', n=5):
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py._storage.StorageOptions(uri=uri, storage_id=storage_id),
                rosbag2_py._storage.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py._storage.TopicMetadata(
        name='chatter', type='std_msgs/msg/String', serialization_format='cdr'))
    writer.create_topic(rosbag2_py.TopicMetadata('/cmd', 'geometry_msgs/msg/Twist', 'cdr'))
    for k in range(n):
        writer.write('chatter', serialize_message(String(data=f'Hello World: {k}')),
                     EPOCH + k * 500_000_000)
    t = Twist()
    t.linear.x = 2.0
    writer.write('/cmd', ifc.serialize(t), EPOCH + 250_000_000)
    return writer


def test_sqlite3_bag_has_humbles_layout(bag_dir):
    _write('my_bag')                 # dropped at once: the destructor closes it
    assert sorted(os.listdir('my_bag')) == ['metadata.yaml', 'my_bag_0.db3']
    db = sqlite3.connect('my_bag/my_bag_0.db3')
    tables = {r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type='table'")}
    assert tables == {'schema', 'metadata', 'topics', 'messages'}
    assert db.execute('SELECT schema_version FROM schema').fetchone() == (3,)
    assert [r[0] for r in db.execute('SELECT name FROM topics ORDER BY id')] == ['chatter', '/cmd']
    info = yaml.safe_load(open('my_bag/metadata.yaml'))['rosbag2_bagfile_information']
    assert info['version'] == 5
    assert info['storage_identifier'] == 'sqlite3'
    assert info['message_count'] == 6
    assert info['relative_file_paths'] == ['my_bag_0.db3']
    assert info['files'][0]['message_count'] == 6
    assert info['duration'] == {'nanoseconds': 2_000_000_000}
    assert info['starting_time'] == {'nanoseconds_since_epoch': EPOCH}


@pytest.mark.parametrize('storage_id', ['sqlite3', 'mcap'])
def test_rosbags_reads_what_we_write(bag_dir, storage_id):
    _write('b', storage_id)                 # dropped at once: the destructor closes it
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader('b') as reader:
        got = [(c.topic, t, store.deserialize_cdr(d, c.msgtype)) for c, t, d in reader.messages()]
    assert [g[0] for g in got] == ['chatter', '/cmd', 'chatter', 'chatter', 'chatter', 'chatter']
    assert got[0][2].data == 'Hello World: 0'
    assert got[1][2].linear.x == 2.0
    assert got[-1][1] == EPOCH + 2_000_000_000


@pytest.mark.parametrize('storage_id', ['sqlite3', 'mcap'])
def test_sequential_reader_round_trip(bag_dir, storage_id):
    _write('b', storage_id)                 # dropped at once: the destructor closes it
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri='b', storage_id=''),
                rosbag2_py.ConverterOptions('', ''))
    topics = {t.name: t.type for t in reader.get_all_topics_and_types()}
    assert topics == {'chatter': 'std_msgs/msg/String', '/cmd': 'geometry_msgs/msg/Twist'}
    seen = []
    while reader.has_next():
        topic, data, t = reader.read_next()
        cls = String if topic == 'chatter' else Twist
        seen.append((topic, deserialize_message(data, cls), t))
    assert len(seen) == 6
    assert [s[2] for s in seen] == sorted(s[2] for s in seen)
    assert seen[0][1] == String(data='Hello World: 0')
    with pytest.raises(RuntimeError, match='Bag is at end'):
        reader.read_next()
    reader.set_filter(rosbag2_py.StorageFilter(topics=['/cmd']))
    assert reader.read_next()[0] == '/cmd' and not reader.has_next()


def test_rosbags_written_bag_is_readable(bag_dir):
    from rosbags.rosbag2 import Writer
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Writer('theirs', version=8) as w:
        conn = w.add_connection('/chatter', 'std_msgs/msg/String', typestore=store)
        w.write(conn, EPOCH, ifc.serialize(String(data='hi')))
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri='theirs'), rosbag2_py.ConverterOptions())
    assert reader.read_next() == ('/chatter', ifc.serialize(String(data='hi')), EPOCH)


def test_writer_refuses_an_existing_bag(bag_dir):
    os.mkdir('my_bag')
    writer = rosbag2_py.SequentialWriter()
    with pytest.raises(RuntimeError, match=r"Database directory already exists \(my_bag\)"):
        writer.open(rosbag2_py.StorageOptions(uri='my_bag', storage_id='sqlite3'),
                    rosbag2_py.ConverterOptions('', ''))


def test_info_text_is_humbles(bag_dir):
    _write('my_bag')                 # dropped at once: the destructor closes it
    m = rosbag2_py.Info().read_metadata('my_bag', '')
    from labkit.rclpy.duration import Duration
    from labkit.rclpy.time import Time
    assert m.starting_time == Time(nanoseconds=EPOCH)  # rclpy objects, as in Humble
    assert m.duration == Duration(seconds=2)
    lines = repr(m).split('\n')
    assert lines[0] == ''
    assert lines[1] == 'Files:             my_bag_0.db3'
    assert lines[2].startswith('Bag size:          ') and lines[2].endswith('KiB')
    assert lines[3:] == [
        'Storage id:        sqlite3',
        'Duration:          2.000000000s',
        'Start:             Jan  1 2024 00:00:00.000000000 (1704067200.000000000)',
        'End:               Jan  1 2024 00:00:02.000000000 (1704067202.000000000)',
        'Messages:          6',
        'Topic information: Topic: chatter | Type: std_msgs/msg/String | Count: 5 | '
        'Serialization Format: cdr',
        '                   Topic: /cmd | Type: geometry_msgs/msg/Twist | Count: 1 | '
        'Serialization Format: cdr',
        '']


def test_file_sizes_like_rosbag2():
    assert format_file_size(0) == '0 B'
    assert format_file_size(1023) == '1023 B'
    assert format_file_size(233984) == '228.5 KiB'
    assert format_file_size(5 * 1024 ** 3) == '5.0 GiB'


def _child_env():
    """labkit importable in the child, also where it is only on PYTHONPATH (Windows job)."""
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    return dict(os.environ, PYTHONPATH=os.pathsep.join(
        p for p in (repo, os.environ.get('PYTHONPATH')) if p))


def _killed_writer(n):
    """A kernel that dies mid-recording: no close, no destructor, no atexit."""
    return textwrap.dedent(f'''
        import os
        import labkit.interfaces as ifc
        from labkit.bag import rosbag2_py
        String = ifc.get_type('std_msgs/msg/String')
        w = rosbag2_py.SequentialWriter()
        w.open(rosbag2_py.StorageOptions(uri='crash'), rosbag2_py.ConverterOptions())
        w.create_topic(rosbag2_py.TopicMetadata('/c', 'std_msgs/msg/String', 'cdr'))
        for k in range({n}):
            w.write('/c', ifc.serialize(String(data=str(k))), 1000 + k)
        os._exit(9)
    ''')


def _committed(bag):
    """Rows the dead writer had committed (opening read-write rolls its half batch back)."""
    db = sqlite3.connect(f'{bag}/{bag}_0.db3')
    rows = db.execute('SELECT data FROM messages ORDER BY id').fetchall()
    db.close()
    return [ifc.deserialize(r[0], String).data for r in rows]


def test_a_killed_writer_leaves_a_readable_bag(bag_dir):
    subprocess.run([sys.executable, '-c', _killed_writer(2500)], check=False, cwd=bag_dir,
                   env=_child_env())
    m = rosbag2_py.Info().read_metadata('crash', '')
    kept = _committed('crash')
    # whole batches (1000 messages or 0.2 s each) stay, in order; the half batch is gone
    assert 0 < len(kept) < 2500 and kept == [str(k) for k in range(len(kept))]
    assert (m.message_count, m.starting_time.nanoseconds, m.duration.nanoseconds) == \
        (len(kept), 1000, len(kept) - 1)
    assert m.topics_with_message_count[0].message_count == len(kept)
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri='crash'), rosbag2_py.ConverterOptions())
    n = 0
    while reader.has_next():
        reader.read_next()
        n += 1
    assert n == len(kept)
    os.remove('crash/metadata.yaml')  # without it, Humble's Info reads the file named itself
    with pytest.raises(RuntimeError, match='^Could not find metadata in bag directory crash$'):
        rosbag2_py.Info().read_metadata('crash', '')
    m = rosbag2_py.Info().read_metadata('crash/crash_0.db3', '')
    assert (m.message_count, m.starting_time.nanoseconds, m.duration.nanoseconds) == \
        (len(kept), 1000, len(kept) - 1)


def test_rosbags_reads_a_killed_writers_bag(bag_dir):
    subprocess.run([sys.executable, '-c', _killed_writer(1500)], check=False, cwd=bag_dir,
                   env=_child_env())
    kept = _committed('crash')
    with Reader('crash') as reader:  # its metadata.yaml: from a refresh along the way
        got = [ifc.deserialize(d, String).data for _, _, d in reader.messages()]
    assert got == kept and len(got) > 0


def test_format_bag_metadata_without_topics():
    from labkit.bag.metadata import BagMetadata
    text = format_bag_metadata(BagMetadata(storage_identifier='sqlite3'))
    assert 'Files:             \n' in text
    assert text.endswith('Topic information: \n')


def test_reindex_rebuilds_metadata(bag_dir):
    import labkit
    subprocess.run([sys.executable, '-c', _killed_writer(1200)], check=False, cwd=bag_dir,
                   env=_child_env())
    kept = _committed('crash')
    r = labkit.ros2('bag reindex crash')
    assert r.returncode == 0, r.stderr
    m = read_metadata('crash')
    assert (m.version, m.message_count, m.relative_file_paths) == (5, len(kept), ['crash_0.db3'])
    assert m.topics_with_message_count[0].topic_metadata.type == 'std_msgs/msg/String'
    assert labkit.ros2('bag reindex crash/crash_0.db3').stderr == \
        '[ERROR] [ros2bag]: Must specify a bag directory\n'


def test_split_by_duration_like_humble(bag_dir):
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri='split', storage_id='sqlite3',
                                          max_bagfile_duration=1),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata('/c', 'std_msgs/msg/String', 'cdr'))
    for k in range(8):  # 0.0 .. 3.5 s
        writer.write('/c', ifc.serialize(String(data=str(k))), k * 500_000_000)
    del writer                 # Humble closes a writer in its destructor
    m = read_metadata('split')
    assert m.relative_file_paths == ['split_0.db3', 'split_1.db3', 'split_2.db3']
    assert [f.message_count for f in m.files] == [3, 3, 2]
    assert [f.starting_time for f in m.files] == [0, 1_500_000_000, 3_000_000_000]
    assert (m.message_count, m.duration) == (8, 3_500_000_000)
    with Reader('split') as reader:
        assert [ifc.deserialize(d, String).data for _, _, d in reader.messages()] == \
            [str(k) for k in range(8)]
    text = repr(rosbag2_py.Info().read_metadata('split'))
    assert 'Files:             split_0.db3\n                   split_1.db3\n' in text


def test_split_size_below_sqlite_minimum_is_refused(bag_dir):
    import labkit
    r = labkit.ros2('bag record -b 1000 -o small /chatter')
    assert r.returncode == 1
    assert 'Invalid bag splitting size given. Please provide a value greater than 86016. ' \
        'Specified value of 1000' in r.stderr
