"""`ros2 run ros_gz_bridge parameter_bridge TOPIC@ROS_TYPE(@|[|])GZ_TYPE ...`

The node /ros_gz_bridge (C++ in real ROS, hence rclcpp's texts) carries
messages between labkit's Gazebo-transport stand-in and the ROS graph:
`@` both ways, `[` Gazebo -> ROS, `]` ROS -> Gazebo. The ROS side is an
ordinary publisher/subscription, so `--ros-args -r /lidar2:=/laser_scan`
renames it; the Gazebo side keeps the name given.
"""
import array
import sys
from dataclasses import dataclass

import numpy as np

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.node import Node
from labkit.rclpy.utilities import remove_ros_args

from . import transport as gz

USAGE = (
    "Bridge a collection of ROS2 and Gazebo Transport topics and services.\n\n"
    "  parameter_bridge [<topic@ROS2_type@Ign_type> ..]  "
    "[<service@ROS2_srv_type[@Ign_req_type@Ign_rep_type]> ..]\n\n"
    "Topics: The first @ symbol delimits the topic name from the message types.\n"
    "Following the first @ symbol is the ROS message type.\n"
    "The ROS message type is followed by an @, [, or ] symbol where\n"
    "    @  == a bidirectional bridge, \n"
    "    [  == a bridge from Gazebo to ROS,\n"
    "    ]  == a bridge from ROS to Gazebo.\n"
    "Following the direction symbol is the Gazebo Transport message type.\n\n"
    "Services: The first @ symbol delimits the service name from the types.\n"
    "Following the first @ symbol is the ROS service type.\n"
    "Optionally, you can include the Gazebo request and response type\n"
    "separated by the @ symbol.\n"
    "It is only supported to expose Gazebo servces as ROS services, i.e.\n"
    "the ROS service will forward request to the Gazebo service and then forward\n"
    "the response back to the ROS client.\n\n"
    "A bidirectional bridge example:\n"
    "    parameter_bridge /chatter@std_msgs/String@ignition.msgs.StringMsg\n\n"
    "A bridge from Gazebo to ROS example:\n"
    "    parameter_bridge /chatter@std_msgs/String[ignition.msgs.StringMsg\n\n"
    "A bridge from ROS to Gazebo example:\n"
    "    parameter_bridge /chatter@std_msgs/String]ignition.msgs.StringMsg\n"
    "A service bridge:\n"
    "    parameter_bridge /world/default/control@ros_gz_interfaces/srv/ControlWorld\n"
    "Or equivalently:\n"
    "    parameter_bridge /world/default/control@ros_gz_interfaces/srv/ControlWorld@"
    "ignition.msgs.WorldControl@ignition.msgs.Boolean\n"
)

BIDIRECTIONAL, GZ_TO_ROS, ROS_TO_GZ = "@", "[", "]"


class UsageError(ValueError):
    pass


@dataclass
class BridgeConfig:
    ros_topic_name: str
    gz_topic_name: str
    ros_type_name: str
    gz_type_name: str
    direction: str
    is_lazy: bool = False


def parse_spec(arg):
    """One `topic@ros_type(@|[|])gz_type` argument -> BridgeConfig (UsageError if malformed)."""
    topic, at, rest = arg.partition("@")
    if not at or not topic:
        raise UsageError(arg)
    # the first of @ [ ] after the ROS type tells the direction (as parameter_bridge.cpp
    # looks: '@' first, then '[', then ']')
    for delim in (BIDIRECTIONAL, GZ_TO_ROS, ROS_TO_GZ):
        pos = rest.find(delim)
        if pos > 0:
            break
        if pos == 0:
            raise UsageError(arg)
    else:
        raise UsageError(arg)      # services are not bridged by labkit
    ros_type, gz_type = rest[:pos], rest[pos + 1:]
    if "/srv/" in ros_type or not gz_type or "@" in gz_type:
        raise UsageError(arg)
    return BridgeConfig(topic, topic, ros_type, gz_type, delim)


