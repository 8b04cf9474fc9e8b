"""`import tf_transformations`: the ROS 1 transformations API, quaternions in x, y, z, w.

Euler axes strings as in transformations.py: 's' static (extrinsic) or 'r' rotating
(intrinsic) and the axis order, default 'sxyz' (roll about x, pitch y, yaw z)."""
import math

import numpy as np

__all__ = ["quaternion_from_euler", "euler_from_quaternion", "quaternion_multiply",
           "quaternion_inverse", "quaternion_conjugate", "quaternion_matrix",
           "quaternion_from_matrix", "euler_matrix", "euler_from_matrix",
           "translation_matrix", "translation_from_matrix", "concatenate_matrices",
           "inverse_matrix", "quaternion_slerp", "identity_matrix", "unit_vector"]


def _scipy_seq(axes):
    if len(axes) != 4 or axes[0] not in "sr" or set(axes[1:]) - set("xyz"):
        raise KeyError(axes)
    return axes[1:] if axes[0] == "s" else axes[1:].upper()


def _rotation(quaternion):
    from scipy.spatial.transform import Rotation
    return Rotation.from_quat(np.asarray(quaternion, dtype=float))


def quaternion_from_euler(ai, aj, ak, axes="sxyz"):
    """Quaternion [x, y, z, w] from Euler angles (radians)."""
    if axes == "sxyz":
        ci, si = math.cos(ai / 2.0), math.sin(ai / 2.0)
        cj, sj = math.cos(aj / 2.0), math.sin(aj / 2.0)
        ck, sk = math.cos(ak / 2.0), math.sin(ak / 2.0)
        cc, cs, sc, ss = ci * ck, ci * sk, si * ck, si * sk
        return np.array([cj * sc - sj * cs, cj * ss + sj * cc,
                         cj * cs - sj * sc, cj * cc + sj * ss])
    from scipy.spatial.transform import Rotation
    return Rotation.from_euler(_scipy_seq(axes), [ai, aj, ak]).as_quat()


def euler_from_quaternion(quaternion, axes="sxyz"):
    """(ai, aj, ak) from a quaternion [x, y, z, w]."""
    return euler_from_matrix(quaternion_matrix(quaternion), axes)


def euler_matrix(ai, aj, ak, axes="sxyz"):
    return quaternion_matrix(quaternion_from_euler(ai, aj, ak, axes))


def euler_from_matrix(matrix, axes="sxyz"):
    m = np.asarray(matrix, dtype=float)[:3, :3]
    if axes == "sxyz":
        # the closed form of transformations.py, which handles gimbal lock its own way
        cy = math.sqrt(m[0, 0] * m[0, 0] + m[1, 0] * m[1, 0])
        if cy > 4 * np.finfo(float).eps:
            return (math.atan2(m[2, 1], m[2, 2]), math.atan2(-m[2, 0], cy),
                    math.atan2(m[1, 0], m[0, 0]))
        return (math.atan2(-m[1, 2], m[1, 1]), math.atan2(-m[2, 0], cy), 0.0)
    from scipy.spatial.transform import Rotation
    return tuple(float(v) for v in Rotation.from_matrix(m).as_euler(_scipy_seq(axes)))


def quaternion_multiply(quaternion1, quaternion0):
    """quaternion1 * quaternion0 (apply quaternion0 first)."""
    x0, y0, z0, w0 = quaternion0
    x1, y1, z1, w1 = quaternion1
    return np.array([x1 * w0 + y1 * z0 - z1 * y0 + w1 * x0,
                     -x1 * z0 + y1 * w0 + z1 * x0 + w1 * y0,
                     x1 * y0 - y1 * x0 + z1 * w0 + w1 * z0,
                     -x1 * x0 - y1 * y0 - z1 * z0 + w1 * w0], dtype=float)


def quaternion_conjugate(quaternion):
    x, y, z, w = quaternion
    return np.array([-x, -y, -z, w], dtype=float)


def quaternion_inverse(quaternion):
    q = np.asarray(quaternion, dtype=float)
    return quaternion_conjugate(q) / np.dot(q, q)


def quaternion_matrix(quaternion):
    """4x4 homogeneous rotation matrix."""
    q = np.array(quaternion, dtype=float)
    n = np.dot(q, q)
    out = np.identity(4)
    if n < np.finfo(float).eps * 4.0:
        return out
    q *= math.sqrt(2.0 / n)
    x, y, z, w = q
    out[:3, :3] = [[1.0 - y * y - z * z, x * y - z * w, x * z + y * w],
                   [x * y + z * w, 1.0 - x * x - z * z, y * z - x * w],
                   [x * z - y * w, y * z + x * w, 1.0 - x * x - y * y]]
    return out


def quaternion_from_matrix(matrix):
    from scipy.spatial.transform import Rotation
    q = Rotation.from_matrix(np.asarray(matrix, dtype=float)[:3, :3]).as_quat()
    return q if q[3] >= 0 else -q


def quaternion_slerp(quat0, quat1, fraction, spin=0, shortestpath=True):
    q0 = np.asarray(quat0, dtype=float) / np.linalg.norm(quat0)
    q1 = np.asarray(quat1, dtype=float) / np.linalg.norm(quat1)
    if fraction == 0.0:
        return q0
    if fraction == 1.0:
        return q1
    d = float(np.dot(q0, q1))
    if abs(abs(d) - 1.0) < np.finfo(float).eps * 4.0:
        return q0
    if shortestpath and d < 0.0:
        d, q1 = -d, -q1
    angle = math.acos(max(-1.0, min(1.0, d))) + spin * math.pi
    if abs(angle) < np.finfo(float).eps * 4.0:
        return q0
    isin = 1.0 / math.sin(angle)
    return ((math.sin((1.0 - fraction) * angle) * isin) * q0
            + (math.sin(fraction * angle) * isin) * q1)


def identity_matrix():
    return np.identity(4)


def translation_matrix(direction):
    m = np.identity(4)
    m[:3, 3] = np.asarray(direction, dtype=float)[:3]
    return m


def translation_from_matrix(matrix):
    return np.array(matrix, copy=True)[:3, 3]


def concatenate_matrices(*matrices):
    m = np.identity(4)
    for i in matrices:
        m = np.dot(m, i)
    return m


def inverse_matrix(matrix):
    return np.linalg.inv(matrix)


def unit_vector(data, axis=None):
    data = np.array(data, dtype=float, copy=True)
    if axis is None:
        return data / math.sqrt(np.dot(data, data))
    return data / np.expand_dims(np.sqrt(np.sum(data * data, axis=axis)), axis)
