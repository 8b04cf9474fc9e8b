"""joint_state_publisher (Humble, the Python node): reads the URDF from the latched
`robot_description` topic (or a file argument) and publishes
sensor_msgs/JointState for every non-fixed joint at `rate` Hz (10): zero, or
the middle of the limits when zero is outside them. Sources in `source_list`
and `zeros.<joint>` parameters override positions.
"""
import math
import sys
import xml.dom.minidom

import labkit.rclpy as rclpy
from labkit.interfaces import module
from labkit.rclpy.executors import ExternalShutdownException
from labkit.rclpy.exceptions import ParameterAlreadyDeclaredException
from labkit.rclpy.node import Node
from labkit.rclpy.qos import DurabilityPolicy, QoSProfile


def _float(name, jtype, which, text):
    try:
        return float(text)
    except ValueError:
        raise ValueError(f'"{which}" limit must be a float for joint "{name}" '
                         f'of type "{jtype}"') from None


def free_joints_of(description, zeros=None):
    """(free_joints, joint_list, dependent_joints) of a URDF, like the real node."""
    zeros = zeros or {}
    dom = xml.dom.minidom.parseString(description)
    robots = dom.getElementsByTagName("robot")
    if not robots:
        raise ValueError('URDF must have a "robot" tag')
    free, order, dependent = {}, [], {}
    for child in robots[0].childNodes:
        if child.nodeType != child.ELEMENT_NODE or child.localName != "joint":
            continue
        jtype = child.getAttribute("type")
        if jtype in ("fixed", "floating", "planar"):
            continue
        name = child.getAttribute("name")
        if jtype == "continuous":
            low, high = -math.pi, math.pi
        else:
            limits = child.getElementsByTagName("limit")
            if not limits:
                raise ValueError(f'Limits must be specified for joint "{name}" of type "{jtype}"')
            limit = limits[0]
            for which in ("lower", "upper"):
                if not limit.hasAttribute(which):
                    raise ValueError(f'"{which}" limit must be specified for joint "{name}" '
                                     f'of type "{jtype}"')
            low = _float(name, jtype, "lower", limit.getAttribute("lower"))
            high = _float(name, jtype, "upper", limit.getAttribute("upper"))
        order.append(name)
        mimics = child.getElementsByTagName("mimic")
        if len(mimics) == 1:
            tag = mimics[0]
            entry = {"parent": tag.getAttribute("joint")}
            if tag.hasAttribute("multiplier"):
                entry["factor"] = float(tag.getAttribute("multiplier"))
            if tag.hasAttribute("offset"):
                entry["offset"] = float(tag.getAttribute("offset"))
            dependent[name] = entry
            continue
        if name in zeros:
            zero = zeros[name]
        elif low > 0 or high < 0:
            zero = (high + low) / 2
        else:
            zero = 0
        joint = {"min": low, "max": high, "zero": zero, "position": zero}
        if jtype == "continuous":
            joint["continuous"] = True
        free[name] = joint
    return free, order, dependent