# ---------------------------------------------------------------- conversions
def _time(stamp):
    Time = get_type("builtin_interfaces/msg/Time")
    return Time(sec=int(stamp.get("sec", 0)), nanosec=int(stamp.get("nsec", 0)))


def _header(h):
    Header = get_type("std_msgs/msg/Header")
    frame = ""
    for item in h.get("data", []):
        if item.get("key") == "frame_id" and item.get("value"):
            frame = item["value"][0]
    return Header(stamp=_time(h.get("stamp", {})), frame_id=_frame(frame))


def _header_value(h, key):
    for item in h.get("data", []):
        if item.get("key") == key and item.get("value"):
            return item["value"][0]
    return ""


def _frame(name):
    # ros_gz_bridge's frame_id_gz_to_ros: scoped names use '/' on the ROS side
    return name.replace("::", "/")


def _vec(cls, d):
    return get_type(cls)(x=float(d.get("x", 0.0)), y=float(d.get("y", 0.0)),
                         z=float(d.get("z", 0.0)))


def _quat(d):
    return get_type("geometry_msgs/msg/Quaternion")(
        x=float(d.get("x", 0.0)), y=float(d.get("y", 0.0)), z=float(d.get("z", 0.0)),
        w=float(d.get("w", 1.0)))


def _floats(values):
    out = array.array("f")
    out.frombytes(np.asarray(values, dtype=np.float32).tobytes())
    return out


