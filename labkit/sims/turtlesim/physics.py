"""The turtlesim world without ROS: kinematics, pen, walls, spawn/kill/reset.

Numbers follow Humble's turtlesim (turtle.cpp, turtle_frame.cpp): a 500x500
pixel window where one metre is 45 pixels (the height of a turtle image), so
the world is (500 - 1) / 45 = 11.088889 m wide; the update timer ticks every
16 ms and always integrates dt = 0.016 s; a velocity command lasts 1 s.

Positions are kept like the original, in window coordinates (metres, y down);
poses are reported with y up. The node (node.py) wraps this in ROS topics,
services and the action; the canvas (labkit/viz/canvas.py) draws it.
"""

import math
import random
import struct
import threading
from collections import deque

import cv2
import numpy as np

PI = 3.14159265            # the value turtlesim's turtle.h uses, not math.pi
TWO_PI = 2.0 * PI
WINDOW_SIZE = 500          # pixels, fixed like the Qt frame
METER = 45.0               # pixels per metre
UPDATE_PERIOD = 0.016      # s: the QTimer interval, and the dt of every step
COMMAND_TIMEOUT_NS = 1_000_000_000
DEFAULT_BACKGROUND = (69, 86, 255)
DEFAULT_PEN = (179, 184, 255)
DEFAULT_PEN_WIDTH = 3
SPRITE_COUNT = 9           # how many turtle looks there are to pick from
ROTATION_TOLERANCE = 0.02  # rad: when rotate_absolute counts as done
HISTORY_SECONDS = 30.0     # how much motion is kept for replays
_KEYFRAME_EVERY_NS = 2_000_000_000
_LIVE_OPS_KEPT = 5000


def f32(value):
    """Round a Python float to float32, as a C++ float (or a float32 field) holds it."""
    return struct.unpack("f", struct.pack("f", value))[0]


# Qt computes these in float: (width() - 1) / meter_
WIDTH_IN_METERS = f32((WINDOW_SIZE - 1) / METER)
HEIGHT_IN_METERS = WIDTH_IN_METERS
CENTER = WIDTH_IN_METERS / 2.0


def normalize_angle(angle):
    """Wrap to [-PI, PI) exactly like turtlesim's normalizeAngle."""
    return angle - TWO_PI * math.floor((angle + PI) / TWO_PI)


class PathImage:
    """The pen layer: RGBA, transparent where nothing was drawn.

    Qt fills it with qRgba(255, 255, 255, 0), so an untouched pixel reads as
    white (r=g=b=255) to the colour sensor, exactly like Humble's turtlesim.
    Every drawing is also appended to `ops` (with a sequence number) so live
    views can draw incrementally and replays can rebuild any moment.
    """

    def __init__(self):
        self.pixels = np.empty((WINDOW_SIZE, WINDOW_SIZE, 4), np.uint8)
        self.seq = 0              # number of the last operation
        self.ops = deque()        # (seq, op) with op ('line', x0, y0, x1, y1, (r,g,b), w) or ('clear',)
        self._fill()

    def _fill(self):
        self.pixels[...] = (255, 255, 255, 0)

    def _log(self, op):
        self.seq += 1
        self.ops.append((self.seq, op))

    def clear(self):
        self._fill()
        self._log(("clear",))

    def draw_line(self, p0, p1, rgb, width):
        """A pen stroke between two points given in metres (window coordinates)."""
        self.stroke(p0[0] * METER, p0[1] * METER, p1[0] * METER, p1[1] * METER, tuple(rgb), int(width))

    def stroke(self, x0, y0, x1, y1, rgb, width):
        """A pen stroke in pixel coordinates."""
        # 4 bits of sub-pixel precision; Qt draws without antialiasing too
        cv2.line(self.pixels, (round(x0 * 16), round(y0 * 16)), (round(x1 * 16), round(y1 * 16)),
                 (*rgb, 255), max(1, width), cv2.LINE_8, 4)
        self._log(("line", x0, y0, x1, y1, rgb, width))

    def pixel(self, pos):
        """(r, g, b) under a point in metres, as QImage::pixel((pos * meter).toPoint())."""
        col = min(max(_qround(pos[0] * METER), 0), WINDOW_SIZE - 1)
        row = min(max(_qround(pos[1] * METER), 0), WINDOW_SIZE - 1)
        r, g, b, _ = self.pixels[row, col]
        return int(r), int(g), int(b)


