"""`ros2 run tf2_ros tf2_echo <source_frame> <target_frame> [rate]` (C++ in ROS).

Prints, at `rate` Hz (default 1), the transform that takes data from target_frame
into source_frame, in tf2_echo's exact layout."""
import math
import random
import sys
import time

import labkit.rclpy as rclpy
from labkit.graph import world
from labkit.rclpy.time import Time

from ._cpp import euler_ypr, like_rclcpp, matrix3, stod_pos

USAGE = ("Usage: tf2_echo source_frame target_frame [echo_rate]\n\n"
         "This will echo the transform from the coordinate frame of the source_frame\n"
         "to the coordinate frame of the target_frame. \n"
         "Note: This is the transform to get data from target_frame into the source_frame.\n"
         "Default echo rate is 1 if echo_rate is not given.\n")

RAD_TO_DEG = 180.0 / math.pi


def format_transform(t):
    """The block tf2_echo prints for one TransformStamped."""
    tr, ro = t.transform.translation, t.transform.rotation
    m = matrix3((ro.x, ro.y, ro.z, ro.w))
    yaw, pitch, roll = euler_ypr(m)
    xyz = (tr.x, tr.y, tr.z)
    lines = ["At time %d.%d" % (t.header.stamp.sec, t.header.stamp.nanosec),
             "- Translation: [%.3f, %.3f, %.3f]" % xyz,
             "- Rotation: in Quaternion [%.3f, %.3f, %.3f, %.3f]" % (ro.x, ro.y, ro.z, ro.w),
             "- Rotation: in RPY (radian) [%.3f, %.3f, %.3f]" % (roll, pitch, yaw),
             "- Rotation: in RPY (degree) [%.3f, %.3f, %.3f]"
             % (roll * RAD_TO_DEG, pitch * RAD_TO_DEG, yaw * RAD_TO_DEG),
             "- Matrix:"]
    for i in range(3):
        lines.append("".join(" %6.3f" % v for v in m[i]) + " %6.3f" % xyz[i])
    lines.append(" %6.3f %6.3f %6.3f %6.3f" % (0.0, 0.0, 0.0, 1.0))
    return "\n".join(lines) + "\n"


def main(args=None):
    argv = list(sys.argv if args is None else args)
    rclpy.init(args=argv)
    try:
        return _run(rclpy.utilities.remove_ros_args(argv))
    finally:
        rclpy.try_shutdown()


def _run(args):
    if len(args) == 3:
        rate_hz = 1.0
    elif len(args) == 4:
        try:
            rate_hz, pos = stod_pos(args[3])
        except ValueError:
            sys.stderr.write("Failed to convert rate argument '%s' to a floating-point number\n"
                             % args[3])
            return 2
        if pos != len(args[3]):
            sys.stderr.write("Failed to convert rate argument '%s' to a floating-point number\n"
                             % args[3])
            return 3
    else:
        sys.stdout.write(USAGE)
        return 1
    period = 1.0 / rate_hz

    from labkit.tf2.core import TransformException
    from labkit.tf2.ros import Buffer, TransformListener
    node = rclpy.create_node("tf2_echo")
    like_rclcpp(node)
    clock = node.get_clock()
    buffer = Buffer()
    # rclcpp's TransformListener makes its own node, transform_listener_impl_<address>,
    # and spins it in its own thread (`ros2 node list` shows both nodes)
    impl = rclpy.create_node(_listener_node_name(), start_parameter_services=False)
    impl._labkit_parameter_dialect = "rclcpp"
    listener = TransformListener(buffer, impl, spin_thread=True)
    source_frameid, target_frameid = args[1], args[2]
    try:
        last_log = None
        while rclpy.ok():
            ok, warning = buffer.can_transform_core(source_frameid, target_frameid, Time())
            if ok:
                break
            now = clock.now().nanoseconds
            if last_log is None or now - last_log >= 10**9:      # INFO_THROTTLE 1000 ms
                last_log = now
                node.get_logger().info("Waiting for transform %s ->  %s: %s"
                                       % (source_frameid, target_frameid, warning))
            time.sleep(period)
        printed = False
        while rclpy.ok():
            try:
                t = buffer.lookup_transform_core(source_frameid, target_frameid, Time())
                sys.stdout.write(format_transform(t))
                printed = True
            except TransformException as ex:
                sys.stdout.write("Failure at %s\n" % _seconds(clock.now().nanoseconds, printed))
                sys.stdout.write("Exception thrown:%s\n" % ex)
                sys.stdout.write("The current list of frames is:\n")
                sys.stdout.write(buffer.all_frames_as_string() + "\n")
            sys.stdout.flush()
            time.sleep(period)
    except KeyboardInterrupt:
        pass
    finally:
        try:
            listener.executor.shutdown()
        except Exception:
            pass
        impl.destroy_node()
        node.destroy_node()
    return 0


_virtual_addresses = random.Random(1)


def _listener_node_name():
    """transform_listener_impl_ + a heap address in hex (fixed sequence in virtual time)."""
    rng = _virtual_addresses if world.mode() == "virtual" else random.SystemRandom()
    return "transform_listener_impl_%x" % (0x550000000000 + rng.randrange(0x10000000000) * 16)


def _seconds(ns, fixed):
    # std::cout: precision 3 fixed once a transform was printed, default (%g) before
    return "%.3f" % (ns / 1e9) if fixed else "%g" % (ns / 1e9)
