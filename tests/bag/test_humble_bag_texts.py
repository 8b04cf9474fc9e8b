"""rosbag2's own words (Humble sources) for a bag that is broken in a way a learner meets:
a .db3 cut in half (a full disk, a copy that stopped), a folder without metadata.yaml, a
metadata.yaml that yaml-cpp cannot parse (its ErrorMsg texts, not PyYAML's)."""
import os

import pytest

import labkit
import labkit.interfaces as ifc
from labkit.bag import rosbag2_py


def _bag(name, count=400):
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=name, storage_id='sqlite3'),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata(
        name='chatter', type='std_msgs/msg/String', serialization_format='cdr'))
    String = ifc.get_type('std_msgs/msg/String')
    for n in range(count):
        writer.write('chatter', ifc.serialize(String(data='x' * 200 + str(n))), 1000 + n)
    del writer


def _messages(stderr):
    """The log lines without their stamps, and the plain lines."""
    return [line.split('] ', 2)[-1] if line.startswith('[') else line
            for line in stderr.splitlines()]


def test_db3_cut_in_half(bag_dir):
    _bag('half')
    path = os.path.join('half', 'half_0.db3')
    size = os.path.getsize(path)
    with open(path, 'r+b') as f:
        f.truncate(size // 2)
    info = labkit.ros2('bag info half')          # metadata.yaml alone: still answers
    assert info.returncode == 0 and 'Messages:          400' in info.stdout
    result = labkit.ros2('bag play half')
    assert result.returncode == 1
    assert _messages(result.stderr) == [
        "[rosbag2_storage]: Could not open 'half/half_0.db3' with 'sqlite3'. Error: Failed to "
        "setup storage. Error: Error when processing SQL statement. SQLite error (11): "
        "database disk image is malformed",
        "[rosbag2_storage]: Could not load/open plugin with storage id 'sqlite3'",
        'No storage could be initialized. Abort']
    reader = rosbag2_py.SequentialReader()
    with pytest.raises(RuntimeError, match='^No storage could be initialized. Abort$'):
        reader.open(rosbag2_py.StorageOptions(uri='half', storage_id='sqlite3'),
                    rosbag2_py.ConverterOptions('', ''))


def test_info_of_a_folder_without_metadata(bag_dir):
    _bag('nometa', count=3)
    os.remove(os.path.join('nometa', 'metadata.yaml'))
    result = labkit.ros2('bag info nometa')
    assert (result.returncode, result.stdout, result.stderr) == \
        (1, '', 'Could not find metadata in bag directory nometa\n')
    with pytest.raises(RuntimeError, match='^Could not find metadata in bag directory nometa$'):
        rosbag2_py.Info().read_metadata('nometa', 'sqlite3')
    # a storage file named directly is asked for its metadata
    single = labkit.ros2('bag info nometa/nometa_0.db3')
    assert single.returncode == 0 and 'Messages:          3' in single.stdout


@pytest.mark.parametrize('text,what', [
    ('rosbag2_bagfile_information:\n  version: 5\n  foo: bar: baz\n',
     'yaml-cpp: error at line 3, column 11: illegal map value'),
    ('rosbag2_bagfile_information:\n  version: [5\n',
     'yaml-cpp: error at line 3, column 1: end of sequence flow not found'),
    ('rosbag2_bagfile_information: {version: 5\n',
     'yaml-cpp: error at line 2, column 1: end of map flow not found'),
    ('rosbag2_bagfile_information:\n  version: 5\n bad: 1\n',
     'yaml-cpp: error at line 3, column 2: end of map not found'),
    ('rosbag2_bagfile_information:\n  version: 5\n  words here\n  more: 1\n',
     'yaml-cpp: error at line 3, column 3: end of map not found'),
    ('rosbag2_bagfile_information:\n  version: "5\n',
     'yaml-cpp: error at line 3, column 1: illegal EOF in scalar'),
    ('rosbag2_bagfile_information:\n  version: *x\n',
     'yaml-cpp: error at line 2, column 12: the referenced anchor is not defined'),
])
def test_corrupt_metadata_in_yaml_cpp_words(bag_dir, text, what):
    _bag('bad', count=3)
    with open('bad/metadata.yaml', 'w', encoding='utf-8') as f:
        f.write(text)
    result = labkit.ros2('bag info bad')
    assert (result.returncode, result.stderr) == \
        (1, 'Exception on parsing info file: ' + what + '\n')
