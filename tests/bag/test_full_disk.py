"""`ros2 bag record` onto a full filesystem ends as Humble's does: the storage's exception
escapes rosbag2's writer thread, libstdc++'s terminate lines, SIGABRT (status -6; a shell
shows 134); the batches committed before stay readable. Humble's sqlite3 plugin raises
SqliteException ("Error when processing SQL statement. SQLite error (13): database or disk
is full"); its mcap plugin does not check its writes (recording goes on, nothing said).

The full disk is a real one where the test may mount a small tmpfs (CI runs as root);
elsewhere the same error is injected at the storage seam (the sqlite3 connection)."""
import os
import subprocess
import sys

import pytest

import labkit
from labkit import process

TERMINATE = ("terminate called after throwing an instance of "
             "'rosbag2_storage_plugins::SqliteException'",
             "  what():  Error when processing SQL statement. SQLite error (13): "
             "database or disk is full")


def _talker(args=None):
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    String = get_type('std_msgs/msg/String')
    rclpy.init(args=args)
    node = rclpy.create_node('filler')
    pub = node.create_publisher(String, 'fill', 1000)
    count = [0]

    def tick():
        pub.publish(String(data=f'{count[0]:08d}' + 'x' * 1016))
        count[0] += 1
    node.create_timer(0.001, tick)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass


@pytest.fixture
def small_disk(tmp_path, monkeypatch):
    disk = tmp_path / 'disk'
    disk.mkdir()
    if sys.platform != 'linux':
        pytest.skip('a small tmpfs to fill needs Linux mount (the full-disk path is shared)')
    mounted = subprocess.run(['mount', '-t', 'tmpfs', '-o', 'size=1600k', 'tmpfs', str(disk)],
                             capture_output=True).returncode == 0
    if not mounted:
        pytest.skip('cannot mount a small tmpfs here (not root)')
    monkeypatch.chdir(disk)
    yield disk
    monkeypatch.chdir(tmp_path)
    subprocess.run(['umount', str(disk)], capture_output=True)


def _record_until_it_dies(args):
    talker = process.start(main=_talker, name='filler', echo=False)
    job = labkit.ros2('bag record -o full /fill ' + args)
    job.wait(20.0)
    talker.stop()
    return job


def test_sqlite3_on_a_full_disk_aborts_and_keeps_what_was_committed(small_disk):
    job = _record_until_it_dies('--max-cache-size 200000')
    assert job.process.returncode == -6
    assert tuple(job.output[-2:]) == TERMINATE, job.output[-6:]
    assert not any('Recording stopped' in line for line in job.output)
    from labkit.bag.storage import BagReader
    reader = BagReader('full')
    got = [int(data[8:16]) for _, data, _ in reader.messages()]
    reader.close()
    assert got and got == list(range(len(got)))      # whole batches, in order


def test_injected_full_disk_without_cache(tmp_path, monkeypatch):
    """The same ending where no small filesystem can be made: SQLITE_FULL injected at
    the storage seam (the second batch), writer without cache (the callback's thread)."""
    import sqlite3
    from labkit.bag import storage
    monkeypatch.chdir(tmp_path)
    real_commit = storage._SqliteFile.commit
    calls = [0]

    class Full(sqlite3.OperationalError):
        sqlite_errorcode = 13

    def commit(self):
        if self._rows:
            calls[0] += 1
            if calls[0] == 2:
                self._rows = []
                raise storage.StorageWriteError(
                    'rosbag2_storage_plugins::SqliteException', storage._sqlite_what(Full()))
        return real_commit(self)
    monkeypatch.setattr(storage._SqliteFile, 'commit', commit)
    job = _record_until_it_dies('--max-cache-size 0')
    assert job.process.returncode == -6
    assert tuple(job.output[-2:]) == TERMINATE, job.output[-6:]
    reader = storage.BagReader('full')
    got = [int(data[8:16]) for _, data, _ in reader.messages()]
    reader.close()
    assert got and got == list(range(len(got)))    # the first batch, whole and in order
