"""tf2_ros.StaticTransformBroadcaster: latched (transient local, depth 1) /tf_static.

As in Humble's Python version each call publishes only what it is given: a late
subscriber gets the last message, so send every static frame in one call."""
from labkit.interfaces import get_type
from labkit.rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile

__all__ = ["StaticTransformBroadcaster"]


class StaticTransformBroadcaster:
    def __init__(self, node, qos=None):
        if qos is None:
            qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                             history=HistoryPolicy.KEEP_LAST)
        self._TFMessage = get_type("tf2_msgs/msg/TFMessage")
        self.pub_tf = node.create_publisher(self._TFMessage, "/tf_static", qos)

    def sendTransform(self, transform):
        if not isinstance(transform, list):
            transform = list(transform) if hasattr(transform, "__iter__") else [transform]
        self.pub_tf.publish(self._TFMessage(transforms=transform))
