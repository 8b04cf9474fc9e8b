"""The seed's chapter 20 programs (bag_recorder_nodes_py/, copied unchanged) run on labkit."""
import os

import pytest
from rosbags.rosbag2 import Reader
from rosbags.typesys import Stores, get_typestore

import labkit


def _ints(bag):
    from labkit.bag.typestore import typestore_for
    store = typestore_for('example_interfaces/msg/Int32')  # not in rosbags' Humble store
    with Reader(bag) as reader:
        return [(t, store.deserialize_cdr(d, c.msgtype).data) for c, t, d in reader.messages()]


def test_rosbag2_py_resolves_like_the_seed_imports_it(hook):
    import rosbag2_py
    import rosbag2_py._storage
    from labkit.bag import rosbag2_py as ours
    assert rosbag2_py.SequentialWriter is ours.SequentialWriter
    assert rosbag2_py._storage.StorageOptions is ours.StorageOptions
    assert rosbag2_py._storage.TopicMetadata is ours.TopicMetadata


def test_simple_bag_recorder_then_play_to_listener(bag_dir, seed_package):
    recorder = labkit.ros2('run bag_recorder_nodes_py simple_bag_recorder')
    talker = labkit.ros2('run demo_nodes_cpp talker')
    labkit.sleep(3.5)
    talker.stop()
    recorder.stop()
    assert sorted(os.listdir('my_bag')) == ['metadata.yaml', 'my_bag_0.db3']
    store = get_typestore(Stores.ROS2_HUMBLE)
    with Reader('my_bag') as reader:
        heard = [store.deserialize_cdr(d, c.msgtype).data for c, _, d in reader.messages()]
    assert heard[:3] == ['Hello World: 1', 'Hello World: 2', 'Hello World: 3']
    assert len(heard) == 3

    listener = labkit.ros2('run demo_nodes_cpp listener')
    play = labkit.ros2('bag play my_bag')
    play.wait()
    labkit.sleep(0.1)
    assert [line.split(']: ')[-1] for line in listener.output
            if 'I heard' in line] == ['I heard: [Hello World: 1]', 'I heard: [Hello World: 2]',
                                      'I heard: [Hello World: 3]']


def test_data_generator_node_writes_one_message_per_second(bag_dir, seed_package):
    node = labkit.ros2('run bag_recorder_nodes_py data_generator_node')
    labkit.sleep(5.5)
    node.stop()
    got = _ints('timed_synthetic_bag')
    assert [v for _, v in got] == [0, 1, 2, 3, 4]
    stamps = [t for t, _ in got]
    assert [b - a for a, b in zip(stamps, stamps[1:])] == [10**9] * 4
    echo = labkit.ros2('topic echo /synthetic example_interfaces/msg/Int32')
    labkit.ros2('bag play timed_synthetic_bag').wait()
    labkit.sleep(0.1)
    assert [line for line in echo.output if line.startswith('data')] == \
        [f'data: {k}' for k in range(5)]


def test_data_generator_executable_writes_100_seconds_at_once(bag_dir, seed_package):
    run = labkit.ros2('run bag_recorder_nodes_py data_generator_executable')
    rc = run.returncode if run.returncode is not None else run.wait()
    assert rc == 0
    got = _ints('big_synthetic_bag')
    assert [v for _, v in got] == list(range(100))
    info = labkit.ros2('bag info big_synthetic_bag').stdout
    assert 'Duration:          99.000000000s' in info
    assert 'Messages:          100' in info
    assert 'Topic: synthetic | Type: example_interfaces/msg/Int32 | Count: 100' in info


@pytest.mark.parametrize('again', ['my_bag'])
def test_rerunning_without_deleting_the_bag_fails_like_rosbag2(bag_dir, seed_package, again):
    os.mkdir(again)
    run = labkit.ros2('run bag_recorder_nodes_py simple_bag_recorder')
    assert run.returncode == 1
    assert "Database directory already exists (my_bag), can't overwrite existing database" \
        in run.stderr