def _qround(v):
    # QPointF::toPoint rounds half away from zero
    return int(math.floor(v + 0.5)) if v >= 0 else -int(math.floor(-v + 0.5))


class RotationGoal:
    """What a turtle needs from a rotate_absolute goal (node.py adapts the ROS goal handle).

    Methods called during a step: is_canceling(), publish_feedback(remaining),
    succeed(delta), canceled(delta). `theta` is the goal heading.
    """
    theta = 0.0

    def is_canceling(self):
        return False

    def publish_feedback(self, remaining):
        pass

    def succeed(self, delta):
        pass

    def canceled(self, delta):
        pass

    def abort(self, delta):
        pass


class StepResult:
    """What one turtle did in one step: the node publishes pose and colour and logs."""
    __slots__ = ("name", "pose", "color", "warning", "infos", "modified")

    def __init__(self, name):
        self.name = name
        self.pose = None        # (x, y, theta, linear_velocity, angular_velocity), y up
        self.color = None       # (r, g, b) under the turtle
        self.warning = None     # the wall message, if the turtle hit one
        self.infos = []         # info lines (rotation goal finished/cancelled)
        self.modified = False


class Turtle:
    def __init__(self, name, x, y, theta, sprite, now_ns=0):
        self.name = name
        self.pos = [float(x), float(y)]   # metres, window coordinates (y down)
        self.orient = float(theta)
        self.lin_vel_x = 0.0
        self.lin_vel_y = 0.0
        self.ang_vel = 0.0
        self.pen_on = True
        self.pen_rgb = DEFAULT_PEN
        self.pen_width = DEFAULT_PEN_WIDTH
        self.sprite = sprite
        self.last_command_ns = now_ns
        self.teleports = []               # (x, y, theta, linear, relative), applied at the next step
        self.goal = None                  # RotationGoal being executed
        self.goal_start_orient = 0.0
        self.goal_delta = 0.0

    # -- inputs (called from ROS callbacks) ---------------------------------------------
    def command_velocity(self, linear_x, linear_y, angular_z, now_ns):
        """A cmd_vel arrived. Returns the rotation goal it pre-empts (to abort), or None."""
        self.last_command_ns = now_ns
        self.lin_vel_x, self.lin_vel_y, self.ang_vel = float(linear_x), float(linear_y), float(angular_z)
        aborted, self.goal = self.goal, None
        return aborted

    def set_pen(self, r, g, b, width, off):
        self.pen_on = not off
        if off:
            return          # turtlesim keeps the old colour when the pen is lifted
        self.pen_rgb = (int(r), int(g), int(b))
        self.pen_width = int(width) if width != 0 else DEFAULT_PEN_WIDTH

    def teleport_absolute(self, x, y, theta):
        self.teleports.append((f32(x), f32(y), float(theta), 0.0, False))

    def teleport_relative(self, linear, angular):
        self.teleports.append((0.0, 0.0, float(angular), float(linear), True))

    def accept_goal(self, goal):
        """A new rotate_absolute goal. Returns the goal it replaces (to abort), or None."""
        previous = self.goal
        self.goal = goal
        self.goal_start_orient = self.orient
        self.goal_delta = 0.0
        return previous

    # -- one 16 ms step -----------------------------------------------------------------
    def update(self, now_ns, dt, path, width, height):
        res = StepResult(self.name)
        old_orient = self.orient

        for x, y, theta, linear, relative in self.teleports:
            old_pos = list(self.pos)
            if relative:
                self.orient += theta
                self.pos[0] += math.cos(self.orient) * linear
                self.pos[1] += -math.sin(self.orient) * linear
            else:
                self.pos[0] = x
                self.pos[1] = max(0.0, height - y)
                self.orient = theta
            if self.pen_on:
                path.draw_line(self.pos, old_pos, self.pen_rgb, self.pen_width)
            res.modified = True
        self.teleports = []

        if self.goal is not None:
            self._run_goal(now_ns, res)

        if now_ns - self.last_command_ns > COMMAND_TIMEOUT_NS:
            self.lin_vel_x = self.lin_vel_y = self.ang_vel = 0.0

        old_pos = list(self.pos)
        self.orient = normalize_angle(self.orient + self.ang_vel * dt)
        c, s = math.cos(self.orient), math.sin(self.orient)
        self.pos[0] += c * self.lin_vel_x * dt - s * self.lin_vel_y * dt
        self.pos[1] -= c * self.lin_vel_y * dt + s * self.lin_vel_x * dt

        x, y = self.pos
        if x < 0 or x > width or y < 0 or y > height:
            res.warning = "Oh no! I hit the wall! (Clamping from [x=%f, y=%f])" % (x, y)
        self.pos[0] = min(max(x, 0.0), width)
        self.pos[1] = min(max(y, 0.0), height)

        res.pose = (self.pos[0], height - self.pos[1], self.orient,
                    math.sqrt(self.lin_vel_x ** 2 + self.lin_vel_y ** 2), self.ang_vel)
        res.color = path.pixel(self.pos)

        if self.orient != old_orient:
            res.modified = True
        if self.pos != old_pos:
            if self.pen_on:
                path.draw_line(self.pos, old_pos, self.pen_rgb, self.pen_width)
            res.modified = True
        return res

    def _run_goal(self, now_ns, res):
        goal = self.goal
        if goal.is_canceling():
            res.infos.append("Rotation goal canceled")
            goal.canceled(self.goal_delta)
            self._stop_goal()
            return
        theta = normalize_angle(goal.theta)
        remaining = normalize_angle(theta - f32(self.orient))
        self.goal_delta = normalize_angle(f32(self.goal_start_orient - self.orient))
        goal.publish_feedback(remaining)
        if abs(normalize_angle(f32(self.orient) - theta)) < ROTATION_TOLERANCE:
            res.infos.append("Rotation goal completed successfully")
            goal.succeed(self.goal_delta)
            self._stop_goal()
        else:
            self.lin_vel_x = self.lin_vel_y = 0.0
            self.ang_vel = -1.0 if remaining < 0.0 else 1.0
            self.last_command_ns = now_ns

    def _stop_goal(self):
        self.goal = None
        self.lin_vel_x = self.lin_vel_y = self.ang_vel = 0.0

    def pose(self):
        """(x, y, theta) with y up, as the pose topic reports it."""
        return self.pos[0], HEIGHT_IN_METERS - self.pos[1], self.orient


