"""`ros2 run teleop_twist_keyboard teleop_twist_keyboard`: keys -> geometry_msgs/Twist on cmd_vel.

The key map, speed keys and texts are those of teleop_twist_keyboard (a
Python node). Keys come from `press('i')` (book cells, tests) or, in a
terminal, from the tty in raw mode. CTRL-C ('\\x03') quits after a zero Twist.
"""
import threading

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.task import Future

Twist = get_type("geometry_msgs/msg/Twist")

BANNER = """
This node takes keypresses from the keyboard and publishes them
as Twist messages. It works best with a US keyboard layout.
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

For Holonomic mode (strafing), hold down the shift key:
---------------------------
   U    I    O
   J    K    L
   M    <    >

t : up (+z)
b : down (-z)

anything else : stop

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%

CTRL-C to quit
"""

# key -> (x, y, z, th) direction factors
MOVE_BINDINGS = {
    "i": (1, 0, 0, 0), "o": (1, 0, 0, -1), "j": (0, 0, 0, 1), "l": (0, 0, 0, -1),
    "u": (1, 0, 0, 1), ",": (-1, 0, 0, 0), ".": (-1, 0, 0, 1), "m": (-1, 0, 0, -1),
    "O": (1, -1, 0, 0), "I": (1, 0, 0, 0), "J": (0, 1, 0, 0), "L": (0, -1, 0, 0),
    "U": (1, 1, 0, 0), "<": (-1, 0, 0, 0), ">": (-1, -1, 0, 0), "M": (-1, 1, 0, 0),
    "t": (0, 0, 1, 0), "b": (0, 0, -1, 0),
}
# key -> (speed factor, turn factor)
SPEED_BINDINGS = {"q": (1.1, 1.1), "z": (.9, .9), "w": (1.1, 1), "x": (.9, 1),
                  "e": (1, 1.1), "c": (1, .9)}
CTRL_C = "\x03"

_running = []


def vels(speed, turn):
    return "currently:\tspeed %s\tturn %s " % (speed, turn)


class TeleopTwistKeyboard:
    """The node and the state of teleop_twist_keyboard's key loop."""

    def __init__(self):
        self.node = rclpy.create_node("teleop_twist_keyboard")
        self.pub = self.node.create_publisher(Twist, "cmd_vel", 10)
        self.speed, self.turn = 0.5, 1.0
        self.x = self.y = self.z = self.th = 0.0
        self.status = 0
        self.quit_future = Future()
        self._lock = threading.Lock()

    def press(self, key):
        """One key, exactly as the original's loop handles a character."""
        with self._lock:
            if self.quit_future.done():
                return
            if key in MOVE_BINDINGS:
                self.x, self.y, self.z, self.th = (float(v) for v in MOVE_BINDINGS[key])
            elif key in SPEED_BINDINGS:
                self.speed *= SPEED_BINDINGS[key][0]
                self.turn *= SPEED_BINDINGS[key][1]
                print(vels(self.speed, self.turn), flush=True)
                if self.status == 14:
                    print(BANNER, flush=True)
                self.status = (self.status + 1) % 15
            else:
                self.x = self.y = self.z = self.th = 0.0
                if key == CTRL_C:
                    self.quit_future.set_result(True)
                    return
            self.pub.publish(self.twist())

    def twist(self):
        twist = Twist()
        twist.linear.x = self.x * self.speed
        twist.linear.y = self.y * self.speed
        twist.linear.z = self.z * self.speed
        twist.angular.z = self.th * self.turn
        return twist


def running():
    return list(_running)


def press(*keys, teleop=None):
    """Type keys into the running teleop_twist_keyboard: `press('i')`, `press('k')`,
    `press('q', 'q')`; one string of several characters is typed character by character."""
    target = teleop or (_running[-1] if _running else None)
    if target is None:
        raise RuntimeError("teleop_twist_keyboard is not running (start it with "
                           "`ros2 run teleop_twist_keyboard teleop_twist_keyboard`)")
    for key in keys:
        for char in str(key):
            target.press(char)


# the key pad a notebook shows (live time): moving keys, speed keys, up/down
KEYPAD = [["uio", "jkl", "m,."], ["qwe", "zxc"], ["t", "b"]]


def _open_terminal(teleop):
    try:
        from IPython import get_ipython
        shell = get_ipython()
        if shell is not None:
            return _open_keypad(teleop)
    except ImportError:
        pass
    from labkit.sims._tty import open_terminal_keys
    return open_terminal_keys(teleop.press, teleop.quit_future.done, pass_ctrl_c=True,
                              name="teleop-twist-tty")


def _open_keypad(teleop):
    """Live JupyterLab: a key pad in the cell, for the keys a terminal would take.
    (Unattended runs type with `press(...)`: their stored output stays plain text.)"""
    from labkit.viz.display import live_kernel
    if not live_kernel():
        return None
    from labkit.viz.teleop_widget import KeyPad
    pad = KeyPad(teleop.press, "teleop_twist_keyboard", KEYPAD)
    pad.show()
    return pad


def main(args=None):
    rclpy.init(args=args)
    teleop = TeleopTwistKeyboard()
    _running.append(teleop)
    keyboard = None
    try:
        print(BANNER, flush=True)
        print(vels(teleop.speed, teleop.turn), flush=True)
        keyboard = _open_terminal(teleop)
        rclpy.spin_until_future_complete(teleop.node, teleop.quit_future)
    except KeyboardInterrupt:
        pass
    except Exception as exc:
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        if keyboard is not None:
            keyboard.close()
        if teleop in _running:
            _running.remove(teleop)
        try:     # the original publishes a zero Twist on the way out
            teleop.pub.publish(Twist())
        except Exception:
            pass
        teleop.node.destroy_node()
        rclpy.try_shutdown()
