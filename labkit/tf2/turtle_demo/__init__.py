"""turtle_tf2_demo: labkit's own turtlesim + tf2 demo package (the book's chapter 22).

The same lesson as the official `turtle_tf2_py` tutorial package, written anew:
  pose_to_tf      one turtle's /<turtle>/pose as the transform world -> <turtle>
  chaser          spawns a second turtle and steers it toward a target frame
  carrot          a frame hung under a turtle, fixed (offset) or circling (radius > 0)
"""
import labkit.rclpy as rclpy


def run(node):
    """Spin `node` until Ctrl-C or until its process is stopped; always clean up."""
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    except Exception as exc:          # a stopped process ends its spin this way
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
