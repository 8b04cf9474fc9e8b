"""Where the lock leaves cyclonedds out (Linux aarch64: no wheel exists), labkit still
imports and runs, and labkit.connect() says in one line what is missing."""
import subprocess
import sys

CODE = r"""
import sys
sys.modules['cyclonedds'] = None          # as on a machine where it is not installed
import labkit
from labkit import compat
compat.activate(quiet=True)
from labkit.graph import world
world.set_mode('live')
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('talker')
node.create_publisher(String, 'chatter', 10).publish(String(data='hi'))
from labkit import dds
try:
    dds.connect()
except dds.ConnectError as exc:
    print('ERR', exc)
node.destroy_node()
rclpy.shutdown()
labkit.reset()
"""


def test_connect_without_cyclonedds_says_so_in_one_line():
    done = subprocess.run([sys.executable, "-c", CODE], capture_output=True, text=True,
                          timeout=120, env={**__import__("os").environ, "LABKIT_TIME": "live"})
    assert done.returncode == 0, done.stderr[-2000:]
    lines = [l for l in done.stdout.splitlines() if l.startswith("ERR")]
    assert lines == ["ERR labkit.connect(): the 'cyclonedds' package is not installed "
                     "(pip install cyclonedds)"], done.stdout
