"""Robot models: URDF/xacro, robot_state_publisher, joint_state_publisher(_gui),
the urdf_tutorial models and the walking r2d2 of the Humble URDF tutorial.

`register()` (called by labkit.plugins) adds the executables; nothing heavy is
imported until a node or a model is used.
"""

EXECUTABLES = {
    ("robot_state_publisher", "robot_state_publisher"):
        "labkit.robots.robot_state_publisher:main",
    ("joint_state_publisher", "joint_state_publisher"):
        "labkit.robots.joint_state_publisher:main",
    ("joint_state_publisher_gui", "joint_state_publisher_gui"):
        "labkit.robots.joint_state_publisher:gui_main",
    ("xacro", "xacro"): "labkit.robots.xacro_support:main",
}


def register():
    from labkit import executables
    for (package, executable), target in EXECUTABLES.items():
        executables.register(package, executable, target)


def load(source, filename=None):
    """A RobotModel from URDF text, a .urdf path or a .xacro path."""
    from labkit.robots import urdf
    if urdf.is_path(source):
        return urdf.load(urdf.read_text(str(source)), str(source))
    return urdf.load(source, filename)


def description(path, mappings=None):
    """The robot_description text of a .urdf or .urdf.xacro file (what `xacro FILE` prints)."""
    from labkit.robots import xacro_support
    path = str(path)
    if path.endswith(".xacro"):
        return xacro_support.process(path, mappings)
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def share_directory(package):
    from labkit.robots import packages
    return packages.share_directory(package)
