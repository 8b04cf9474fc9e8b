"""launch_ros on labkit: `launch_ros.actions.Node` and `launch_ros.substitutions`."""
from labkit.launch_ros import actions, substitutions  # noqa: F401
