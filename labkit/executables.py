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
    **{("examples_rclpy_minimal_publisher", f"publisher_{style}"):
       "labkit.demos.minimal_py:publisher_main"
       for style in ("local_function", "member_function", "old_school")},
    **{("examples_rclpy_minimal_subscriber", f"subscriber_{style}"):
       "labkit.demos.minimal_py:subscriber_main"
       for style in ("lambda", "member_function", "old_school")},
}

# Which of the real executables labkit stands in for are C++ programs (rclcpp): when one
# fails it dies as a C++ program does (std::terminate: two lines on stderr, SIGABRT), not
# with a Python traceback. Packages named *_cpp / examples_rclcpp_* are C++ as well.
CPP = {
    ("turtlesim", "turtlesim_node"), ("turtlesim", "turtle_teleop_key"),
    ("turtlesim", "draw_square"), ("turtlesim", "mimic"),
    ("robot_state_publisher", "robot_state_publisher"), ("rviz2", "rviz2"),
    ("tf2_ros", "static_transform_publisher"), ("tf2_ros", "tf2_echo"),
    ("tf2_ros", "tf2_monitor"), ("ros_gz_bridge", "parameter_bridge"),
    ("image_tools", "cam2image"), ("image_tools", "showimage"),
}

_extra = {}
_paths = {}      # (package, executable) -> the path `ros2 run` shows as argv[0]
_overlaid = set()   # packages a sourced workspace provides: only its own executables count


def is_cpp(package, executable):
    """True if the real executable is a C++ (rclcpp) program."""
    if (package, executable) in _paths:       # a built workspace's entry points are Python
        return False
    return ((package, executable) in CPP or package.endswith("_cpp")
            or package.startswith("examples_rclcpp"))


class Target(str):
    """"module:function", knowing which language the real program is written in."""

    cpp = False


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


def overlay_package(package):
    """A sourced workspace now provides `package`: like ament's get_package_prefix, the
    tools look only under the first prefix that has it, so the bundled (underlay)
    executables of that package are no longer found; only what register() adds is."""
    unregister_package(package)
    _overlaid.add(package)


def _builtin(package, executable):
    if package in _overlaid:
        return None
    return BUILTIN.get((package, executable))


def lookup(package, executable):
    """Return "module:function" (a `Target`) or None."""
    target = _extra.get((package, executable)) or _builtin(package, executable)
    if target is None:
        return None
    target = Target(target)
    target.cpp = is_cpp(package, executable)
    return target


def packages():
    """Every package that has at least one executable."""
    return sorted({p for p, _ in list(BUILTIN) + list(_extra)})


def executables(package=None):
    """Sorted (package, executable) pairs, optionally of one package."""
    pairs = {p for p in BUILTIN if p[0] not in _overlaid} | set(_extra)
    return sorted(p for p in pairs if package is None or p[0] == package)


def resolve(target):
    """Import "module:function" and return the program's main: when it fails, it ends
    as the real program would (rclcpp's terminate lines, or rclpy's exception), never
    with a traceback through labkit's files."""
    import functools
    import importlib
    module, _, func = target.partition(":")
    main = getattr(importlib.import_module(module), func)
    die = _die_like_rclcpp if getattr(target, "cpp", False) else _die_like_python

    @functools.wraps(main)
    def program(*args, **kwargs):
        try:
            return main(*args, **kwargs)
        except (SystemExit, KeyboardInterrupt):
            raise
        except Exception as exc:       # noqa: BLE001 - the program dies of it
            return die(exc)
    return program


SIGABRT_EXIT = -6      # what a process killed by std::abort() returns (-SIGABRT)


def _die_like_rclcpp(exc):
    """An uncaught C++ exception: libstdc++'s verbose terminate handler, then abort."""
    import sys
    cls, what = rclcpp_exception(exc)
    sys.stderr.write(f"terminate called after throwing an instance of '{cls}'\n"
                     f"  what():  {what}\n")
    return SIGABRT_EXIT


def rclcpp_exception(exc):
    """(C++ exception class, what()) rclcpp throws where labkit's rclpy raised `exc`."""
    import ast
    from labkit.rclpy import exceptions as e
    if isinstance(exc, e.UnknownROSArgsError):
        try:
            args = ast.literal_eval(str(exc))
        except (ValueError, SyntaxError):
            args = [str(exc)]
        return ("rclcpp::exceptions::UnknownROSArgsError",
                "found unknown ROS arguments: '" + "', '".join(args) + "'")
    if isinstance(exc, e.RCLError) and str(exc).startswith("failed to initialize rcl:"):
        return "rclcpp::exceptions::RCLInvalidROSArgsError", str(exc)
    if isinstance(exc, e.InvalidParameterTypeException):
        name = exc._param_name
        expected = _rclcpp_type_name(getattr(exc, "_expected_type", "NOT_SET"))
        actual = _rclcpp_type_name(exc._actual_type.name)
        return ("rclcpp::exceptions::InvalidParameterTypeException",
                f"parameter '{name}' has invalid type: Wrong parameter type, parameter "
                f"{{{name}}} is of type {{{expected}}}, setting it to {{{actual}}} is not "
                "allowed.")
    if isinstance(exc, e.InvalidParameterValueException):
        reason = exc.args[0].split("Reason: ", 1)[-1] if exc.args else ""
        name = exc.args[1] if len(exc.args) > 1 else ""
        return ("rclcpp::exceptions::InvalidParameterValueException",
                f"parameter '{name}' could not be set: {reason}")
    if isinstance(exc, e.ParameterUninitializedException):
        name = str(exc).split("'")[1] if "'" in str(exc) else str(exc)
        return ("rclcpp::exceptions::ParameterUninitializedException",
                f"parameter '{name}' is not initialized")
    names = {e.InvalidNodeNameException: "InvalidNodeNameError",
             e.InvalidNamespaceException: "InvalidNamespaceError",
             e.InvalidTopicNameException: "InvalidTopicNameError",
             e.InvalidServiceNameException: "InvalidServiceNameError"}
    for py_cls, cpp_name in names.items():
        if isinstance(exc, py_cls):
            return f"rclcpp::exceptions::{cpp_name}", str(exc) + "\n"
    if isinstance(exc, e.RCLError):
        return "rclcpp::exceptions::RCLError", str(exc)
    return "std::runtime_error", str(exc)


def _rclcpp_type_name(rclpy_name):
    # rclcpp::to_string(ParameterType): "integer", "string", "byte_array", ... "not set"
    return "not set" if rclpy_name == "NOT_SET" else str(rclpy_name).lower()


def _die_like_python(exc):
    """An uncaught Python exception: the traceback a real install prints, with the
    program's own frames but none of labkit's (whose files a real install does not have)."""
    import sys
    from labkit.process import python_traceback
    sys.stderr.write(python_traceback(exc))
    return 1
