"""The simulated robot of the Gazebo chapter: labkit's 2D stand-in for
`ign gazebo -v 4 -r visualize_lidar.sdf` (vehicle_blue + a lidar), the
ros_gz_bridge parameter_bridge, and teleop_twist_keyboard.

labkit is not Gazebo: the world is flat, seen from above, and the physics is
a unicycle that stops at obstacles. The topics, message types, frames and the
bridge's command line are Gazebo's and ros_gz's.

    %ign gazebo -v 4 -r visualize_lidar.sdf     # start the world (a background job)
    %ign topic -l                               # Gazebo-side topics
    %ros2 run ros_gz_bridge parameter_bridge /lidar2@sensor_msgs/msg/LaserScan[ignition.msgs.LaserScan --ros-args -r /lidar2:=/laser_scan
    world2d.picture()                           # top-down PNG: world, robot, rays
"""

EXECUTABLES = {
    ("ros_gz_bridge", "parameter_bridge"): "labkit.sims.world2d.bridge:main",
    ("teleop_twist_keyboard", "teleop_twist_keyboard"): "labkit.sims.world2d.teleop:main",
}


def register():
    """Cheap: executables and the %ign magic (labkit.plugins calls it)."""
    from labkit import executables
    for (package, executable), target in EXECUTABLES.items():
        executables.register(package, executable, target)
    from labkit.plugins import register_magic
    register_magic("ign", _ign_magic)


def _ign_magic(line):
    from .gz_cli import ign_magic
    return ign_magic(line)


def ign(command):
    """Run an `ign` command line: 'gazebo -v 4 -r visualize_lidar.sdf' or 'topic -l'."""
    from .gz_cli import run
    return run(command)


def current():
    """The newest running simulation."""
    from .sim import current as _current
    return _current()


def picture(sim=None, **kwargs):
    """A top-down PNG (IPython Image) of the running world, robot and scan rays."""
    from .render import picture as _picture
    return _picture(sim, **kwargs)


def replay(sim=None, **kwargs):
    """An animated GIF (IPython Image) of the recent scans."""
    from .render import replay as _replay
    return _replay(sim, **kwargs)


def scan_points(sim=None, vehicle="vehicle_blue", frame="model"):
    """(N, 3) points of the last scan in the robot (model) frame, for the 3D viewer."""
    from .world import scan_points as _points
    sim = sim or current()
    v = sim.vehicle(vehicle)
    if v.ranges is None:
        import numpy as np
        return np.zeros((0, 3))
    return _points(v.ranges, v.config.lidar, frame=frame)


def press(*keys):
    """Type keys into the running teleop_twist_keyboard (see teleop.press)."""
    from .teleop import press as _press
    return _press(*keys)
