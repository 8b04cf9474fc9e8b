"""tf2_ros.TransformListener: /tf and /tf_static (transient local) into a Buffer."""
import threading

from labkit.interfaces import get_type
from labkit.rclpy.callback_groups import ReentrantCallbackGroup
from labkit.rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile

__all__ = ["TransformListener"]


class TransformListener:
    def __init__(self, buffer, node, *, spin_thread=False, qos=None, static_qos=None):
        if qos is None:
            qos = QoSProfile(depth=100, durability=DurabilityPolicy.VOLATILE,
                             history=HistoryPolicy.KEEP_LAST)
        if static_qos is None:
            static_qos = QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                                    history=HistoryPolicy.KEEP_LAST)
        TFMessage = get_type("tf2_msgs/msg/TFMessage")
        self.buffer = buffer
        self.node = node
        # a reentrant group lets a callback of this node wait for transforms
        self.group = ReentrantCallbackGroup()
        self.tf_sub = node.create_subscription(
            TFMessage, "/tf", self.callback, qos, callback_group=self.group)
        self.tf_static_sub = node.create_subscription(
            TFMessage, "/tf_static", self.static_callback, static_qos, callback_group=self.group)
        if spin_thread:
            from labkit.rclpy.executors import SingleThreadedExecutor
            self.executor = SingleThreadedExecutor()

            def run_func():
                self.executor.add_node(self.node)
                try:
                    self.executor.spin()
                except Exception as exc:
                    # the context was shut down under the spin: the thread just ends
                    if type(exc).__name__ != "ExternalShutdownException":
                        raise
                self.executor.remove_node(self.node)

            # labkit's virtual time adopts a thread from its first line only when its target
            # comes from rclpy (process._spins_rclpy); this one spins rclpy, so say so
            run_func.__module__ = SingleThreadedExecutor.spin.__module__
            self.dedicated_listener_thread = threading.Thread(target=run_func, daemon=True)
            self.dedicated_listener_thread.start()

    def __del__(self):
        try:
            if hasattr(self, "dedicated_listener_thread") and hasattr(self, "executor"):
                self.executor.shutdown()
            self.unregister()
        except Exception:
            pass

    def unregister(self):
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)

    def callback(self, data):
        who = "default_authority"
        for transform in data.transforms:
            self.buffer.set_transform(transform, who)

    def static_callback(self, data):
        who = "default_authority"
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, who)
