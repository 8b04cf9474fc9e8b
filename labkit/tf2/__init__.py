"""tf2 for labkit: tf2_ros (Buffer, listener, broadcasters), tf2_geometry_msgs,
tf_transformations, and the executables tf2_ros static_transform_publisher /
tf2_echo, tf2_tools view_frames and labkit's turtle_tf2_demo nodes.

`register()` (called by labkit.plugins) only records names: nothing heavy is imported.
`snapshot(buffer)` gives the viewers every frame as a 4x4 matrix in one fixed frame.
"""
__all__ = ["register", "snapshot"]

ALIASES = {
    "tf2_ros": "labkit.tf2.ros",
    "tf2_py": "labkit.tf2.tf2_py",
    "tf2_geometry_msgs": "labkit.tf2.tf2_geometry_msgs",
    "tf_transformations": "labkit.tf2.transformations",
}

EXECUTABLES = {
    ("tf2_ros", "static_transform_publisher"): "labkit.tf2.static_transform_publisher:main",
    ("tf2_ros", "tf2_echo"): "labkit.tf2.tf2_echo:main",
    ("tf2_tools", "view_frames"): "labkit.tf2.view_frames:main",
    # labkit's own demo package (chapter 22); the official one is turtle_tf2_py
    ("turtle_tf2_demo", "pose_to_tf"): "labkit.tf2.turtle_demo.pose_to_tf:main",
    ("turtle_tf2_demo", "chaser"): "labkit.tf2.turtle_demo.chaser:main",
    ("turtle_tf2_demo", "carrot"): "labkit.tf2.turtle_demo.carrot:main",
}


def register():
    from labkit import compat, executables
    for name, target in ALIASES.items():
        compat.register_alias(name, target)
    for (package, executable), target in EXECUTABLES.items():
        executables.register(package, executable, target)


def snapshot(buffer, fixed_frame=None, time=None):
    """{frame: 4x4 numpy matrix of that frame in fixed_frame} (see labkit.tf2.tree)."""
    from labkit.tf2.tree import snapshot as _snapshot
    return _snapshot(buffer, fixed_frame, time)
