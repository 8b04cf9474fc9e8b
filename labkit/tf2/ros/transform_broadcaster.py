"""tf2_ros.TransformBroadcaster: TFMessage on /tf."""
from labkit.interfaces import get_type
from labkit.rclpy.qos import QoSProfile

__all__ = ["TransformBroadcaster"]


class TransformBroadcaster:
    def __init__(self, node, qos=None):
        if qos is None:
            qos = QoSProfile(depth=100)
        self._TFMessage = get_type("tf2_msgs/msg/TFMessage")
        self.pub_tf = node.create_publisher(self._TFMessage, "/tf", qos)

    def sendTransform(self, transform):
        if not isinstance(transform, list):
            transform = list(transform) if hasattr(transform, "__iter__") else [transform]
        self.pub_tf.publish(self._TFMessage(transforms=transform))
