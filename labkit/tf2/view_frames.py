"""`ros2 run tf2_tools view_frames`: listen to TF, write frames_<date>.gv and .pdf.

`svg(source)` draws the same picture for the book (source: a Buffer, the YAML
tf2 gives, or dot text / a .gv path)."""
import argparse
import contextlib
import os
import sys
import threading
import time as _time

import labkit.rclpy as rclpy
from labkit.interfaces import get_type

__all__ = ["main", "generate_dot", "svg", "render", "listen"]


def main(args=None):
    argv = list(sys.argv if args is None else args)
    rclpy.init(args=argv)
    args_without_ros = rclpy.utilities.remove_ros_args(argv)
    parser = argparse.ArgumentParser(
        prog="view_frames",
        description="Create a diagram of the TF frames being broadcast over ROS")
    parser.add_argument(
        "--wait-time", "-t", type=float, default=5.0,
        help="Listen to the /tf topic for this many seconds before rendering the frame tree")
    parser.add_argument("-o", "--output", help="Output filename")
    parsed_args = parser.parse_args(args=args_without_ros[1:])

    from labkit.tf2.ros import Buffer, TransformListener
    FrameGraph = get_type("tf2_msgs/srv/FrameGraph")
    node = rclpy.create_node("view_frames")
    buf = Buffer(node=node)
    TransformListener(buf, node, spin_thread=False)

    node.get_logger().info(f"Listening to tf data for {parsed_args.wait_time} seconds...")
    clock = node.get_clock()   # ROS wall clock: simulated seconds in virtual time
    end = clock.now().nanoseconds + int(parsed_args.wait_time * 1e9)
    while clock.now().nanoseconds < end:
        rclpy.spin_once(node, timeout_sec=0.1)

    node.get_logger().info("Generating graph in frames.pdf file...")
    cli = node.create_client(FrameGraph, "tf2_frames")
    while not cli.wait_for_service(timeout_sec=1.0):
        node.get_logger().info("service not available, waiting again...")
    future = cli.call_async(FrameGraph.Request())
    rclpy.spin_until_future_complete(node, future)

    ret = 1
    try:
        result = future.result()
        ret = 0
    except Exception as e:
        node.get_logger().error("Service call failed %r" % (e,))
    else:
        import yaml
        node.get_logger().info("Result:" + str(result))
        data = yaml.safe_load(result.frame_yaml)
        if parsed_args.output is not None:
            frames_gv = "{:s}.gv".format(parsed_args.output)
            frames_pdf = "{:s}.pdf".format(parsed_args.output)
        else:
            sec, _ = clock.now().seconds_nanoseconds()
            stamp = _time.strftime("%Y-%m-%d_%H.%M.%S", _time.localtime(sec))
            frames_gv = "frames_{:s}.gv".format(stamp)
            frames_pdf = "frames_{:s}.pdf".format(stamp)
        dot = generate_dot(data, clock.now().seconds_nanoseconds())
        with open(frames_gv, "w", encoding="utf-8") as f:
            f.write(dot)
        with open(frames_pdf, "wb") as f:
            f.write(render(dot, "pdf"))
    finally:
        cli.destroy()
        node.destroy_node()
        rclpy.try_shutdown()
    return ret


def generate_dot(data, recorded_time):
    """The dot text tf2_tools writes, from tf2's frame YAML (already parsed)."""
    if not data:
        return 'digraph G { "No tf data received" }'
    dot = "digraph G {\n"
    root = None
    for el in data:
        entry = data[el]
        dot += '"' + entry["parent"] + '" -> "' + str(el) + '"'
        dot += '[label=" '
        dot += "Broadcaster: " + entry["broadcaster"] + "\\n"
        dot += "Average rate: " + str(entry["rate"]) + "\\n"
        dot += "Buffer length: " + str(entry["buffer_length"]) + "\\n"
        dot += "Most recent transform: " + str(entry["most_recent_transform"]) + "\\n"
        dot += "Oldest transform: " + str(entry["oldest_transform"]) + "\\n"
        dot += '"];\n'
        if entry["parent"] not in data:
            root = entry["parent"]
    dot += "edge [style=invis];\n"
    dot += ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n'
    dot += ('"Recorded at time: ' + str(recorded_time[0] + recorded_time[1] / 1e9)
            + '"[ shape=plaintext ] ;\n')
    dot += '}->"' + str(root) + '";\n}'
    return dot


class SVG(str):
    """SVG text that a notebook shows as a picture."""

    def _repr_svg_(self):
        return str(self)


_first = threading.Lock()
_quiet_done = False


@contextlib.contextmanager
def _quiet_once():
    # graphviz's bundled fontconfig may complain once on fd 2 about this machine's config
    global _quiet_done
    with _first:
        if _quiet_done:
            yield
            return
        _quiet_done = True
        try:
            sys.stderr.flush()
            saved = os.dup(2)
        except (OSError, ValueError, AttributeError):
            yield
            return
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 2)
        os.close(devnull)
        try:
            yield
        finally:
            os.dup2(saved, 2)
            os.close(saved)


def render(dot, fmt="svg"):
    """Lay dot text out with graphviz (pygraphviz's bundled dot): bytes of `fmt`."""
    import pygraphviz as pgv
    with _quiet_once():
        return pgv.AGraph(string=dot).draw(format=fmt, prog="dot")


def svg(source=None, recorded_time=None, wait_time=1.0):
    """The view_frames picture as SVG text, from a Buffer, a frame-YAML dict/str, or dot.

    Without a source, listen to /tf and /tf_static for `wait_time` seconds first (a
    notebook's view_frames, drawn in the page instead of a PDF)."""
    if source is None:
        source = listen(wait_time)
    if hasattr(source, "all_frames_as_yaml"):
        import yaml
        data = yaml.safe_load(source.all_frames_as_yaml())
        dot = generate_dot(data, recorded_time or _now())
    elif isinstance(source, dict):
        dot = generate_dot(source, recorded_time or _now())
    elif isinstance(source, str) and source.lstrip().startswith(("digraph", "graph", "strict")):
        dot = source
    elif isinstance(source, (str, os.PathLike)) and str(source).endswith(".gv"):
        with open(source, encoding="utf-8") as f:
            dot = f.read()
    else:
        import yaml
        dot = generate_dot(yaml.safe_load(source), recorded_time or _now())
    return SVG(render(dot, "svg").decode("utf-8"))


def listen(wait_time=1.0):
    """A Buffer filled by listening to TF for wait_time seconds (own context and node)."""
    from labkit.rclpy.context import Context
    from labkit.rclpy.executors import SingleThreadedExecutor
    from labkit.tf2.ros import Buffer, TransformListener
    context = Context()
    rclpy.init(context=context)
    try:
        node = rclpy.create_node("view_frames", context=context)
        buffer = Buffer()
        TransformListener(buffer, node)
        executor = SingleThreadedExecutor(context=context)
        executor.add_node(node)
        clock = node.get_clock()
        end = clock.now().nanoseconds + int(wait_time * 1e9)
        while clock.now().nanoseconds < end:
            executor.spin_once(timeout_sec=(end - clock.now().nanoseconds) / 1e9)
        executor.shutdown()
        node.destroy_node()
    finally:
        rclpy.try_shutdown(context=context)
    return buffer


def _now():
    from labkit.graph import world
    ns = world.system_ns()
    return ns // 10**9, ns % 10**9
