"""The simulator behind `ign gazebo -v 4 -r visualize_lidar.sdf` (labkit's 2D stand-in).

What it does, the way gz-sim's DiffDrive system and gpu_lidar sensor do it:
- listens on /model/<name>/cmd_vel (ignition.msgs.Twist); the last command
  holds until the next one (DiffDrive has no timeout);
- moves the vehicle as a unicycle (exact arcs), stopping at obstacles;
- publishes /model/<name>/odometry (ignition.msgs.Odometry, pose relative to
  where it started, frame <name>/odom -> <name>/chassis) and
  /model/<name>/tf (ignition.msgs.Pose_V) at odom_publish_frequency;
- publishes the lidar's ignition.msgs.LaserScan on its topic at update_rate, for
  the vehicle's lidar and for every static sensor model (model_with_lidar, which
  sees the vehicles' chassis too); each lidar also advertises <topic>/points
  (ignition.msgs.PointCloudPacked) as gz-sensors does, but labkit does not fill
  point clouds (nothing is published there);
- publishes /clock and /world/<world>/clock (sim time, which starts at 0).
All on labkit's Gazebo-transport stand-in (transport.py), not on ROS topics.
"""
import math
import threading
from collections import deque

import numpy as np

from . import transport as gz
from .world import Obstacle, scan_ranges

STEP_NS = 10_000_000              # 10 ms physics step
HISTORY = 600                     # scans kept for the replay GIF (60 s at 10 Hz)

_running = []                     # live simulations, newest last


def _quaternion(yaw):
    return {"x": 0.0, "y": 0.0, "z": math.sin(yaw / 2.0), "w": math.cos(yaw / 2.0)}


class Vehicle:
    """A differential-drive model with a lidar on a fixed link."""

    def __init__(self, config):
        self.config = config
        self.x, self.y, self.yaw = config.pose
        self.cmd_linear = 0.0
        self.cmd_angular = 0.0
        self.linear = 0.0             # what it actually did in the last step
        self.angular = 0.0
        self.ranges = None            # the last scan
        self.scan_pose = None         # where the vehicle was when it took it
        self._lock = threading.Lock()

    @property
    def name(self):
        return self.config.name

    @property
    def pose(self):
        return (self.x, self.y, self.yaw)

    def odom_pose(self):
        """The pose relative to the start pose: what DiffDrive's odometry reports."""
        x0, y0, yaw0 = self.config.pose
        dx, dy = self.x - x0, self.y - y0
        c, s = math.cos(yaw0), math.sin(yaw0)
        yaw = math.atan2(math.sin(self.yaw - yaw0), math.cos(self.yaw - yaw0))
        return (c * dx + s * dy, -s * dx + c * dy, yaw)

    def on_cmd_vel(self, msg):
        with self._lock:
            self.cmd_linear = float(msg.get("linear", {}).get("x", 0.0))
            self.cmd_angular = float(msg.get("angular", {}).get("z", 0.0))

    def footprint(self, pose):
        """Points on the chassis outline at `pose` (for collisions)."""
        x, y, yaw = pose
        (lx, ly), (ox, oy) = self.config.chassis_size, self.config.chassis_offset
        xs = np.linspace(-lx / 2, lx / 2, max(2, int(lx / 0.2) + 1)) + ox
        ys = np.linspace(-ly / 2, ly / 2, max(2, int(ly / 0.2) + 1)) + oy
        outline = np.concatenate([
            np.column_stack([xs, np.full_like(xs, ys[0])]),
            np.column_stack([xs, np.full_like(xs, ys[-1])]),
            np.column_stack([np.full_like(ys, xs[0]), ys]),
            np.column_stack([np.full_like(ys, xs[-1]), ys])])
        c, s = math.cos(yaw), math.sin(yaw)
        return np.column_stack([x + c * outline[:, 0] - s * outline[:, 1],
                                y + s * outline[:, 0] + c * outline[:, 1]])

    def step(self, dt, world):
        with self._lock:
            v, w = self.cmd_linear, self.cmd_angular
        x, y, yaw = self.x, self.y, self.yaw
        # exact unicycle motion over dt (a straight line when w is 0)
        if abs(w) < 1e-12:
            nx, ny, nyaw = x + v * dt * math.cos(yaw), y + v * dt * math.sin(yaw), yaw
        else:
            nyaw = yaw + w * dt
            nx = x + v / w * (math.sin(nyaw) - math.sin(yaw))
            ny = y - v / w * (math.cos(nyaw) - math.cos(yaw))
        candidates = [((nx, ny, nyaw), v, w), ((x, y, nyaw), 0.0, w)]
        self.linear, self.angular = 0.0, 0.0
        for pose, lin, ang in candidates:
            if (lin == 0.0 and ang == 0.0) or not world.collides(self.footprint(pose)):
                self.x, self.y, self.yaw = pose[0], pose[1], math.atan2(
                    math.sin(pose[2]), math.cos(pose[2]))
                self.linear, self.angular = lin, ang
                break


