"""The facer robot on the move: the motion the URDF chapter's `state_publisher` node
publishes (facer drives a 0.6 m circle while its head pans left and right, looking
for faces, and its mast rises and sinks), as plain functions of time, so the book's
stored animation and the live node agree.

`drive_view()` is that motion as an animated meshcat snapshot;
`start_robot_state_publisher()` starts robot_state_publisher with a description,
what a launch file's Node(parameters=[{'robot_description': ...}]) does.
"""
import math
import os

RADIUS = 0.6            # m, the circle facer drives
SPEED = 0.2             # m/s along it
TRACK = 0.25            # m between the wheels (07-physics.urdf: y = +-0.125)
WHEEL_RADIUS = 0.05     # m, also base_link's height above the floor


def model_path(step="07-physics.urdf"):
    from labkit.robots import packages
    return os.path.join(packages.share_directory("facer_description"), "urdf", step)


def joints_at(t):
    """{joint: position} at t seconds."""
    turned = SPEED * t / RADIUS                       # rad around the circle
    return {
        "left_wheel_joint": (RADIUS - TRACK / 2) * turned / WHEEL_RADIUS,
        "right_wheel_joint": (RADIUS + TRACK / 2) * turned / WHEEL_RADIUS,
        "head_pan": 1.2 * math.sin(0.8 * t),
        "mast_lift": 0.04 - 0.04 * math.cos(0.5 * t),
    }


def base_at(t):
    """(xyz, yaw) of base_link in odom at t seconds: counter-clockwise (turning left, so
    the left wheel runs on the inner circle) around (0, RADIUS), starting at the origin."""
    turned = SPEED * t / RADIUS
    xyz = (RADIUS * math.sin(turned), RADIUS - RADIUS * math.cos(turned), WHEEL_RADIUS)
    return xyz, turned


def drive_view(seconds=12.0, fps=10):
    """The driving facer as an animated snapshot (odom fixed, base_link moving)."""
    import numpy as np
    from labkit.robots.urdf import pose_matrix
    from labkit.viz.meshcat_view import RobotView
    view = RobotView(model_path(), frame_scale=0.08)
    frames = []
    for k in range(int(seconds * fps)):
        t = k / fps
        xyz, yaw = base_at(t)
        base = pose_matrix(xyz, (0, 0, yaw))
        poses = {n: base @ m for n, m in view.model.link_poses(joints_at(t)).items()}
        poses["odom"] = np.eye(4)
        frames.append(poses)
    view.animate(frames, fps=fps)
    return view


def start_robot_state_publisher(description, echo=True, extra_args=()):
    """Start robot_state_publisher with `robot_description` set (what a launch file does)."""
    from labkit import process
    from labkit.robots import robot_state_publisher

    def run(args=None):
        return robot_state_publisher.main_with_description(description, args)
    return process.start(main=run, name="robot_state_publisher", echo=echo,
                         args=["robot_state_publisher", *extra_args])
