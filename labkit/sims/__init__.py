"""Simulators written as ordinary ROS 2 nodes: turtlesim and the 2D world of the Gazebo chapter."""


def register():
    """Cheap: the 2D world's executables (ign gazebo, ros_gz_bridge, teleop_twist_keyboard) and %ign."""
    from labkit.sims import world2d
    world2d.register()