class Simulation:
    """One running world. `advance(seconds)` steps it by hand (tests); `run()` is the
    server loop `ign gazebo` runs in its own labkit process."""

    def __init__(self, world, transport=None, running=True):
        self.world = world
        self.transport = transport or gz.TRANSPORT
        self.vehicles = [Vehicle(v) for v in world.vehicles]
        self.paused = not running
        self.time_ns = 0
        self.history = deque(maxlen=HISTORY)   # (sim time, [(pose, ranges) per vehicle])
        self._subs = []
        self._pubs = {}
        self._next = {}
        self._advertise()

    # ------------------------------------------------------------ topics
    def _advertise(self):
        t, w = self.transport, self.world.name

        def adv(name, msg_type):
            self._pubs[name] = t.advertise(name, msg_type)
        adv("/clock", "ignition.msgs.Clock")
        adv(f"/world/{w}/clock", "ignition.msgs.Clock")
        adv("/stats", "ignition.msgs.WorldStatistics")
        adv(f"/world/{w}/stats", "ignition.msgs.WorldStatistics")
        adv(f"/world/{w}/pose/info", "ignition.msgs.Pose_V")
        adv(f"/world/{w}/dynamic_pose/info", "ignition.msgs.Pose_V")
        adv(f"/world/{w}/scene/info", "ignition.msgs.Scene")
        adv(f"/world/{w}/scene/deletion", "ignition.msgs.UInt32_V")
        adv(f"/world/{w}/state", "ignition.msgs.SerializedStepMap")
        adv("/gazebo/resource_paths", "ignition.msgs.StringMsg_V")
        for vehicle in self.vehicles:
            name = vehicle.name
            adv(f"/model/{name}/odometry", "ignition.msgs.Odometry")
            adv(f"/model/{name}/tf", "ignition.msgs.Pose_V")
            adv(self.lidar_topic(vehicle), "ignition.msgs.LaserScan")
            self._subs.append(t.subscribe(f"/model/{name}/cmd_vel", "ignition.msgs.Twist",
                                          vehicle.on_cmd_vel))
            adv(self.lidar_topic(vehicle) + "/points", "ignition.msgs.PointCloudPacked")
            lidar = vehicle.config.lidar
            self._next[(name, "scan")] = _period_ns(lidar.update_rate)
            self._next[(name, "odom")] = _period_ns(vehicle.config.odom_publish_frequency)
        for sensor in self.world.sensors:
            topic = self.lidar_topic(sensor)
            adv(topic, "ignition.msgs.LaserScan")
            adv(topic + "/points", "ignition.msgs.PointCloudPacked")
            self._next[(sensor.name, "scan")] = _period_ns(sensor.lidar.update_rate)
        self._next["clock"] = 0

    @staticmethod
    def lidar_topic(model):
        """A vehicle's or a sensor model's lidar topic, absolute."""
        lidar = model.config.lidar if hasattr(model, "config") else model.lidar
        return lidar.topic if lidar.topic.startswith("/") else "/" + lidar.topic

    def _sensor_view(self, sensor):
        """The world as a static sensor sees it: without its own box, with each
        vehicle's chassis as a box where the vehicle is now."""
        import dataclasses
        seen = [o for o in self.world.obstacles if o.name != sensor.name]
        for vehicle in self.vehicles:
            x, y, yaw = vehicle.pose
            (lx, ly), (ox, oy) = vehicle.config.chassis_size, vehicle.config.chassis_offset
            c, s = math.cos(yaw), math.sin(yaw)
            seen.append(Obstacle(name=vehicle.name, type="box", x=x + c * ox - s * oy,
                                 y=y + s * ox + c * oy, yaw=yaw, size=(lx, ly)))
        return dataclasses.replace(self.world, obstacles=seen)

    def close(self):
        for handle in self._subs:
            self.transport.unsubscribe(handle)
        for publish in self._pubs.values():
            self.transport.unadvertise(publish)
        self._subs, self._pubs = [], {}
        if self in _running:
            _running.remove(self)

    # ------------------------------------------------------------ stepping
    @property
    def sim_time(self):
        return self.time_ns / 1e9

    def vehicle(self, name="vehicle_blue"):
        for vehicle in self.vehicles:
            if vehicle.name == name:
                return vehicle
        raise KeyError(name)

    def advance(self, seconds):
        """Step the world by `seconds` of sim time (a whole number of 10 ms steps)."""
        for _ in range(int(round(seconds * 1e9 / STEP_NS))):
            self.step()

    def step(self):
        dt = STEP_NS / 1e9
        for vehicle in self.vehicles:
            vehicle.step(dt, self.world)
        self.time_ns += STEP_NS
        self._publish_due()

    def _due(self, key, period_ns):
        if period_ns <= 0 or self.time_ns < self._next[key]:
            return False
        self._next[key] += period_ns * max(1, (self.time_ns - self._next[key]) // period_ns + 1)
        return True

    def _publish_due(self):
        t = self.sim_time
        if self._due("clock", 100_000_000):
            clock = {"sim": gz.stamp(t)}
            self._pubs["/clock"](clock)
            self._pubs[f"/world/{self.world.name}/clock"](clock)
        scans = []
        for vehicle in self.vehicles:
            name, lidar = vehicle.name, vehicle.config.lidar
            if self._due((name, "scan"), _period_ns(lidar.update_rate)):
                vehicle.ranges = scan_ranges(self.world, lidar, vehicle.pose)
                vehicle.scan_pose = vehicle.pose
                scans.append(vehicle)
                self._pubs[self.lidar_topic(vehicle)](self._laser_scan(vehicle, t))
            if self._due((name, "odom"), _period_ns(vehicle.config.odom_publish_frequency)):
                odom = self._odometry(vehicle, t)
                self._pubs[f"/model/{name}/odometry"](odom)
                pose = dict(odom["pose"], header=odom["header"])
                self._pubs[f"/model/{name}/tf"]({"pose": [pose]})
        for sensor in self.world.sensors:
            if self._due((sensor.name, "scan"), _period_ns(sensor.lidar.update_rate)):
                ranges = scan_ranges(self._sensor_view(sensor), sensor.lidar, sensor.pose)
                self._pubs[self.lidar_topic(sensor)](self._laser_scan_of(
                    sensor.name, sensor.lidar, sensor.pose, np.tile(ranges, sensor.vertical_count),
                    t, vertical_count=sensor.vertical_count))
        if scans:
            self.history.append((t, [(v.pose, v.ranges) for v in self.vehicles]))

    # ------------------------------------------------------------ messages (gz side)
    def _laser_scan(self, vehicle, t):
        return self._laser_scan_of(vehicle.name, vehicle.config.lidar, vehicle.pose,
                                   vehicle.ranges, t)

    @staticmethod
    def _laser_scan_of(model, lidar, pose, ranges, t, vertical_count=1):
        frame = f"{model}::{lidar.link}::{lidar.sensor}"
        count = lidar.samples
        x, y, yaw = pose
        return {
            "header": gz.header(t, frame_id=frame, seq=str(int(t * lidar.update_rate))),
            "frame": frame,
            "world_pose": {"position": {"x": x, "y": y, "z": 0.0}, "orientation": _quaternion(yaw)},
            "angle_min": lidar.min_angle, "angle_max": lidar.max_angle,
            "angle_step": lidar.angle_step, "range_min": lidar.range_min,
            "range_max": lidar.range_max, "count": count,
            "vertical_angle_min": -0.261799 if vertical_count > 1 else 0.0,
            "vertical_angle_max": 0.261799 if vertical_count > 1 else 0.0,
            "vertical_angle_step": 0.523598 / (vertical_count - 1) if vertical_count > 1 else 0.0,
            "vertical_count": vertical_count,
            "ranges": np.asarray(ranges, dtype=np.float64),
            "intensities": np.zeros(len(ranges)),
        }

    @staticmethod
    def _odometry(vehicle, t):
        ox, oy, oyaw = vehicle.odom_pose()
        return {
            "header": gz.header(t, frame_id=f"{vehicle.name}/odom",
                                child_frame_id=f"{vehicle.name}/chassis"),
            "pose": {"position": {"x": ox, "y": oy, "z": 0.0}, "orientation": _quaternion(oyaw)},
            "twist": {"linear": {"x": vehicle.linear, "y": 0.0, "z": 0.0},
                      "angular": {"x": 0.0, "y": 0.0, "z": vehicle.angular}},
        }

    # ------------------------------------------------------------ the server loop
    def run(self):
        """Step in (world) real time until the labkit process is told to stop."""
        from labkit import process
        from labkit.graph import world as clock
        proc = process.current()

        def stop_requested():
            return bool(getattr(proc, "_sigint", False))
        _running.append(self)
        try:
            deadline = clock.steady_ns()
            while True:
                deadline += STEP_NS
                now = clock.steady_ns()
                if now - deadline > 500_000_000:     # far behind (a slow machine): catch up
                    deadline = now
                clock.wait(stop_requested, timeout_ns=max(0, deadline - now))
                if stop_requested():
                    proc._sigint = False
                    break
                if not self.paused:
                    self.step()
        finally:
            self.close()

    def play(self):
        self.paused = False

    def pause(self):
        self.paused = True


def _period_ns(rate_hz):
    return int(round(1e9 / rate_hz)) if rate_hz and rate_hz > 0 else 0


def running():
    """The simulations alive now (newest last)."""
    return list(_running)


def current():
    """The newest running simulation (what `ign gazebo` started)."""
    if not _running:
        raise RuntimeError("no simulation is running (start one with "
                           "`%ign gazebo -v 4 -r visualize_lidar.sdf`)")
    return _running[-1]
