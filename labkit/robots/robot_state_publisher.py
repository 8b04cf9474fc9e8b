"""robot_state_publisher (Humble): URDF + /joint_states -> /tf, /tf_static.

Parameters `robot_description`, `publish_frequency` (20.0), `frame_prefix`,
`ignore_timestamp`; fixed joints go once to latched /tf_static, movable joints
to /tf whenever a JointState arrives (throttled by publish_frequency per joint,
on the message stamps, like the C++ node); the description is republished on
latched `/robot_description` (std_msgs/String).
TF goes out as plain tf2_msgs/TFMessage so this room does not depend on tf2.
"""
import functools
import sys

import labkit.rclpy as rclpy
from labkit.interfaces import module
from labkit.rclpy.executors import ExternalShutdownException
from labkit.rclpy.node import Node
from labkit.rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from labkit.robots.urdf import URDFError, load

_NS_PER_S = 1_000_000_000


@functools.lru_cache(maxsize=1)
def _msgs():
    return (module("tf2_msgs.msg").TFMessage, module("geometry_msgs.msg").TransformStamped,
            module("std_msgs.msg").String, module("sensor_msgs.msg").JointState)


def static_qos():
    return QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


def transform_stamped(parent, child, stamp, xyz, quat):
    _, TransformStamped, _, _ = _msgs()
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = parent
    t.child_frame_id = child
    tr, rot = t.transform.translation, t.transform.rotation
    tr.x, tr.y, tr.z = xyz
    rot.x, rot.y, rot.z, rot.w = quat
    return t


# rclcpp declares read-only qos_overrides.* parameters for /parameter_events and for
# every entity created with qos_overriding_options (tf2_ros broadcasters, joint_states)
_QOS_OVERRIDES = (
    ("/parameter_events", "publisher", (("depth", 1000), ("durability", "volatile"),
                                        ("history", "keep_last"), ("reliability", "reliable"))),
    ("/joint_states", "subscription", (("depth", 5), ("history", "keep_last"),
                                       ("reliability", "best_effort"))),
    ("/tf", "publisher", (("depth", 100), ("durability", "volatile"),
                          ("history", "keep_last"), ("reliability", "reliable"))),
    ("/tf_static", "publisher", (("depth", 1), ("durability", "transient_local"),
                                 ("history", "keep_last"), ("reliability", "reliable"))),
)


def _declare_qos_overrides(node):
    Descriptor = module("rcl_interfaces.msg").ParameterDescriptor
    for topic, kind, policies in _QOS_OVERRIDES:
        for policy, value in policies:
            name = f"qos_overrides.{topic}.{kind}.{policy}"
            if not node.has_parameter(name):
                node.declare_parameter(name, value, Descriptor(
                    description=f"qos policy {{{policy}}} for {kind} {{{topic}}}",
                    read_only=True))


def _stamp_ns(stamp):
    return stamp.sec * _NS_PER_S + stamp.nanosec