class JointStatePublisher(Node):

    def __init__(self, description_file=None, node_name="joint_state_publisher"):
        super().__init__(node_name, automatically_declare_parameters_from_overrides=True)
        Descriptor = module("rcl_interfaces.msg").ParameterDescriptor
        # (name, default, ParameterType): typed like the real node, so `ros2 param` agrees
        for name, default, ptype in (("publish_default_efforts", False, 1),
                                     ("publish_default_positions", True, 1),
                                     ("publish_default_velocities", False, 1),
                                     ("rate", 10, 2), ("source_list", [], 9),
                                     ("use_mimic_tags", True, 1),
                                     ("use_smallest_joint_limits", True, 1),
                                     ("delta", 0.0, 3)):
            try:
                self.declare_parameter(name, default, Descriptor(type=ptype))
            except ParameterAlreadyDeclaredException:
                pass
        self.free_joints, self.joint_list, self.dependent_joints = {}, [], {}
        self.robot_description_update_cb = None
        self.source_update_cb = None
        if description_file is not None:
            with open(description_file, encoding="utf-8") as handle:
                self.configure_robot(handle.read())
        else:
            self.get_logger().info(
                "Waiting for robot_description to be published on the robot_description topic...")
        String = module("std_msgs.msg").String
        JointState = module("sensor_msgs.msg").JointState
        self.create_subscription(String, "robot_description", self._on_description,
                                 QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        self.sources = [self.create_subscription(JointState, source, self.source_cb, 10)
                        for source in self.get_parameter("source_list").value if source]
        self.pub = self.create_publisher(JointState, "joint_states", 10)
        self.timer = self.create_timer(1.0 / self.get_parameter("rate").value,
                                       self.timer_callback)

    def _zeros(self):
        return {name: p.value for name, p in self.get_parameters_by_prefix("zeros").items()}

    def configure_robot(self, description):
        self.free_joints, self.joint_list, self.dependent_joints = free_joints_of(
            description, self._zeros())
        if self.robot_description_update_cb is not None:
            self.robot_description_update_cb()

    def _on_description(self, msg):
        try:
            self.configure_robot(msg.data)
        except Exception as exc:   # the real node warns and keeps going
            self.get_logger().warn(str(exc))

    def source_cb(self, msg):
        for i, name in enumerate(msg.name):
            joint = self.free_joints.get(name)
            if joint is None:
                continue
            if msg.position:
                joint["position"] = msg.position[i]
        if self.source_update_cb is not None:
            self.source_update_cb()

    def set_source_update_cb(self, user_cb):
        self.source_update_cb = user_cb

    def set_robot_description_update_cb(self, user_cb):
        self.robot_description_update_cb = user_cb

    def set_position(self, name, position):
        """What a GUI slider does."""
        self.free_joints[name]["position"] = float(position)

    def positions(self):
        """[(name, position)] in URDF order, mimic joints resolved."""
        out = []
        for name in self.joint_list:
            if name in self.free_joints:
                out.append((name, float(self.free_joints[name]["position"])))
                continue
            parent = self.dependent_joints[name]["parent"]
            entry = self.dependent_joints[name]
            factor, offset = entry.get("factor", 1.0), entry.get("offset", 0.0)
            seen = [name]
            while parent in self.dependent_joints:
                if parent in seen:
                    raise ValueError(f"Found an infinite recursive mimic chain: {seen + [parent]}")
                seen.append(parent)
                entry = self.dependent_joints[parent]
                parent = entry["parent"]
                offset += factor * entry.get("offset", 0.0)
                factor *= entry.get("factor", 1.0)
            out.append((name, float(self.free_joints[parent]["position"]) * factor + offset))
        return out

    def timer_callback(self):
        delta = self.get_parameter("delta").value
        if delta > 0:
            self._sweep(delta)
        JointState = module("sensor_msgs.msg").JointState
        msg = JointState()
        msg.header.stamp = self.get_clock().now().to_msg()
        pairs = self.positions()
        msg.name = [n for n, _ in pairs]
        msg.position = [p for _, p in pairs]
        if msg.name:
            self.pub.publish(msg)

    def _sweep(self, delta):
        for joint in self.free_joints.values():
            forward = joint.get("forward", True)
            joint["position"] += delta if forward else -delta
            if joint["position"] > joint["max"]:
                if joint.get("continuous"):
                    joint["position"] = joint["min"]
                else:
                    joint["position"], joint["forward"] = joint["max"], not forward
            elif joint["position"] < joint["min"]:
                joint["position"], joint["forward"] = joint["min"], not forward


def _description_file(args):
    from labkit.rclpy.utilities import remove_ros_args
    rest = remove_ros_args(args=args if args is not None else sys.argv)[1:]
    return rest[0] if rest else None


def run(node):
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


def main(args=None):
    rclpy.init(args=args)
    run(JointStatePublisher(_description_file(args)))


def gui_main(args=None):
    """joint_state_publisher_gui: the same node with a slider per joint (an ipywidgets panel)."""
    rclpy.init(args=args)
    node = JointStatePublisher(_description_file(args))
    from labkit.robots import sliders
    sliders.attach(node)
    run(node)
