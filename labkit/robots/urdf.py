"""URDF models: parse (with urdf_parser_py, ROS's own Python parser) and compute
the transforms robot_state_publisher publishes.

`load(text_or_path)` returns a `RobotModel`; a malformed description raises
`URDFError` whose message names the file and the offending element.
"""
import math
import os
import xml.etree.ElementTree as ET

import numpy as np

MOVABLE = ("revolute", "continuous", "prismatic")


class URDFError(ValueError):
    """A robot description that urdf::Model would refuse."""


def _quiet_parser():
    # urdf_parser_py prints "Unknown tag" for <gazebo>, <transmission> ...;
    # urdf::Model ignores those silently, so do we.
    from urdf_parser_py import xml_reflection
    xml_reflection.core.on_error = lambda message: None
    from urdf_parser_py.urdf import URDF
    return URDF


def _where(filename):
    return f"'{filename}'" if filename else "robot_description"


def load(source, filename=None):
    """Parse a URDF given as XML text or as a path to a .urdf file."""
    text = source
    if not source.lstrip().startswith("<"):
        filename = source
        try:
            with open(source, encoding="utf-8") as handle:
                text = handle.read()
        except OSError as exc:
            raise URDFError(f"Failed to open URDF file: {source} ({exc.strerror})") from None
    return RobotModel(text, filename)


def rpy_matrix(rpy):
    """URDF rpy: fixed-axis roll about X, then pitch about Y, then yaw about Z."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = (math.cos(r), math.sin(r), math.cos(p), math.sin(p),
                              math.cos(y), math.sin(y))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def pose_matrix(xyz=(0.0, 0.0, 0.0), rpy=(0.0, 0.0, 0.0)):
    m = np.eye(4)
    m[:3, :3] = rpy_matrix(rpy)
    m[:3, 3] = xyz
    return m


def axis_angle_matrix(axis, angle):
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    t = 1.0 - c
    return np.array([[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                     [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                     [t * x * z - s * y, t * y * z + s * x, t * z * z + c]])


def quaternion_from_matrix(r):
    """(x, y, z, w) of a rotation matrix, w >= 0 (Shepperd's method: plain floats are
    faster than scipy for one matrix at a time)."""
    (m00, m01, m02), (m10, m11, m12), (m20, m21, m22) = r.tolist()
    trace = m00 + m11 + m22
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s)
    elif m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        q = (0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s)
    elif m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        q = ((m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
        q = ((m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s)
    return q if q[3] >= 0 else tuple(-v for v in q)


class Joint:
    """One joint as robot_state_publisher sees it (a KDL segment)."""

    def __init__(self, j):
        self.name = j.name
        self.type = j.type
        self.parent = j.parent
        self.child = j.child
        origin = j.origin
        self.origin = pose_matrix(origin.xyz if origin and origin.xyz else (0, 0, 0),
                                  origin.rpy if origin and origin.rpy else (0, 0, 0))
        axis = np.array(j.axis if j.axis is not None else (1.0, 0.0, 0.0), dtype=float)
        norm = np.linalg.norm(axis)
        self.axis = axis / norm if norm > 0 else np.array([1.0, 0.0, 0.0])
        self.limit = j.limit
        self.mimic = j.mimic

    @property
    def movable(self):
        return self.type in MOVABLE

    def matrix(self, position=0.0):
        """Pose of the child link in the parent link for this joint position."""
        if self.type in ("revolute", "continuous"):
            motion = np.eye(4)
            motion[:3, :3] = axis_angle_matrix(self.axis, position)
            return self.origin @ motion
        if self.type == "prismatic":
            m = self.origin.copy()
            m[:3, 3] += self.origin[:3, :3] @ (self.axis * position)
            return m
        return self.origin

    def transform(self, position=0.0):
        """((x, y, z), (qx, qy, qz, qw)) of the child in the parent."""
        m = self.matrix(position)
        return tuple(float(v) for v in m[:3, 3]), quaternion_from_matrix(m[:3, :3])


class RobotModel:
    """A parsed URDF: links, joints, materials, the kinematic tree."""

    def __init__(self, text, filename=None):
        self.xml = text
        self.filename = filename
        where = _where(filename)
        try:
            root = ET.fromstring(text)
        except ET.ParseError as exc:
            raise URDFError(f"Error parsing {where}: {exc}") from None
        if root.tag != "robot":
            raise URDFError(f"Error parsing {where}: Could not find the 'robot' element "
                            f"in the xml file (found <{root.tag}>)")
        URDF = _quiet_parser()
        try:
            self.urdf = URDF.from_xml_string(text)
        except Exception as exc:   # urdf_parser_py's ParseError names the XPath
            message = " ".join(str(exc).split())
            raise URDFError(f"Error parsing {where}: {message}") from None
        self.name = self.urdf.name
        self.links = {link.name: link for link in self.urdf.links}
        if not self.links:
            raise URDFError(f"Error parsing {where}: No link elements found in urdf file")
        self.joints = {}
        for j in self.urdf.joints:
            if j.type in ("revolute", "prismatic") and j.limit is None:
                raise URDFError(f"Error parsing {where}: joint '{j.name}' of type "
                                f"'{j.type}' has no <limit> element")
            self.joints[j.name] = Joint(j)
        self.root = self._find_root(where)
        self.materials = {m.name: m for m in self.urdf.materials}

    def _find_root(self, where):
        # urdfdom's ModelInterface::initTree, then initRoot: joints and links in name order
        # (std::map), the child looked up before the parent, the texts of its ParseErrors
        # after parseURDF's "Failed to build tree: " / "Failed to find root link: "
        parent_of = {}
        twice = None
        for name in sorted(self.joints):
            j = self.joints[name]
            if j.child not in self.links:
                raise URDFError(f"Failed to build tree: child link [{j.child}] of joint "
                                f"[{name}] not found")
            if j.parent not in self.links:
                raise URDFError(
                    f"Failed to build tree: parent link [{j.parent}] of joint [{name}] not "
                    "found.  This is not valid according to the URDF spec. Every link you "
                    "refer to from a joint needs to be explicitly defined in the robot "
                    f"description. To fix this problem you can either remove this joint "
                    f"[{name}] from your urdf file, or add \"<link name=\"{j.parent}\" />\" "
                    "to your urdf file.")
            if j.child in parent_of and twice is None:
                twice = j.child
            parent_of[j.child] = j.parent
        root = None
        for name in sorted(self.links):
            if name not in parent_of:
                if root is not None:
                    raise URDFError(f"Failed to find root link: Two root links found: "
                                    f"[{root}] and [{name}]")
                root = name
        if root is None:
            raise URDFError("Failed to find root link: No root link found. The robot xml is "
                            "not a valid tree.")
        if twice is not None:
            # urdfdom lets the last joint win; KDL then meets the link twice and refuses
            raise URDFError(f"Error parsing {where}: link '{twice}' has two parents")
        return root

    # -- tree ----------------------------------------------------------------
    def movable_joints(self):
        return [j for j in self.joints.values() if j.movable]

    def fixed_joints(self):
        """Joints robot_state_publisher sends on /tf_static (floating ones are skipped)."""
        return [j for j in self.joints.values() if j.type == "fixed"]

    def children(self, link):
        return [j for j in self.joints.values() if j.parent == link]

    def link_poses(self, positions=None):
        """{link: 4x4 pose in the root link} for {joint: position} (missing ones are 0)."""
        positions = positions or {}
        poses = {self.root: np.eye(4)}
        stack = [self.root]
        while stack:
            link = stack.pop()
            for j in self.children(link):
                q = positions.get(j.name, 0.0)
                if j.mimic is not None and j.name not in positions:
                    q = (positions.get(j.mimic.joint, 0.0) * (j.mimic.multiplier or 1.0)
                         + (j.mimic.offset or 0.0))
                poses[j.child] = poses[link] @ j.matrix(q)
                stack.append(j.child)
        return poses

    def material_rgba(self, visual):
        """RGBA of a visual's material (a named material defined at top level), or None."""
        material = visual.material
        if material is None:
            return None
        if material.color is not None:
            return tuple(material.color.rgba)
        named = self.materials.get(material.name)
        if named is not None and named.color is not None:
            return tuple(named.color.rgba)
        return None


