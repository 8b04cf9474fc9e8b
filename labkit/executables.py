"""Which Python function stands behind `ros2 run <package> <executable>`.

Each entry is "module:function"; the function is an ordinary ROS 2
`main(args=None)`. Workspaces built with colcon add their own console_scripts
entry points at run time through `register()`.
"""
BUILTIN = {
    ("turtlesim", "turtlesim_node"): "labkit.sims.turtlesim.node:main",
    ("turtlesim", "turtle_teleop_key"): "labkit.sims.turtlesim.teleop:main",
    ("turtlesim", "draw_square"): "labkit.sims.turtlesim.draw_square:main",
    ("turtlesim", "mimic"): "labkit.sims.turtlesim.mimic:main",
    ("demo_nodes_cpp", "talker"): "labkit.demos.talker_listener:talker_main",
    ("demo_nodes_cpp", "listener"): "labkit.demos.talker_listener:listener_main",
    ("demo_nodes_py", "talker"): "labkit.demos.talker_listener:talker_main",
    ("demo_nodes_py", "listener"): "labkit.demos.talker_listener:listener_main",
    ("examples_rclcpp_minimal_publisher", "publisher_member_function"):
        "labkit.demos.minimal:publisher_main",
    ("examples_rclcpp_minimal_subscriber", "subscriber_member_function"):
        "labkit.demos.minimal:subscriber_main",
    ("rqt_graph", "rqt_graph"): "labkit.viz.graph_view:main",
}

_extra = {}
_paths = {}      # (package, executable) -> the path `ros2 run` shows as argv[0]


def register(package, executable, target, path=None):
    """Add (or replace) an executable, e.g. from a workspace's setup.py entry points.

    `path` is the file a real install would run (install/<pkg>/lib/<pkg>/<exe>, as
    printed); by default /opt/ros/humble/lib/<pkg>/<exe>."""
    _extra[(package, executable)] = target
    if path is not None:
        _paths[(package, executable)] = path
    else:
        _paths.pop((package, executable), None)


def path_of(package, executable):
    """argv[0] of the executable's process, as a real machine would show it."""
    return _paths.get((package, executable)) or f"/opt/ros/humble/lib/{package}/{executable}"


def unregister_package(package):
    for key in [k for k in _extra if k[0] == package]:
        del _extra[key]
        _paths.pop(key, None)


def lookup(package, executable):
    """Return "module:function" or None."""
    return _extra.get((package, executable)) or BUILTIN.get((package, executable))


def packages():
    """Every package that has at least one executable."""
    return sorted({p for p, _ in list(BUILTIN) + list(_extra)})


def executables(package=None):
    """Sorted (package, executable) pairs, optionally of one package."""
    pairs = set(BUILTIN) | set(_extra)
    return sorted(p for p in pairs if package is None or p[0] == package)


def resolve(target):
    """Import "module:function" and return the function."""
    import importlib
    module, _, func = target.partition(":")
    return getattr(importlib.import_module(module), func)
