"""What rclcpp gives every node and rclpy does not (turtlesim's executables are C++).

`ros2 param list` shows rclcpp's read-only qos_overrides./parameter_events.publisher.*
parameters, and `ros2 node info` shows the /parameter_events subscription rclcpp's
TimeSource makes to watch use_sim_time.
"""
from labkit.interfaces import get_type
from labkit.rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

ParameterDescriptor = get_type("rcl_interfaces/msg/ParameterDescriptor")
ParameterEvent = get_type("rcl_interfaces/msg/ParameterEvent")

_PARAMETER_EVENTS_QOS = (("depth", 1000), ("durability", "volatile"),
                         ("history", "keep_last"), ("reliability", "reliable"))


def declare_qos_override_parameters(node):
    """The read-only qos_overrides./parameter_events.publisher.* parameters rclcpp declares."""
    prefix = "qos_overrides./parameter_events.publisher."
    for policy, value in _PARAMETER_EVENTS_QOS:
        if not node.has_parameter(prefix + policy):
            node.declare_parameter(prefix + policy, value, ParameterDescriptor(
                description="qos policy {%s} for publisher {/parameter_events}" % policy,
                read_only=True))


def like_rclcpp(node):
    """Give an rclpy node the parameters and the subscription an rclcpp node has."""
    # parameter refusals and listings in rclcpp's words (`ros2 param set/load` print them)
    node._labkit_parameter_dialect = "rclcpp"
    declare_qos_override_parameters(node)
    qos = QoSProfile(depth=1000, history=HistoryPolicy.KEEP_LAST,
                     reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.VOLATILE)
    node._rclcpp_time_source_events = node.create_subscription(
        ParameterEvent, "/parameter_events", lambda event: None, qos)
