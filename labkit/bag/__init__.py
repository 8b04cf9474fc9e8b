"""rosbag2 on labkit: real rosbag2 bags (sqlite3 `.db3` + metadata.yaml v5, or mcap),
the `rosbag2_py` API, and the `ros2 bag record|info|play` verbs.

Layer 4: written on the public rclpy API only. Modules: metadata (structs,
metadata.yaml, info text), storage (sqlite3/mcap writers and readers, the message
cache and its writer thread), mcap_file (the MCAP format, and recovery of a cut file),
rosbag2_py (the Python API), recorder/player (the transport), cli (the verbs).
"""


def register():
    """Called once by labkit.plugins: the `ros2 bag` noun and `import rosbag2_py`."""
    from labkit import compat
    from labkit.plugins import register_noun
    register_noun('bag', 'labkit.bag.cli', 'Various rosbag related sub-commands')
    compat.register_alias('rosbag2_py', 'labkit.bag.rosbag2_py')
