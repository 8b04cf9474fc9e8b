"""launch_ros on labkit: `launch_ros.actions.Node` and `launch_ros.substitutions`."""
from labkit.launch_ros import actions, parameter_descriptions, substitutions  # noqa: F401
