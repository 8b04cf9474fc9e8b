"""Robot models: URDF/xacro, robot_state_publisher, joint_state_publisher(_gui),
the facer robot's description package (facer_description) and its motion.

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
    # rviz2 stand-in: the meshcat viewer following /robot_description and /tf
    ("rviz2", "rviz2"): "labkit.viz.meshcat_view:rviz_main",
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


def display(model="urdf/01-one-shape.urdf", gui=True, echo=True):
    """What `ros2 launch facer_description display.launch.py model:=... gui:=...` starts:
    robot_state_publisher (xacro-expanded model), joint_state_publisher(_gui) and
    the viewer in place of rviz2. A relative `model` is taken inside facer_description's share.
    Returns the processes; `labkit.viz.meshcat_view.current()` is the viewer."""
    import os
    from labkit import process
    from labkit.robots import facer
    model = str(model)
    if not os.path.isabs(model):
        model = os.path.join(share_directory("facer_description"), model)
    text = description(model)
    jsp = "joint_state_publisher_gui" if gui else "joint_state_publisher"
    return [process.start([jsp, jsp], echo=echo),
            facer.start_robot_state_publisher(text, echo=echo),
            process.start(["rviz2", "rviz2"], echo=echo)]
