"""A broken bag answers in one line, in rosbag2's words (rosbag2_storage's MetadataIo,
rosbag2_cpp's SequentialReader), never with a Python traceback."""
import os

import pytest

import labkit
import labkit.interfaces as ifc
from labkit.bag import rosbag2_py


def _bag(name, storage='sqlite3'):
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=name, storage_id=storage),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata(
        name='chatter', type='std_msgs/msg/String', serialization_format='cdr'))
    String = ifc.get_type('std_msgs/msg/String')
    for n in range(5):
        writer.write('chatter', ifc.serialize(String(data=str(n))), 1000 + n)
    del writer


def _one_line(result):
    assert result.returncode == 1
    assert result.stderr.count('\n') == 1 and 'Traceback' not in result.stderr
    return result.stderr.rstrip('\n')


@pytest.mark.parametrize('text,what', [
    ('rosbag2_bagfile_information:\n  version: [5\n',
     'yaml-cpp: error at line 3, column 1: '),
    ('rosbag2_bagfile_information: {version: 5}\n', 'invalid node; first invalid key: '),
    ('just some words\n', 'yaml-cpp: error at line 1, column 1: operator[] call on a scalar '
                           '(key: "rosbag2_bagfile_information")'),
])
def test_corrupt_metadata_is_one_line(bag_dir, text, what):
    _bag('bad')
    with open('bad/metadata.yaml', 'w') as f:
        f.write(text)
    for command in ('bag info bad', 'bag play bad'):
        line = _one_line(labkit.ros2(command))
        assert line.startswith('Exception on parsing info file: ' + what), line
    with pytest.raises(RuntimeError, match='^Exception on parsing info file: '):
        rosbag2_py.Info().read_metadata('bad', '')


@pytest.mark.parametrize('storage,name', [('sqlite3', 'bad_0.db3'), ('mcap', 'bad_0.mcap')])
def test_garbage_storage_file_is_one_line(bag_dir, storage, name):
    _bag('bad', storage)
    with open(os.path.join('bad', name), 'wb') as f:
        f.write(b'this is not a bag at all, just some bytes\n' * 100)
    if storage == 'mcap':
        assert _one_line(labkit.ros2('bag play bad')) == \
            'No storage could be initialized from the inputs.'
    else:   # Humble's StorageFactory says why, then SequentialReader::load_current_file
        result = labkit.ros2('bag play bad')
        assert result.returncode == 1
        lines = [line.split('] ', 2)[-1] for line in result.stderr.splitlines()]
        assert lines == [
            "[rosbag2_storage]: Could not open 'bad/bad_0.db3' with 'sqlite3'. Error: Failed "
            "to setup storage. Error: Error when processing SQL statement. SQLite error (26): "
            "file is not a database",
            "[rosbag2_storage]: Could not load/open plugin with storage id 'sqlite3'",
            'No storage could be initialized. Abort'], result.stderr
    os.remove('bad/metadata.yaml')     # nothing to go by but the file itself
    reader = rosbag2_py.SequentialReader()
    with pytest.raises(RuntimeError, match='^No storage could be initialized from the inputs.$'):
        reader.open(rosbag2_py.StorageOptions(uri='bad'), rosbag2_py.ConverterOptions())
    # rosbag2_cpp::Info wants metadata.yaml in a folder (ros2 bag reindex makes one)
    assert _one_line(labkit.ros2('bag info bad')) == \
        'Could not find metadata in bag directory bad'
