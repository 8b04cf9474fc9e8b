"""`ros2 bag record` loses nothing (issue 13), and says so in rosbag2's words when its
bounded cache must drop. Counts messages, never seconds."""
import json
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def _record(tmp_path, mode, storage, kind, count, rate, busy):
    env = dict(os.environ, LABKIT_TIME=mode, TZ='UTC', PYTHONPATH=ROOT)
    done = subprocess.run(
        [sys.executable, os.path.join(HERE, 'lossless_run.py'), storage, kind, str(count),
         str(rate), '1' if busy else '0'],
        capture_output=True, text=True, timeout=300, cwd=tmp_path, env=env)
    assert done.returncode == 0, done.stderr[-2000:]
    report = json.loads(done.stdout.strip().splitlines()[-1])
    assert report['publisher_rc'] == 0
    return report


def _recorded(bag, kind):
    """The sequence numbers in the bag, read by labkit's own reader (rosbag2_py)."""
    import labkit.interfaces as ifc
    from labkit.bag import rosbag2_py
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri=str(bag)), rosbag2_py.ConverterOptions())
    cls = ifc.get_type('sensor_msgs/msg/Image' if kind == 'image' else 'std_msgs/msg/String')
    seen = []
    while reader.has_next():
        _, data, _ = reader.read_next()
        msg = ifc.deserialize(data, cls)
        seen.append(int(msg.header.frame_id if kind == 'image' else msg.data))
    return seen


@pytest.mark.parametrize('mode', ['virtual', 'live'])
@pytest.mark.parametrize('storage', ['sqlite3', 'mcap'])
@pytest.mark.parametrize('kind,count,rate', [('small', 1000, 1000), ('image', 45, 30)])
def test_record_keeps_every_message(tmp_path, mode, storage, kind, count, rate):
    # live: the notebook keeps computing meanwhile (the recorder's thread must share the CPU)
    report = _record(tmp_path, mode, storage, kind, count, rate, busy=mode == 'live')
    assert report['warnings'] == []
    assert _recorded(tmp_path / 'lossless', kind) == list(range(count))
    info = json.dumps(report['lines'])
    assert 'Writing remaining messages from cache to the bag. It may take a while' in info


def test_a_full_cache_drops_and_says_so_in_rosbag2s_words(tmp_path, capsys):
    """The writer thread is held up (its storage busy): the bounded producer buffer fills,
    the rest is dropped and counted, and close() reports it as rosbag2_cpp does."""
    import labkit.interfaces as ifc
    from labkit.bag.metadata import TopicMetadata
    from labkit.bag.storage import BagWriter
    String = ifc.get_type('std_msgs/msg/String')
    bag = BagWriter(tmp_path / 'full', 'sqlite3', max_cache_size=1000)
    bag.create_topic(TopicMetadata('/data', 'std_msgs/msg/String', 'cdr', ''))
    with bag._lock:                       # the storage is busy: nothing can be written
        for n in range(100):
            bag.write('/data', ifc.serialize(String(data=f'{n:0>96}')), 1000 + n)
        dropped = bag.cache.dropped['/data']
    bag.close()
    written = bag.metadata().message_count
    assert dropped > 0 and written + dropped == 100
    err = capsys.readouterr().err
    assert ('Cache buffers lost messages per topic: \n\t/data: %d\nTotal lost: %d' %
            (dropped, dropped)) in err
    assert '[WARN]' in err and '[rosbag2_cpp]' in err


def test_without_a_cache_nothing_is_dropped_or_reported(tmp_path, capsys):
    """rosbag2_py's writer (max_cache_size 0): every write goes straight to the file."""
    import labkit.interfaces as ifc
    from labkit.bag.metadata import TopicMetadata
    from labkit.bag.storage import BagWriter
    String = ifc.get_type('std_msgs/msg/String')
    bag = BagWriter(tmp_path / 'direct', 'mcap')
    bag.create_topic(TopicMetadata('/data', 'std_msgs/msg/String', 'cdr', ''))
    for n in range(500):
        bag.write('/data', ifc.serialize(String(data=str(n))), 1000 + n)
    bag.close()
    assert bag.cache is None and bag.metadata().message_count == 500
    assert 'Cache buffers' not in capsys.readouterr().err


def test_python_writer_with_a_cache_flushes_it_on_shutdown(bag_dir):
    """rosbag2_py with StorageOptions(max_cache_size=...): the cache and its writer thread,
    emptied when the process's rclpy shuts down (a real writer's destructor)."""
    import labkit.interfaces as ifc
    import labkit.rclpy as rclpy
    from labkit.bag import rosbag2_py
    from labkit.bag.storage import read_bag_metadata
    String = ifc.get_type('std_msgs/msg/String')
    rclpy.init()
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri='cached', storage_id='mcap',
                                          max_cache_size=1 << 20),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata('/c', 'std_msgs/msg/String', 'cdr'))
    for k in range(300):
        writer.write('/c', ifc.serialize(String(data=str(k))), 1000 + k)
    assert writer._bag.cache is not None
    rclpy.shutdown()
    assert read_bag_metadata('cached').message_count == 300
