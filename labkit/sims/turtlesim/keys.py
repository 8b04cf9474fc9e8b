"""turtle_teleop_key's keys and startup text (no ROS here, so widgets can use it too)."""

BANNER = (
    "Reading from keyboard\n"
    "---------------------------\n"
    "Use arrow keys to move the turtle.\n"
    "Use G|B|V|C|D|E|R|T keys to rotate to absolute orientations. 'F' to cancel a rotation.\n"
    "'Q' to quit."
)

# key -> (linear, angular) for driving keys
DRIVE = {"up": (1.0, 0.0), "down": (-1.0, 0.0), "left": (0.0, 1.0), "right": (0.0, -1.0)}
# key -> goal heading (float32 literals of teleop_turtle_key.cpp)
ROTATE = {"g": 0.0, "t": 0.7854, "r": 1.5708, "e": 2.3562, "d": 3.1416,
          "c": -2.3562, "v": -1.5708, "b": -0.7854}
KEYS = tuple(DRIVE) + tuple(ROTATE) + ("f", "q")

# what the terminal sends: arrows arrive as ESC [ A..D and only the last byte counts
TTY_CHARS = {"A": "up", "B": "down", "C": "right", "D": "left"}
_ALIASES = {"arrowup": "up", "arrowdown": "down", "arrowleft": "left", "arrowright": "right"}


def key_name(key):
    """Normalise a key: 'ArrowUp'/'UP'/'up' -> 'up', 'G'/'g' -> 'g'; None if it means nothing."""
    k = str(key).strip().lower()
    k = _ALIASES.get(k, k)
    return k if k in KEYS else None
