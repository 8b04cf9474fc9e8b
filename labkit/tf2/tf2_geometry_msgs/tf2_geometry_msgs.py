"""Transform geometry_msgs points, vectors and poses by a TransformStamped.

Importing this module registers the stamped types, so `buffer.transform(obj, frame)`
works for them (as in ROS, where the import is the whole point)."""
import numpy as np

from labkit.interfaces import get_type
from labkit.tf2.core import qmul, qrot
from labkit.tf2.ros.buffer_interface import ConvertRegistration, TransformRegistration

__all__ = ["do_transform_point", "do_transform_vector3", "do_transform_pose",
           "do_transform_pose_stamped", "do_transform_pose_with_covariance_stamped",
           "transform_covariance", "to_msg_msg", "from_msg_msg",
           # the real module's star-import hands these on too
           "Point", "PointStamped", "Pose", "PoseStamped", "PoseWithCovarianceStamped",
           "Vector3Stamped", "TransformStamped"]

Point = get_type("geometry_msgs/msg/Point")
PointStamped = get_type("geometry_msgs/msg/PointStamped")
Pose = get_type("geometry_msgs/msg/Pose")
PoseStamped = get_type("geometry_msgs/msg/PoseStamped")
PoseWithCovarianceStamped = get_type("geometry_msgs/msg/PoseWithCovarianceStamped")
Vector3Stamped = get_type("geometry_msgs/msg/Vector3Stamped")
TransformStamped = get_type("geometry_msgs/msg/TransformStamped")


def _tq(transform):
    tr = transform.transform.translation
    ro = transform.transform.rotation
    return (tr.x, tr.y, tr.z), (ro.x, ro.y, ro.z, ro.w)


def to_msg_msg(msg):
    return msg


def from_msg_msg(msg):
    return msg


for _t in (Vector3Stamped, PoseStamped, PointStamped):
    ConvertRegistration().add_to_msg(_t, to_msg_msg)
    ConvertRegistration().add_from_msg(_t, from_msg_msg)


def do_transform_point(point, transform):
    """PointStamped -> PointStamped in transform.header.frame_id."""
    t, q = _tq(transform)
    p = qrot(q, (point.point.x, point.point.y, point.point.z))
    res = PointStamped()
    res.point.x, res.point.y, res.point.z = p[0] + t[0], p[1] + t[1], p[2] + t[2]
    res.header = transform.header
    return res


def do_transform_vector3(vector3, transform):
    """Vector3Stamped -> Vector3Stamped: rotation only (a direction has no position)."""
    _, q = _tq(transform)
    v = qrot(q, (vector3.vector.x, vector3.vector.y, vector3.vector.z))
    res = Vector3Stamped()
    res.vector.x, res.vector.y, res.vector.z = v
    res.header = transform.header
    return res


def do_transform_pose(pose, transform):
    """Pose -> Pose (unstamped, as in Humble)."""
    t, q = _tq(transform)
    p = qrot(q, (pose.position.x, pose.position.y, pose.position.z))
    o = pose.orientation
    r = qmul(q, (o.x, o.y, o.z, o.w))
    res = Pose()
    res.position.x, res.position.y, res.position.z = p[0] + t[0], p[1] + t[1], p[2] + t[2]
    res.orientation.x, res.orientation.y, res.orientation.z, res.orientation.w = r
    return res


def do_transform_pose_stamped(pose, transform):
    res = PoseStamped()
    res.pose = do_transform_pose(pose.pose, transform)
    res.header = transform.header
    return res


def _rotation_matrix(q):
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def transform_covariance(cov_in, transform):
    """Rotate a 6x6 (row-major, 36 values) pose covariance into the new frame."""
    _, q = _tq(transform)
    r = _rotation_matrix(q)
    big = np.zeros((6, 6))
    big[:3, :3] = r
    big[3:, 3:] = r
    cov = np.asarray(cov_in, dtype=float).reshape(6, 6)
    return (big @ cov @ big.T).reshape(36).tolist()


def do_transform_pose_with_covariance_stamped(pose, transform):
    # the pose moves like a pose, its uncertainty turns with the rotation
    moved = PoseWithCovarianceStamped(header=transform.header)
    moved.pose.covariance = transform_covariance(pose.pose.covariance, transform)
    moved.pose.pose = do_transform_pose(pose.pose.pose, transform)
    return moved


TransformRegistration().add(PointStamped, do_transform_point)
TransformRegistration().add(Vector3Stamped, do_transform_vector3)
TransformRegistration().add(PoseStamped, do_transform_pose_stamped)
TransformRegistration().add(PoseWithCovarianceStamped, do_transform_pose_with_covariance_stamped)
