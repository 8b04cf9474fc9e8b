"""`import tf2_geometry_msgs`: do_transform_* for geometry_msgs, registered with tf2_ros."""
from .tf2_geometry_msgs import *  # noqa: F401,F403
