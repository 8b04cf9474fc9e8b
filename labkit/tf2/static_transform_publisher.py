"""`ros2 run tf2_ros static_transform_publisher` (C++ in ROS): one latched /tf_static message.

New style: --x --y --z, --qx --qy --qz --qw or --roll --pitch --yaw, --frame-id,
--child-frame-id. Old style (deprecated, warned): x y z yaw pitch roll frame child,
or x y z qx qy qz qw frame child."""
import random

import labkit.rclpy as rclpy
from labkit.graph import world
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.rclpy.parameter import Parameter

from ._cpp import like_rclcpp, quaternion_from_rpy, rcutils_log, stod

USAGE = (
    "usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] "
    "[--qz QZ] [--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID "
    "--child-frame-id CHILD_FRAME_ID\n\n"
    "A command line utility for manually sending a static transform.\n\nIf no translation or"
    " orientation is provided, the identity transform will be published.\n\nThe translation offsets"
    " are in meters.\n\nThe rotation may be provided with roll, pitch, yaw euler angles in radians,"
    " or as a quaternion.\n\n"
    "required arguments:\n"
    "  --frame-id FRAME_ID parent frame\n"
    "  --child-frame-id CHILD_FRAME_ID child frame id\n\n"
    "optional arguments:\n"
    "  --x X                 x component of translation\n"
    "  --y Y                 y component of translation\n"
    "  --z Z                 z component of translation\n"
    "  --qx QX               x component of quaternion rotation\n"
    "  --qy QY               y component of quaternion rotation\n"
    "  --qz QZ               z component of quaternion rotation\n"
    "  --qw QW               w component of quaternion rotation\n"
    "  --roll ROLL           roll component Euler rotation\n"
    "  --pitch PITCH         pitch component Euler rotation\n"
    "  --yaw YAW             yaw component Euler rotation")

_FLOATS = {"--qx": ("quat", 0), "--qy": ("quat", 1), "--qz": ("quat", 2), "--qw": ("quat", 3),
           "--roll": ("rpy", 0), "--pitch": ("rpy", 1), "--yaw": ("rpy", 2),
           "--x": ("trans", 0), "--y": ("trans", 1), "--z": ("trans", 2)}


class ParseError(Exception):
    pass


def parse_args(args):
    """args without ROS arguments (args[0] is the program). Returns a dict or raises ParseError."""
    if len(args) < 1:
        raise ParseError("Not enough arguments to parse")
    quat = [0.0, 0.0, 0.0, 1.0]
    trans = [0.0, 0.0, 0.0]
    rpy = [0.0, 0.0, 0.0]
    frames = {"--frame-id": "", "--child-frame-id": ""}
    seen = set()
    help_ = False
    loose = []

    def number(optname, text):
        try:
            return stod(text)
        except ValueError:
            raise ParseError("Failed to parse " + optname + " argument as float") from None

    def put(optname, key, text):
        kind, i = _FLOATS[key]
        value = number(optname, text)
        {"quat": quat, "rpy": rpy, "trans": trans}[kind][i] = value
        seen.add(kind)

    i = 1
    while i < len(args):
        opt = args[i]
        if opt in ("--help", "-h"):
            help_ = True
        elif opt in _FLOATS or opt in frames:
            if i == len(args) - 1:
                raise ParseError("Not enough arguments for " + opt)
            i += 1
            if opt in frames:
                frames[opt] = args[i]
                seen.add("frame")
            else:
                put(opt, opt, args[i])
        else:
            loose.append(opt)
        i += 1
    if help_:
        return None
    if "rpy" in seen and "quat" in seen:
        raise ParseError("Cannot specify both quaternion and Euler rotations")
    if "rpy" in seen:
        quat[:] = quaternion_from_rpy(*rpy)
    if len(loose) in (8, 9):
        rcutils_log("WARN", "Old-style arguments are deprecated; "
                    "see --help for new-style arguments")
        if seen & {"frame", "trans", "quat"}:
            raise ParseError("Cannot specify both new-style (flags) and old-style (arguments)")
        for name, key, text in zip("xyz", ("--x", "--y", "--z"), loose):
            put(name, key, text)
        if len(loose) == 8:
            for name, key, text in zip(("yaw", "pitch", "roll"), ("--yaw", "--pitch", "--roll"),
                                       loose[3:6]):
                put(name, key, text)
            quat[:] = quaternion_from_rpy(*rpy)
            frames["--frame-id"], frames["--child-frame-id"] = loose[6], loose[7]
        else:
            for name, key, text in zip(("qx", "qy", "qz", "qw"), ("--qx", "--qy", "--qz", "--qw"),
                                       loose[3:7]):
                put(name, key, text)
            frames["--frame-id"], frames["--child-frame-id"] = loose[7], loose[8]
    elif loose:
        raise ParseError("Extra unparsed arguments on command-line")
    if frames["--frame-id"] == "":
        raise ParseError("Frame id must not be empty")
    if frames["--child-frame-id"] == "":
        raise ParseError("Child frame id must not be empty")
    return {"translation": tuple(trans), "rotation": tuple(quat),
            "frame_id": frames["--frame-id"], "child_frame_id": frames["--child-frame-id"]}


