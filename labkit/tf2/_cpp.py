"""Small pieces the C++ tools (static_transform_publisher, tf2_echo) need."""
import math
import re
import sys

from labkit.graph import world

_FLOAT_PREFIX = re.compile(
    r"\s*[+-]?(?:inf(?:inity)?|nan|0[xX][0-9a-fA-F]*\.?[0-9a-fA-F]*(?:[pP][+-]?\d+)?|"
    r"(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)", re.IGNORECASE)


def stod(text):
    """std::stod: the longest leading float ("1.5abc" -> 1.5); ValueError if none."""
    return stod_pos(text)[0]


def stod_pos(text):
    """(value, number of characters used), like std::stod(text, &pos)."""
    m = _FLOAT_PREFIX.match(text)
    if not m:
        raise ValueError(text)
    return _float(m.group(0).strip()), m.end()


def _float(s):
    if s.lower().lstrip("+-").startswith("0x"):
        sign = -1.0 if s.startswith("-") else 1.0
        body = s.lstrip("+-")
        if "p" not in body.lower():
            body += "p0"
        return sign * float.fromhex(body)
    return float(s)


def rcutils_log(severity, message):
    """RCUTILS_LOG_* (no logger name): '[SEVERITY] [sec.nsec] []: message' on stderr."""
    ns = world.system_ns()
    sys.stderr.write("[%s] [%d.%09d] []: %s\n" % (severity, ns // 10**9, ns % 10**9, message))


def quaternion_from_rpy(roll, pitch, yaw):
    """tf2::Quaternion::setRPY (x, y, z, w)."""
    hr, hp, hy = roll / 2.0, pitch / 2.0, yaw / 2.0
    cr, sr = math.cos(hr), math.sin(hr)
    cp, sp = math.cos(hp), math.sin(hp)
    cy, sy = math.cos(hy), math.sin(hy)
    return (sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


def matrix3(q):
    """tf2::Matrix3x3 from a quaternion (rows)."""
    x, y, z, w = q
    d = x * x + y * y + z * z + w * w
    s = 2.0 / d
    xs, ys, zs = x * s, y * s, z * s
    wx, wy, wz = w * xs, w * ys, w * zs
    xx, xy, xz = x * xs, x * ys, x * zs
    yy, yz, zz = y * ys, y * zs, z * zs
    return ((1.0 - (yy + zz), xy - wz, xz + wy),
            (xy + wz, 1.0 - (xx + zz), yz - wx),
            (xz - wy, yz + wx, 1.0 - (xx + yy)))


def euler_ypr(m):
    """tf2::Matrix3x3::getEulerYPR, first solution: (yaw, pitch, roll)."""
    if abs(m[2][0]) >= 1:
        delta = math.atan2(m[2][1], m[2][2])
        pitch = math.pi / 2.0 if m[2][0] < 0 else -math.pi / 2.0
        return 0.0, pitch, delta
    pitch = -math.asin(m[2][0])
    c = math.cos(pitch)
    roll = math.atan2(m[2][1] / c, m[2][2] / c)
    yaw = math.atan2(m[1][0] / c, m[0][0] / c)
    return yaw, pitch, roll


_QOS = {"/parameter_events": (("depth", 1000), ("durability", "volatile"),
                              ("history", "keep_last"), ("reliability", "reliable")),
        "/tf_static": (("depth", 1), ("durability", "transient_local"),
                       ("history", "keep_last"), ("reliability", "reliable"))}


def like_rclcpp(node, publishers=("/parameter_events",)):
    """What an rclcpp node shows that an rclpy node does not: rclcpp's parameter texts,
    read-only qos_overrides.<topic>.publisher.* parameters, and the /parameter_events
    subscription of its time source."""
    from labkit.interfaces import get_type
    from labkit.rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
    ParameterDescriptor = get_type("rcl_interfaces/msg/ParameterDescriptor")
    node._labkit_parameter_dialect = "rclcpp"
    for topic in publishers:
        for policy, value in _QOS[topic]:
            name = "qos_overrides.%s.publisher.%s" % (topic, policy)
            if not node.has_parameter(name):
                node.declare_parameter(name, value, ParameterDescriptor(
                    description="qos policy {%s} for publisher {%s}" % (policy, topic),
                    read_only=True))
    qos = QoSProfile(depth=1000, history=HistoryPolicy.KEEP_LAST,
                     reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.VOLATILE)
    node._rclcpp_time_source_events = node.create_subscription(
        get_type("rcl_interfaces/msg/ParameterEvent"), "/parameter_events", lambda e: None, qos)