class RobotStatePublisher(Node):
    """The node; `model` is the parsed URDF (labkit.robots.urdf.RobotModel)."""

    def __init__(self, description_file=None, **kwargs):
        super().__init__("robot_state_publisher", **kwargs)
        self._labkit_parameter_dialect = "rclcpp"   # a C++ node: rclcpp's parameter texts
        TFMessage, _, String, JointState = _msgs()
        urdf_xml = self.declare_parameter("robot_description", "").value
        if not urdf_xml:
            if description_file is None:
                self.get_logger().fatal("robot_description parameter must not be empty")
                raise RuntimeError("robot_description parameter must not be empty")
            self.get_logger().warn(
                "No robot_description parameter, but command-line argument available."
                "  Assuming argument is name of URDF file."
                "  This backwards compatibility fallback will be removed in the future.")
            try:
                with open(description_file, encoding="utf-8") as handle:
                    urdf_xml = handle.read()
            except OSError:
                raise RuntimeError(f"Failed to open URDF file: {description_file}") from None
            from labkit.rclpy.parameter import Parameter
            self.set_parameters([Parameter("robot_description", value=urdf_xml)])
        frequency = self.declare_parameter("publish_frequency", 20.0).value
        if frequency < 0.0 or frequency > 1000.0:
            raise RuntimeError("publish_frequency must be between 0 and 1000")
        self.declare_parameter("frame_prefix", "")
        self.declare_parameter("ignore_timestamp", False)
        _declare_qos_overrides(self)

        self._tf_pub = self.create_publisher(TFMessage, "/tf", QoSProfile(depth=100))
        self._tf_static_pub = self.create_publisher(TFMessage, "/tf_static", static_qos())
        self._description_pub = self.create_publisher(String, "robot_description", static_qos())
        self._last_publish_ns = {}
        self._last_callback_ns = 0
        self._setup_urdf(urdf_xml)
        self.create_subscription(JointState, "joint_states", self._on_joint_state,
                                 qos_profile_sensor_data)
        self.publish_fixed_transforms()
        self.add_on_set_parameters_callback(self._on_set_parameters)
        self.create_subscription(module("rcl_interfaces.msg").ParameterEvent,
                                 "/parameter_events", self._on_parameter_event,
                                 QoSProfile(depth=1000))

    # -- description ---------------------------------------------------------
    def _parse(self, urdf_xml):
        try:
            return load(urdf_xml)
        except URDFError as exc:
            sys.stderr.write(f"Error:   {exc}\n")
            raise RuntimeError("Unable to initialize urdf::model from robot description") \
                from None

    def _setup_urdf(self, urdf_xml):
        self.model = self._parse(urdf_xml)
        for link in sorted(self.model.links):   # KDL's segment map is ordered by name
            self.get_logger().info(f"got segment {link}")
        self._moving = {j.name: j for j in self.model.movable_joints()}
        self._fixed = {j.name: j for j in sorted(self.model.fixed_joints(),
                                                 key=lambda j: j.name)}
        self._mimic = {j.name: j.mimic for j in self.model.joints.values() if j.mimic}
        msg = _msgs()[2]()
        msg.data = urdf_xml
        self._description_pub.publish(msg)

    def _on_set_parameters(self, parameters):
        result = module("rcl_interfaces.msg").SetParametersResult(successful=True)
        for p in parameters:
            if p.name == "robot_description":
                if not p.value:
                    result.successful, result.reason = False, "Empty URDF is not allowed"
                    break
                try:
                    self._parse(p.value)
                except RuntimeError as exc:
                    self.get_logger().warn(str(exc))
                    result.successful, result.reason = False, str(exc)
                    break
            elif p.name == "publish_frequency":
                if p.value < 0.0 or p.value > 1000.0:
                    result.successful = False
                    result.reason = "publish_frequency must be between 0.0 and 1000.0"
                    break
        return result

    def _on_parameter_event(self, event):
        """A changed robot_description (seen on /parameter_events, as Humble does) reloads."""
        if event.node != self.get_fully_qualified_name():
            return
        for p in event.changed_parameters:
            if p.name == "robot_description":
                try:
                    self._setup_urdf(p.value.string_value)
                    self.publish_fixed_transforms()
                except RuntimeError as exc:
                    self.get_logger().warn(f"Failed to parse new URDF: {exc}")

    # -- transforms ------------------------------------------------------------
    def _prefix(self):
        return self.get_parameter("frame_prefix").value

    def publish_fixed_transforms(self):
        TFMessage = _msgs()[0]
        prefix = self._prefix()
        stamp = self.get_clock().now().to_msg()
        msg = TFMessage()
        msg.transforms = [transform_stamped(prefix + j.parent, prefix + j.child, stamp,
                                            *j.transform()) for j in self._fixed.values()]
        self._tf_static_pub.publish(msg)

    def publish_transforms(self, positions, stamp):
        TFMessage = _msgs()[0]
        prefix = self._prefix()
        msg = TFMessage()
        msg.transforms = [transform_stamped(prefix + self._moving[name].parent,
                                            prefix + self._moving[name].child, stamp,
                                            *self._moving[name].transform(q))
                          for name, q in sorted(positions.items()) if name in self._moving]
        self._tf_pub.publish(msg)

    def _on_joint_state(self, state):
        if len(state.name) != len(state.position):
            if not state.position:
                self.get_logger().warn(
                    "Robot state publisher ignored a JointState message about joint(s) "
                    f"\"{state.name[0]}\"(,...) whose position member was empty.")
            else:
                self.get_logger().error(
                    "Robot state publisher ignored an invalid JointState message")
            return
        now = self.get_clock().now().nanoseconds
        if self._last_callback_ns > now:
            self.get_logger().warn("Moved backwards in time, re-publishing joint transforms!")
            self._last_publish_ns.clear()
        self._last_callback_ns = now
        last_published = now
        for name in state.name:
            last_published = min(last_published, self._last_publish_ns.get(name, 0))
        frequency = self.get_parameter("publish_frequency").value
        interval_ns = int(1000.0 / frequency) * 1_000_000 if frequency > 0 else 0
        stamp_ns = _stamp_ns(state.header.stamp)
        if not (self.get_parameter("ignore_timestamp").value
                or stamp_ns >= last_published + interval_ns):
            return
        positions = dict(zip(state.name, state.position))
        for name, mimic in self._mimic.items():
            if mimic.joint in positions and name not in positions:
                positions[name] = (positions[mimic.joint] * (mimic.multiplier or 1.0)
                                   + (mimic.offset or 0.0))
        self.publish_transforms(positions, state.header.stamp)
        for name in state.name:
            self._last_publish_ns[name] = stamp_ns


def _terminate(what):
    # what an uncaught std::runtime_error prints before the C++ process aborts
    sys.stderr.write("terminate called after throwing an instance of 'std::runtime_error'\n"
                     f"  what():  {what}\n")


def main(args=None):
    return _run(args, None)


def main_with_description(description, args=None):
    """main() with `robot_description` given, as a launch file's parameters=[...] does."""
    return _run(args, description)


def _run(args, description):
    rclpy.init(args=args)
    from labkit.rclpy.utilities import remove_ros_args
    rest = remove_ros_args(args=args if args is not None else sys.argv)[1:]
    kwargs = {}
    if description is not None:
        from labkit.rclpy.parameter import Parameter
        kwargs["parameter_overrides"] = [Parameter("robot_description", value=description)]
    try:
        node = RobotStatePublisher(rest[0] if rest else None, **kwargs)
    except RuntimeError as exc:
        _terminate(exc)
        rclpy.try_shutdown()
        return -6
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
