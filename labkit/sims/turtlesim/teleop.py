"""`ros2 run turtlesim turtle_teleop_key`: node /teleop_turtle drives turtle1 from keys.

Arrow keys publish turtle1/cmd_vel (scaled by scale_linear / scale_angular);
G B V C D E R T send rotate_absolute goals; F cancels the last goal; Q quits.

Where the keys come from: in a notebook kernel, a focusable widget with
buttons (labkit/viz/teleop_widget.py); in a terminal, the tty in raw mode;
anywhere, `press('up')` (tests and book cells).
"""
import threading

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.action import ActionClient
from labkit.rclpy.node import Node
from labkit.rclpy.task import Future

from .cpp_node import like_rclcpp
from .keys import BANNER, DRIVE, KEYS, ROTATE, TTY_CHARS, key_name

Twist = get_type("geometry_msgs/msg/Twist")
RotateAbsolute = get_type("turtlesim/action/RotateAbsolute")

_running = []        # TeleopTurtle nodes alive (newest last)


class TeleopTurtle(Node):
    def __init__(self):
        super().__init__("teleop_turtle")
        like_rclcpp(self)
        self.declare_parameter("scale_angular", 2.0)
        self.declare_parameter("scale_linear", 2.0)
        self.twist_pub = self.create_publisher(Twist, "turtle1/cmd_vel", 1)
        self.rotate_absolute_client = ActionClient(self, RotateAbsolute, "turtle1/rotate_absolute")
        self.goal_handle = None
        self.quit_future = Future()
        self._lock = threading.Lock()

    def press(self, key):
        """React to one key, by name (see KEYS). Unknown keys are ignored, like the original."""
        k = key_name(key)
        if k is None:
            return
        with self._lock:
            if k in DRIVE:
                linear, angular = DRIVE[k]
                twist = Twist()
                twist.angular.z = float(self.get_parameter("scale_angular").value) * angular
                twist.linear.x = float(self.get_parameter("scale_linear").value) * linear
                self.twist_pub.publish(twist)
            elif k in ROTATE:
                self.send_goal(ROTATE[k])
            elif k == "f":
                self.cancel_goal()
            elif k == "q" and not self.quit_future.done():
                self.quit_future.set_result(True)

    def press_char(self, char):
        """A byte from a raw terminal, mapped exactly as teleop_turtle_key.cpp maps it."""
        if char in TTY_CHARS:
            self.press(TTY_CHARS[char])
        elif char in ROTATE or char in ("f", "q"):
            self.press(char)

    def send_goal(self, theta):
        goal = RotateAbsolute.Goal()
        goal.theta = theta
        future = self.rotate_absolute_client.send_goal_async(goal)
        future.add_done_callback(self._goal_response)

    def _goal_response(self, future):
        self.goal_handle = future.result()

    def cancel_goal(self):
        if self.goal_handle is not None:
            try:
                self.goal_handle.cancel_goal_async()
            except Exception:       # the goal may have finished and expired already
                pass

    def destroy_node(self):
        if self in _running:
            _running.remove(self)
        return super().destroy_node()


def running():
    """The teleop nodes alive now (newest last)."""
    return list(_running)


def press(*keys, node=None):
    """Press keys on the running turtle_teleop_key (the newest one unless `node` is given).

    `press('up')`, `press('up', 'up', 'left')`, `press('r')`; names as in KEYS,
    'ArrowUp' style names and capitals work too.
    """
    target = node or (_running[-1] if _running else None)
    if target is None:
        raise RuntimeError("turtle_teleop_key is not running (start it with "
                           "`ros2 run turtlesim turtle_teleop_key`)")
    for key in keys:
        if key_name(key) is None:
            raise ValueError("unknown key %r; keys are %s" % (key, ", ".join(KEYS)))
        target.press(key)


def _in_notebook():
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and getattr(shell, "kernel", None) is not None


def _open_keyboard(node):
    if _in_notebook():
        # the widget lives with the other viewers (labkit/viz); loaded only when a kernel can show it
        from labkit.viz.teleop_widget import TeleopWidget
        widget = TeleopWidget(node.press)
        widget.show()
        return widget
    from labkit.sims._tty import open_terminal_keys
    return open_terminal_keys(node.press_char, node.quit_future.done)


def main(args=None):
    rclpy.init(args=args)
    node = TeleopTurtle()
    print(BANNER, flush=True)
    _running.append(node)
    keyboard = None
    try:
        keyboard = _open_keyboard(node)
        rclpy.spin_until_future_complete(node, node.quit_future)
    except KeyboardInterrupt:
        pass
    except Exception as exc:
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        if keyboard is not None:
            keyboard.close()
        node.destroy_node()
        rclpy.try_shutdown()