class TurtleWorld:
    """Every turtle, the pen layer, the background, and a short history for replays.

    All mutation happens under `lock`; viewers take `snapshot()` or read the
    history under the same lock. `version` grows on every visible change and
    each registered listener is called (outside the lock) so a canvas can wake.
    """

    def __init__(self, seed=0):
        self.lock = threading.RLock()
        self.turtles = {}                 # name -> Turtle; stepped in sorted order like std::map
        self.id_counter = 0
        self.path = PathImage()
        self.background = DEFAULT_BACKGROUND
        self.frame_count = 0
        self.last_update_ns = None
        self.version = 0
        self.listeners = []
        self._rng = random.Random(seed)   # deterministic sprite choice (Qt uses rand())
        self.history = deque()            # (t_ns, path_seq, background, turtles) per changed step
        self.keyframes = deque()          # (t_ns, path_seq, pixels copy)
        self.now_ns = 0

    # -- spawn / kill / clear / reset ---------------------------------------------------
    def has_turtle(self, name):
        return name in self.turtles

    def spawn(self, name, x, y, theta, now_ns=None, sprite=None):
        """Add a turtle at (x, y) with y up. Returns its name, or '' if the name is taken."""
        with self.lock:
            now_ns = self.now_ns if now_ns is None else now_ns
            real_name = name
            if not real_name:
                while True:
                    self.id_counter += 1
                    real_name = "turtle%d" % self.id_counter
                    if real_name not in self.turtles:
                        break
            elif real_name in self.turtles:
                return ""
            if sprite is None:
                sprite = self._rng.randrange(SPRITE_COUNT)
            x, y, theta = f32(x), f32(y), f32(theta)
            self.turtles[real_name] = Turtle(real_name, x, HEIGHT_IN_METERS - y, theta, sprite, now_ns)
            self._changed()
        return real_name

    def kill(self, name):
        with self.lock:
            if name not in self.turtles:
                return False
            del self.turtles[name]
            self._changed()
        return True

    def clear(self):
        with self.lock:
            self.path.clear()
            self._changed()

    def remove_all(self):
        """Forget every turtle and restart the automatic names at turtle1."""
        with self.lock:
            self.turtles.clear()
            self.id_counter = 0
            self._changed()

    def reset(self, now_ns=None):
        """Remove every turtle, respawn turtle1 in the centre, clear the pen layer."""
        with self.lock:
            self.remove_all()
            self.spawn("", CENTER, CENTER, 0.0, now_ns)
            self.clear()

    def set_background(self, rgb):
        with self.lock:
            rgb = tuple(int(c) for c in rgb)
            if rgb != self.background:
                self.background = rgb
                self._changed()

    # -- time ---------------------------------------------------------------------------
    def step(self, now_ns, dt=UPDATE_PERIOD):
        """One timer tick. Returns a StepResult per turtle (none on the very first tick)."""
        with self.lock:
            self.now_ns = now_ns
            if self.last_update_ns is None:
                self.last_update_ns = now_ns   # like updateTurtles(): the first tick only starts the clock
                return []
            results = [self.turtles[n].update(now_ns, dt, self.path, WIDTH_IN_METERS, HEIGHT_IN_METERS)
                       for n in sorted(self.turtles)]
            self.frame_count += 1
            if any(r.modified for r in results):
                self._changed()
        return results

    # -- views --------------------------------------------------------------------------
    def snapshot(self):
        """A consistent copy of what is visible: (background, [(name, x_px, y_px, orient, sprite)], path_seq)."""
        with self.lock:
            return self.background, self._turtle_states(), self.path.seq

    def _turtle_states(self):
        return tuple((t.name, t.pos[0] * METER, t.pos[1] * METER, t.orient, t.sprite)
                     for _, t in sorted(self.turtles.items()))

    def ops_since(self, seq):
        """Pen operations after `seq`, or None if some were already forgotten."""
        with self.lock:
            ops = self.path.ops
            if ops and ops[0][0] > seq + 1:
                return None
            if not ops and self.path.seq > seq:
                return None
            return [op for s, op in ops if s > seq]

    def _changed(self):
        self.version += 1
        self._record(self.now_ns)
        for listener in list(self.listeners):
            listener()      # cheap (sets an event); viewers must not call back into the world

    def _record(self, now_ns):
        """Keep what a replay needs: each distinct visible state, and pen-layer keyframes."""
        state = (self.path.seq, self.background, self._turtle_states())
        if self.history and self.history[-1][1:] == state:
            return
        self.history.append((now_ns,) + state)
        last = self.keyframes[-1] if self.keyframes else None
        if last is None or (last[1] != self.path.seq and now_ns - last[0] >= _KEYFRAME_EVERY_NS):
            self.keyframes.append((now_ns, self.path.seq, self.path.pixels.copy()))
        self._trim(now_ns)

    def _trim(self, now_ns):
        horizon = now_ns - int(HISTORY_SECONDS * 1e9)
        while len(self.history) > 1 and self.history[1][0] <= horizon:
            self.history.popleft()
        first_seq = self.history[0][1]
        # keep the newest keyframe at or before the oldest remembered state
        while len(self.keyframes) > 1 and self.keyframes[1][1] <= first_seq:
            self.keyframes.popleft()
        # pen ops are needed from that keyframe on, and by a live canvas lagging behind
        keep_after = min(self.keyframes[0][1], self.path.seq - _LIVE_OPS_KEPT)
        ops = self.path.ops
        while ops and ops[0][0] <= keep_after:
            ops.popleft()

    def state_at(self, index):
        """Rebuild history entry `index`: (t_ns, background, turtles, pen pixels). Call under lock."""
        t_ns, seq, background, turtles = self.history[index]
        return t_ns, background, turtles, self.pixels_at(seq)

    def pixels_at(self, seq):
        """The pen layer as it was after operation `seq` (a new array). Call under lock."""
        base = None
        for k_t, k_seq, k_pixels in reversed(self.keyframes):
            if k_seq <= seq:
                base = (k_seq, k_pixels)
                break
        if base is None:
            raise LookupError("pen history before operation %d is gone" % seq)
        scratch = PathImage.__new__(PathImage)
        scratch.pixels = base[1].copy()
        scratch.seq, scratch.ops = base[0], deque()
        for s, op in self.path.ops:
            if base[0] < s <= seq:
                apply_op(scratch, op)
        return scratch.pixels


def apply_op(path, op):
    """Replay one logged pen operation (pixel coordinates) onto a PathImage."""
    if op[0] == "clear":
        path.clear()
    else:
        path.stroke(*op[1:])
