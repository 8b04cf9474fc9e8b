"""The turtle_tf2_py tutorial nodes (ros/geometry_tutorials), on labkit's rclpy."""
import labkit.rclpy as rclpy


def spin_until_stopped(node):
    """rclpy.spin(node) until Ctrl-C or the process is stopped, then clean up."""
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    except Exception as exc:
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