_CHARS = "0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
_virtual_rng = random.Random(0)     # virtual time: the same node names every run


def unique_node_name():
    rng = _virtual_rng if world.mode() == "virtual" else random.SystemRandom()
    return "static_transform_publisher_" + "".join(rng.choice(_CHARS) for _ in range(16))


def make_node(parsed):
    TransformStamped = get_type("geometry_msgs/msg/TransformStamped")
    ParameterDescriptor = get_type("rcl_interfaces/msg/ParameterDescriptor")
    (tx, ty, tz), (qx, qy, qz, qw) = parsed["translation"], parsed["rotation"]
    overrides = [Parameter("translation.x", value=tx), Parameter("translation.y", value=ty),
                 Parameter("translation.z", value=tz), Parameter("rotation.x", value=qx),
                 Parameter("rotation.y", value=qy), Parameter("rotation.z", value=qz),
                 Parameter("rotation.w", value=qw),
                 Parameter("frame_id", value=parsed["frame_id"]),
                 Parameter("child_frame_id", value=parsed["child_frame_id"])]
    node = Node(unique_node_name(), parameter_overrides=overrides)
    like_rclcpp(node, ("/parameter_events", "/tf_static"))
    ro = ParameterDescriptor(read_only=True)
    msg = TransformStamped()
    msg.header.stamp = node.get_clock().now().to_msg()
    t, r = msg.transform.translation, msg.transform.rotation
    t.x = node.declare_parameter("translation.x", 0.0, ro).value
    t.y = node.declare_parameter("translation.y", 0.0, ro).value
    t.z = node.declare_parameter("translation.z", 0.0, ro).value
    r.x = node.declare_parameter("rotation.x", 0.0, ro).value
    r.y = node.declare_parameter("rotation.y", 0.0, ro).value
    r.z = node.declare_parameter("rotation.z", 0.0, ro).value
    r.w = node.declare_parameter("rotation.w", 1.0, ro).value
    msg.header.frame_id = node.declare_parameter("frame_id", "/frame", ro).value
    msg.child_frame_id = node.declare_parameter("child_frame_id", "/child", ro).value
    if msg.header.frame_id == msg.child_frame_id:
        node.get_logger().error("cannot publish static transform from '%s' to '%s', exiting"
                                % (msg.header.frame_id, msg.child_frame_id))
        node.destroy_node()
        raise RuntimeError("child_frame_id cannot equal frame_id")
    from labkit.tf2.ros.static_transform_broadcaster import StaticTransformBroadcaster
    node.broadcaster = StaticTransformBroadcaster(node)
    node.broadcaster.sendTransform(msg)
    return node


def main(args=None):
    import sys
    argv = list(sys.argv if args is None else args)
    rclpy.init(args=argv)
    try:
        argv = rclpy.utilities.remove_ros_args(argv)
        try:
            parsed = parse_args(argv)
        except ParseError as exc:
            rcutils_log("ERROR", "error parsing command line arguments: %s" % exc)
            print(USAGE)
            return 1
        if parsed is None:
            print(USAGE)
            return 0
        try:
            node = make_node(parsed)
        except RuntimeError as exc:
            # an uncaught C++ exception: std::terminate
            sys.stderr.write("terminate called after throwing an instance of "
                             "'std::runtime_error'\n  what():  %s\n" % exc)
            return -6
        (tx, ty, tz), (qx, qy, qz, qw) = parsed["translation"], parsed["rotation"]
        node.get_logger().info(
            "Spinning until stopped - publishing transform\ntranslation: ('%f', '%f', '%f')\n"
            "rotation: ('%f', '%f', '%f', '%f')\nfrom '%s' to '%s'"
            % (tx, ty, tz, qx, qy, qz, qw, parsed["frame_id"], parsed["child_frame_id"]))
        try:
            rclpy.spin(node)
        except KeyboardInterrupt:
            pass
        except Exception as exc:
            if type(exc).__name__ != "ExternalShutdownException":
                raise
        node.destroy_node()
        return 0
    finally:
        rclpy.try_shutdown()
