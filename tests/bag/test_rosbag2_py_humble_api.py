"""rosbag2_py is Humble's: SequentialReader/SequentialWriter have no close() (Jazzy added
it); a bag is finished when its writer is let go (`del writer`), as Humble's pybind11
binding does in the C++ destructor."""
import pytest

import labkit.interfaces as ifc
from labkit.bag import rosbag2_py


@pytest.mark.parametrize('cls', ['SequentialReader', 'SequentialWriter'])
def test_no_close_in_humble(cls):
    obj = getattr(rosbag2_py, cls)()
    with pytest.raises(AttributeError, match=f"'{cls}' object has no attribute 'close'"):
        obj.close()


def test_del_finishes_the_bag_and_lets_the_file_go(bag_dir):
    String = ifc.get_type('std_msgs/msg/String')
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri='b', storage_id='sqlite3'),
                rosbag2_py.ConverterOptions('', ''))
    writer.create_topic(rosbag2_py.TopicMetadata('/c', 'std_msgs/msg/String', 'cdr'))
    writer.write('/c', ifc.serialize(String(data='x')), 5)
    del writer
    from labkit.bag.metadata import read_metadata
    assert read_metadata('b').message_count == 1
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri='b', storage_id='sqlite3'),
                rosbag2_py.ConverterOptions('', ''))
    assert reader.read_next()[0] == '/c'
    bag = reader._bag
    del reader
    assert bag.files and all(
        getattr(f, 'conn', None) is None or _closed(f.conn) for f in bag.files)


def _closed(conn):
    import sqlite3
    try:
        conn.execute('SELECT 1')
    except sqlite3.ProgrammingError:
        return True
    return False