def read_text(path):
    """A description file as text: .xacro files are expanded first."""
    if path.endswith(".xacro"):
        from labkit.robots import xacro_support
        return xacro_support.process(path)
    with open(path, encoding="utf-8") as handle:
        return handle.read()


def is_path(value):
    return isinstance(value, (str, os.PathLike)) and not str(value).lstrip().startswith("<")


def check_urdf(path):
    """What urdfdom's `check_urdf FILE` prints: the robot's name and its link tree,
    each link's children in the order of their joints' names (urdf::Model keeps joints
    in a std::map). Returns (exit code, text); a file it cannot read or parse exits 255 (-1)."""
    if not os.path.isfile(path):
        return 255, f"Could not open file [{path}] for parsing."
    try:
        model = load(path)
    except URDFError as exc:
        return 255, f"Error:   {exc}\nERROR: Model Parsing the xml failed"
    by_parent = {}
    for name in sorted(model.joints):
        joint = model.joints[name]
        by_parent.setdefault(joint.parent, []).append(joint.child)
    lines = [f"robot name is: {model.name}",
             "---------- Successfully Parsed XML ---------------",
             f"root Link: {model.root} has {len(by_parent.get(model.root, []))} child(ren)"]

    def tree(link, level):
        level += 2
        for count, child in enumerate(by_parent.get(link, []), 1):
            lines.append("  " * level + f"child({count}):  {child}")
            tree(child, level)
    tree(model.root, 0)
    return 0, "\n".join(lines)
