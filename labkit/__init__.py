"""labkit: a faithful ROS 2 Humble graph inside one Python process.

The public surface a notebook needs is small:

    %load_ext labkit                 # activate: `import rclpy` etc. now resolve to labkit
    labkit.ros2("topic list -t")     # run a ros2 verb, get returncode/stdout/stderr
    labkit.sleep(2.0)                # let the graph live for 2 s (simulated in virtual time)
    labkit.reset()                   # stop every process, clear the graph

Everything else is ordinary ROS 2 code.
"""
__version__ = "0.1.0"

__all__ = ["ros2", "colcon", "source", "rosdep", "sleep", "reset", "activate", "time_mode", "set_time_mode",
           "connect", "disconnect",
           "load_ipython_extension",
           "unload_ipython_extension"]


def ros2(command, **kwargs):
    """Run one `ros2` command line (without the leading `ros2`).

    Returns a CompletedProcess-like object (returncode, stdout, stderr); verbs
    that keep running (run, echo, hz, ...) return a background job at once.
    """
    from labkit.cli.ros2 import run_command
    return run_command(command, **kwargs)


def colcon(command=""):
    """Run one `colcon` command line in the current folder (build, list); like ros2()."""
    from labkit.ament import colcon as _colcon
    return _colcon.run_command(command)


def source(path="install/setup.bash"):
    """`source install/setup.bash`: make a built workspace's packages visible; returns 0 on success."""
    from labkit.ament import source as _source
    return _source.run(path)


def rosdep(command=""):
    """Run one `rosdep` command line (install, resolve, keys, check, ...); like ros2()."""
    from labkit.ament import rosdep as _rosdep
    return _rosdep.run_command(command)


def sleep(seconds):
    """Let the whole graph run for `seconds` (wall-clock in live mode, simulated in virtual mode)."""
    from labkit.graph import world
    world.sleep(seconds)


def reset():
    """Stop every process and background job, shut every context down, clear the graph."""
    from labkit import process
    process.reset_all()
    import sys as _sys
    if "labkit.dds" in _sys.modules:  # a DDS connection ends with everything else
        _sys.modules["labkit.dds"].disconnect()
    from labkit.rclpy import utilities as _rclpy_utilities
    _rclpy_utilities.forget_after_reset()   # a later rclpy.shutdown() in the notebook is fine
    import sys
    meshcat_view = sys.modules.get('labkit.viz.meshcat_view')
    if meshcat_view is not None:   # the 3D viewer's live parts (views following /tf)
        meshcat_view.stop_all()
    daemon = sys.modules.get('labkit.cli.ros2.daemon')
    if daemon is not None:         # `ros2 daemon status` starts over: not running
        daemon.reset()
    graph_view = sys.modules.get('labkit.viz.graph_view')
    if graph_view is not None:     # live graph views and consoles hold nodes of their own
        graph_view.stop_all()
    try:  # goal ids restart too, so a notebook re-run from here prints the same ids
        from labkit.rclpy.action import _common
        _common.reset_virtual_uuids()
    except (ImportError, AttributeError):
        pass


def connect(domain_id=None, localhost_only=None):
    """Join the real ROS 2 graph over DDS (live time only; see labkit/dds/__init__.py).

    domain_id: default ROS_DOMAIN_ID or 0. localhost_only: default True (loopback),
    unless ROS_LOCALHOST_ONLY=0 / ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET say otherwise."""
    from labkit import dds
    return dds.connect(domain_id, localhost_only)


def disconnect():
    """Leave the DDS network; the in-process graph stays."""
    from labkit import dds
    dds.disconnect()


def time_mode():
    """'live' or 'virtual' (see labkit/ARCHITECTURE.md, 'Time and determinism')."""
    from labkit.graph import world
    return world.mode()


def set_time_mode(mode):
    """Choose 'live' or 'virtual' time before anything has started (see ARCHITECTURE.md)."""
    from labkit.graph import world
    world.set_mode(mode)


def activate():
    """Make `import rclpy`, `import std_msgs.msg`, ... resolve to labkit (never over a sourced ROS)."""
    from labkit import compat
    return compat.activate()


def load_ipython_extension(ipython):
    from labkit.cli import magics
    magics.load_ipython_extension(ipython)


def unload_ipython_extension(ipython):
    from labkit.cli import magics
    magics.unload_ipython_extension(ipython)
