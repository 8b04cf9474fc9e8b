"""The TF tree as data: parents, roots, and every frame as a 4x4 in one fixed frame."""
import numpy as np

from labkit.tf2.core import TransformException

__all__ = ["parents", "roots", "snapshot", "matrix"]


def parents(buffer):
    """{child: parent} for every frame the buffer has data for."""
    return {child: parent for child, (parent, _, _) in buffer.frames().items()}


def roots(buffer):
    """Frames that are nobody's child, sorted (a healthy tree has exactly one)."""
    tree = parents(buffer)
    return sorted({p for p in tree.values() if p not in tree})


def matrix(translation, rotation):
    """4x4 homogeneous matrix from (x, y, z) and a quaternion (x, y, z, w)."""
    x, y, z, w = rotation
    m = np.identity(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = translation
    return m


def snapshot(buffer, fixed_frame=None, time=None):
    """{frame: 4x4 pose of the frame in fixed_frame} for every frame connected to it.

    fixed_frame defaults to the root of the tree (the first root, sorted, if the
    tree is broken); time defaults to the latest data (each frame on its own).
    Frames that cannot be looked up at that time are left out."""
    from labkit.rclpy.time import Time
    tree = parents(buffer)
    if fixed_frame is None:
        found = roots(buffer)
        if not found:
            return {}
        fixed_frame = found[0]
    when = Time() if time is None else time
    out = {fixed_frame: np.identity(4)}
    for frame in sorted(set(tree) | set(tree.values())):
        if frame == fixed_frame:
            continue
        try:
            msg = buffer.lookup_transform_core(fixed_frame, frame, when)
        except TransformException:
            continue
        tr, ro = msg.transform.translation, msg.transform.rotation
        out[frame] = matrix((tr.x, tr.y, tr.z), (ro.x, ro.y, ro.z, ro.w))
    return out