def laser_scan_to_ros(m):
    msg = get_type("sensor_msgs/msg/LaserScan")()
    msg.header = _header(m["header"])
    msg.header.frame_id = _frame(m.get("frame", ""))
    msg.angle_min = float(m["angle_min"])
    msg.angle_max = float(m["angle_max"])
    msg.angle_increment = float(m["angle_step"])
    msg.time_increment = 0.0
    msg.scan_time = 0.0
    msg.range_min = float(m["range_min"])
    msg.range_max = float(m["range_max"])
    count, vertical = int(m["count"]), int(m.get("vertical_count", 1) or 1)
    start = (vertical // 2) * count        # several vertical beams: the middle one
    msg.ranges = _floats(m["ranges"][start:start + count])
    msg.intensities = _floats(m["intensities"][start:start + count])
    return msg


def odometry_to_ros(m):
    msg = get_type("nav_msgs/msg/Odometry")()
    msg.header = _header(m["header"])
    msg.child_frame_id = _frame(_header_value(m["header"], "child_frame_id"))
    msg.pose.pose.position = _vec("geometry_msgs/msg/Point", m["pose"]["position"])
    msg.pose.pose.orientation = _quat(m["pose"]["orientation"])
    msg.twist.twist = twist_to_ros(m["twist"])
    return msg


def pose_v_to_tf(m):
    msg = get_type("tf2_msgs/msg/TFMessage")()
    transforms = []
    for pose in m.get("pose", []):
        t = get_type("geometry_msgs/msg/TransformStamped")()
        t.header = _header(pose.get("header", {}))
        t.child_frame_id = _frame(_header_value(pose.get("header", {}), "child_frame_id"))
        t.transform.translation = _vec("geometry_msgs/msg/Vector3", pose["position"])
        t.transform.rotation = _quat(pose["orientation"])
        transforms.append(t)
    msg.transforms = transforms
    return msg


def clock_to_ros(m):
    return get_type("rosgraph_msgs/msg/Clock")(clock=_time(m.get("sim", {})))


def twist_to_ros(m):
    return get_type("geometry_msgs/msg/Twist")(
        linear=_vec("geometry_msgs/msg/Vector3", m.get("linear", {})),
        angular=_vec("geometry_msgs/msg/Vector3", m.get("angular", {})))


def twist_to_gz(msg):
    return {"linear": {"x": msg.linear.x, "y": msg.linear.y, "z": msg.linear.z},
            "angular": {"x": msg.angular.x, "y": msg.angular.y, "z": msg.angular.z}}


def string_to_ros(m):
    return get_type("std_msgs/msg/String")(data=str(m.get("data", "")))


def string_to_gz(msg):
    return {"data": msg.data}


# ROS -> Gazebo: what a bridge written with ']' (or '@') sends the other way; the
# same fields ros_gz_bridge's convert_ros_to_gz fills for these types
def _frame_to_gz(name):
    return name.replace("/", "::")


def _header_to_gz(header, **extra):
    data = [{"key": "frame_id", "value": [_frame_to_gz(header.frame_id)]}]
    data += [{"key": key, "value": [_frame_to_gz(value)]} for key, value in extra.items()]
    return {"stamp": {"sec": int(header.stamp.sec), "nsec": int(header.stamp.nanosec)},
            "data": data}


def _xyz(v):
    return {"x": float(v.x), "y": float(v.y), "z": float(v.z)}


def _xyzw(q):
    return {"x": float(q.x), "y": float(q.y), "z": float(q.z), "w": float(q.w)}


def laser_scan_to_gz(msg):
    return {"header": _header_to_gz(msg.header), "frame": _frame_to_gz(msg.header.frame_id),
            "angle_min": float(msg.angle_min), "angle_max": float(msg.angle_max),
            "angle_step": float(msg.angle_increment), "range_min": float(msg.range_min),
            "range_max": float(msg.range_max), "count": len(msg.ranges), "vertical_count": 0,
            "ranges": [float(r) for r in msg.ranges],
            "intensities": [float(i) for i in msg.intensities]}


def odometry_to_gz(msg):
    header = _header_to_gz(msg.header, child_frame_id=msg.child_frame_id)
    return {"header": header,
            "pose": {"position": _xyz(msg.pose.pose.position),
                     "orientation": _xyzw(msg.pose.pose.orientation)},
            "twist": twist_to_gz(msg.twist.twist)}


def tf_to_pose_v(msg):
    return {"pose": [{"header": _header_to_gz(t.header, child_frame_id=t.child_frame_id),
                      "name": _frame_to_gz(t.child_frame_id),
                      "position": _xyz(t.transform.translation),
                      "orientation": _xyzw(t.transform.rotation)} for t in msg.transforms]}


def clock_to_gz(msg):
    return {"sim": {"sec": int(msg.clock.sec), "nsec": int(msg.clock.nanosec)}}


# (ROS type, gz type) -> (gz->ros, ros->gz)
FACTORIES = {
    ("std_msgs/msg/String", "ignition.msgs.StringMsg"): (string_to_ros, string_to_gz),
    ("sensor_msgs/msg/LaserScan", "ignition.msgs.LaserScan"): (laser_scan_to_ros, laser_scan_to_gz),
    ("nav_msgs/msg/Odometry", "ignition.msgs.Odometry"): (odometry_to_ros, odometry_to_gz),
    ("tf2_msgs/msg/TFMessage", "ignition.msgs.Pose_V"): (pose_v_to_tf, tf_to_pose_v),
    ("rosgraph_msgs/msg/Clock", "ignition.msgs.Clock"): (clock_to_ros, clock_to_gz),
    ("geometry_msgs/msg/Twist", "ignition.msgs.Twist"): (twist_to_ros, twist_to_gz),
}


def factory(ros_type, gz_type):
    return FACTORIES.get((ros_type, gz.normalize_type(gz_type)))


# ---------------------------------------------------------------- the node
class RosGzBridge(Node):
    def __init__(self, transport=None):
        super().__init__("ros_gz_bridge")
        from labkit.sims.turtlesim.cpp_node import like_rclcpp
        like_rclcpp(self)
        self.transport = transport or gz.TRANSPORT
        self.declare_parameter("subscription_heartbeat", 1000)
        self.declare_parameter("config_file", "")
        self.declare_parameter("expand_gz_topic_names", False)
        self.declare_parameter("lazy", False)
        self.lazy = bool(self.get_parameter("lazy").value)
        self._gz_subs, self._gz_pubs = [], []

    def add_bridge(self, config):
        config.is_lazy = self.lazy
        convert = factory(config.ros_type_name, config.gz_type_name)
        log = self.get_logger()
        if convert is None or (config.direction != GZ_TO_ROS and convert[1] is None):
            log.warn(
                f"Failed to create a bridge for topic [{config.ros_topic_name}] with ROS2 type "
                f"[{config.ros_type_name}] to topic [{config.gz_topic_name}] with Gazebo "
                f"Transport type [{config.gz_type_name}]")
            return
        ros_cls = get_type(config.ros_type_name)
        gz_type = gz.normalize_type(config.gz_type_name)
        # A two-way bridge must not carry its own messages back (ros_gz_bridge ignores
        # its own publications on both sides): count what it sends each way.
        echoes = {"to_ros": 0, "to_gz": 0, "two_way": config.direction == BIDIRECTIONAL}
        if config.direction in (BIDIRECTIONAL, GZ_TO_ROS):
            log.info(f"Creating GZ->ROS Bridge: [{config.gz_topic_name} ({config.gz_type_name}) "
                     f"-> {config.ros_topic_name} ({config.ros_type_name})] (Lazy {int(config.is_lazy)})")
            publisher = self.create_publisher(ros_cls, config.ros_topic_name, 10)
            self._gz_subs.append(self.transport.subscribe(
                config.gz_topic_name, gz_type, self._forward(publisher, convert[0], echoes)))
        if config.direction in (BIDIRECTIONAL, ROS_TO_GZ):
            log.info(f"Creating ROS->GZ Bridge: [{config.ros_topic_name} ({config.ros_type_name}) "
                     f"-> {config.gz_topic_name} ({config.gz_type_name})] (Lazy {int(config.is_lazy)})")
            gz_publish = self.transport.advertise(config.gz_topic_name, gz_type)
            self._gz_pubs.append(gz_publish)
            to_gz = convert[1]

            def ros_to_gz(msg):
                if echoes["to_ros"] > 0:          # our own GZ->ROS message coming back
                    echoes["to_ros"] -= 1
                    return
                echoes["to_gz"] += 1
                gz_publish(to_gz(msg))
                echoes["to_gz"] = max(0, echoes["to_gz"] - 1)
            self.create_subscription(ros_cls, config.ros_topic_name, ros_to_gz, 10)

    @staticmethod
    def _forward(publisher, to_ros, echoes):
        def callback(gz_msg):
            if echoes["to_gz"] > 0:               # our own ROS->GZ message, delivered at once
                return
            try:
                publisher.publish(to_ros(gz_msg))
            except Exception:      # the bridge is shutting down: drop, as a dead socket would
                return
            if echoes["two_way"]:
                echoes["to_ros"] += 1             # our own subscription will see it: skip it there
        return callback

    def destroy_node(self):
        for handle in self._gz_subs:
            self.transport.unsubscribe(handle)
        for publish in self._gz_pubs:
            self.transport.unadvertise(publish)
        self._gz_subs, self._gz_pubs = [], []
        return super().destroy_node()


def main(args=None):
    argv = list(args if args is not None else sys.argv)
    if len(argv) < 2:
        print(USAGE, flush=True)
        return 255
    rclpy.init(args=argv)
    node = None
    try:
        specs = remove_ros_args(argv)[1:]
        node = RosGzBridge()
        for spec in specs:       # like parameter_bridge.cpp: each bridge starts as it is read
            try:
                config = parse_spec(spec)
            except UsageError:
                print(USAGE, flush=True)
                return 255
            node.add_bridge(config)
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    except Exception as exc:
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
