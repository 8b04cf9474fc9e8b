"""The 2D world: obstacles from a small YAML file, and vectorised ray casting.

Not Gazebo: the world is flat and seen from above. A box is a rectangle
(centre x, y, yaw; size along its own x and y), a cylinder a circle. The
lidar's plane cuts every obstacle, so every obstacle is seen by the scan.
"""
import math
import os
from dataclasses import dataclass, field

import numpy as np

WORLDS_DIR = os.path.join(os.path.dirname(__file__), "worlds")


@dataclass
class Obstacle:
    name: str
    type: str                       # 'box' or 'cylinder'
    x: float
    y: float
    yaw: float = 0.0
    size: tuple = (1.0, 1.0)        # box only
    radius: float = 0.5             # cylinder only
    color: tuple = (120, 120, 120)

    def corners(self):
        """The 4 corners of a box, counter-clockwise, in the world frame."""
        hx, hy = self.size[0] / 2.0, self.size[1] / 2.0
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        local = [(hx, hy), (-hx, hy), (-hx, -hy), (hx, -hy)]
        return [(self.x + c * px - s * py, self.y + s * px + c * py) for px, py in local]

    def contains(self, points):
        """Which of the (N, 2) points lie inside this obstacle."""
        d = np.asarray(points, dtype=float) - (self.x, self.y)
        if self.type == "cylinder":
            return (d ** 2).sum(axis=1) <= self.radius ** 2
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        lx = c * d[:, 0] + s * d[:, 1]
        ly = -s * d[:, 0] + c * d[:, 1]
        return (np.abs(lx) <= self.size[0] / 2.0) & (np.abs(ly) <= self.size[1] / 2.0)


@dataclass
class LidarConfig:
    link: str = "lidar_link"
    sensor: str = "gpu_lidar"
    topic: str = "lidar2"
    offset: tuple = (0.0, 0.0)       # in the model frame
    update_rate: float = 10.0
    samples: int = 640
    min_angle: float = -1.396263
    max_angle: float = 1.396263
    range_min: float = 0.08
    range_max: float = 10.0

    @property
    def angle_step(self):
        # gz-sensors: (max - min) / (samples - 1), both ends included
        return (self.max_angle - self.min_angle) / max(1, self.samples - 1)

    def angles(self):
        return self.min_angle + self.angle_step * np.arange(self.samples)


@dataclass
class VehicleConfig:
    name: str = "vehicle_blue"
    pose: tuple = (0.0, 0.0, 0.0)            # x, y, yaw at start
    chassis_size: tuple = (2.01142, 1.0)
    chassis_offset: tuple = (-0.151427, 0.0)
    color: tuple = (128, 128, 255)
    wheel_separation: float = 1.25
    wheel_radius: float = 0.3
    odom_publish_frequency: float = 1.0
    lidar: LidarConfig = field(default_factory=LidarConfig)


@dataclass
class SensorModel:
    """A static model carrying a lidar (visualize_lidar.sdf's model_with_lidar)."""
    name: str = "model_with_lidar"
    pose: tuple = (0.0, 0.0, 0.0)            # x, y, yaw of the sensor
    vertical_count: int = 1                  # layers of a 3D lidar (the 2D scan is each layer)
    lidar: LidarConfig = field(default_factory=LidarConfig)


@dataclass
class World:
    name: str = "default"
    ground: tuple = (20.0, 20.0)
    obstacles: list = field(default_factory=list)
    vehicles: list = field(default_factory=list)
    sensors: list = field(default_factory=list)
    source: str = ""

    # ------------------------------------------------------------ geometry caches
    def _geometry(self):
        cache = getattr(self, "_cache", None)
        if cache is not None and cache[0] == len(self.obstacles):
            return cache[1]
        starts, ends, circles = [], [], []
        for ob in self.obstacles:
            if ob.type == "cylinder":
                circles.append((ob.x, ob.y, ob.radius))
            else:
                pts = ob.corners()
                for i in range(4):
                    starts.append(pts[i])
                    ends.append(pts[(i + 1) % 4])
        geometry = (np.array(starts, float).reshape(-1, 2), np.array(ends, float).reshape(-1, 2),
                    np.array(circles, float).reshape(-1, 3))
        self._cache = (len(self.obstacles), geometry)
        return geometry

    def raycast(self, origin, angles):
        """Distance along each ray (world angles, radians) to the nearest obstacle; inf if none."""
        ox, oy = origin
        angles = np.asarray(angles, dtype=float)
        dx, dy = np.cos(angles)[:, None], np.sin(angles)[:, None]
        best = np.full(angles.shape, np.inf)
        starts, ends, circles = self._geometry()
        if len(starts):
            ex, ey = (ends - starts).T                     # segment directions (M,)
            px, py = starts[:, 0] - ox, starts[:, 1] - oy  # segment starts, ray-relative
            denom = dx * ey - dy * ex                      # (N, M) cross(d, e)
            with np.errstate(divide="ignore", invalid="ignore"):
                s = (px * ey - py * ex) / denom            # distance along the ray
                t = (px * dy - py * dx) / denom            # position along the segment
            hit = (np.abs(denom) > 1e-12) & (s >= 0.0) & (t >= 0.0) & (t <= 1.0)
            best = np.minimum(best, np.where(hit, s, np.inf).min(axis=1))
        if len(circles):
            cx, cy, r = circles[:, 0] - ox, circles[:, 1] - oy, circles[:, 2]
            b = dx * cx + dy * cy                          # (N, K) projection of centre on ray
            disc = b * b - (cx * cx + cy * cy - r * r)
            root = np.sqrt(np.maximum(disc, 0.0))
            near, far = b - root, b + root
            s = np.where(near >= 0.0, near, far)           # origin inside: the exit point
            hit = (disc >= 0.0) & (s >= 0.0)
            best = np.minimum(best, np.where(hit, s, np.inf).min(axis=1))
        return best

    def collides(self, points):
        """True if any of the (N, 2) points is inside an obstacle."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        if not len(points):
            return False
        centre = points.mean(axis=0)
        spread = float(np.sqrt(((points - centre) ** 2).sum(axis=1).max()))
        for ob in self.obstacles:
            # only obstacles whose bounding circle reaches the points' one can touch them
            bound = ob.radius if ob.type == "cylinder" else math.hypot(*ob.size) / 2.0
            if math.hypot(ob.x - centre[0], ob.y - centre[1]) > bound + spread:
                continue
            if ob.contains(points).any():
                return True
        return False


def scan_ranges(world, lidar, pose):
    """A lidar's ranges from a vehicle pose (x, y, yaw), as gz-sensors reports them:
    beyond range_max is +inf, nearer than range_min is -inf."""
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    ox = x + c * lidar.offset[0] - s * lidar.offset[1]
    oy = y + s * lidar.offset[0] + c * lidar.offset[1]
    ranges = world.raycast((ox, oy), yaw + lidar.angles())
    ranges[ranges > lidar.range_max] = np.inf
    ranges[ranges < lidar.range_min] = -np.inf
    return ranges


def scan_points(ranges, lidar, frame="sensor"):
    """(N, 3) points of the finite ranges, in the sensor frame (frame='sensor')
    or in the vehicle's model frame (frame='model'): for the 3D viewer."""
    ranges = np.asarray(ranges, dtype=float)
    angles = lidar.angles()[: len(ranges)]
    ok = np.isfinite(ranges)
    x = ranges[ok] * np.cos(angles[ok])
    y = ranges[ok] * np.sin(angles[ok])
    if frame == "model":
        x, y = x + lidar.offset[0], y + lidar.offset[1]
    return np.column_stack([x, y, np.zeros_like(x)])


# ---------------------------------------------------------------- loading
def _obstacle(spec):
    pose = list(spec.get("pose", [0.0, 0.0, 0.0])) + [0.0, 0.0, 0.0]
    kind = spec.get("type", "box")
    if kind not in ("box", "cylinder"):
        raise ValueError(f"obstacle {spec.get('name')!r}: unknown type {kind!r} (box, cylinder)")
    return Obstacle(name=str(spec.get("name", kind)), type=kind, x=float(pose[0]),
                    y=float(pose[1]), yaw=float(pose[2]),
                    size=tuple(float(v) for v in spec.get("size", (1.0, 1.0))),
                    radius=float(spec.get("radius", 0.5)),
                    color=tuple(spec.get("color", (120, 120, 120))))


def _vehicle(name, spec):
    pose = list(spec.get("pose", [0.0, 0.0, 0.0])) + [0.0, 0.0, 0.0]
    chassis = spec.get("chassis", {})
    drive = spec.get("diff_drive", {})
    lidar = dict(spec.get("lidar", {}))
    if "offset" in lidar:
        lidar["offset"] = tuple(float(v) for v in lidar["offset"])
    return VehicleConfig(
        name=name, pose=(float(pose[0]), float(pose[1]), float(pose[2])),
        chassis_size=tuple(chassis.get("size", (2.01142, 1.0))),
        chassis_offset=tuple(chassis.get("offset", (-0.151427, 0.0))),
        color=tuple(chassis.get("color", (128, 128, 255))),
        wheel_separation=float(drive.get("wheel_separation", 1.25)),
        wheel_radius=float(drive.get("wheel_radius", 0.3)),
        odom_publish_frequency=float(drive.get("odom_publish_frequency", 1.0)),
        lidar=LidarConfig(**lidar))


def _sensor(name, spec):
    pose = list(spec.get("pose", [0.0, 0.0, 0.0])) + [0.0, 0.0, 0.0]
    lidar = dict(spec.get("lidar", {}))
    return SensorModel(name=name, pose=(float(pose[0]), float(pose[1]), float(pose[2])),
                       vertical_count=int(spec.get("vertical_samples", 1)),
                       lidar=LidarConfig(**lidar))


def from_dict(data, source=""):
    world = World(name=str(data.get("world", "default")),
                  ground=tuple(data.get("ground", (20.0, 20.0))), source=source)
    world.obstacles = [_obstacle(o) for o in data.get("obstacles", [])]
    world.vehicles = [_vehicle(n, v) for n, v in (data.get("models") or {}).items()]
    world.sensors = [_sensor(n, v) for n, v in (data.get("sensors") or {}).items()]
    return world


def find(name):
    """A world file: a path, or a bundled world by name ('visualize_lidar.sdf' finds
    worlds/visualize_lidar.yaml, as `ign gazebo` finds its example worlds)."""
    if os.path.isfile(name):
        return name
    stem = os.path.basename(name)
    for ext in (".sdf", ".yaml", ".yml"):
        if stem.endswith(ext):
            stem = stem[: -len(ext)]
    path = os.path.join(WORLDS_DIR, stem + ".yaml")
    if os.path.isfile(path):
        return path
    raise FileNotFoundError(name)


def load(name="visualize_lidar.sdf"):
    import yaml
    path = find(name)
    with open(path, encoding="utf-8") as handle:
        return from_dict(yaml.safe_load(handle) or {}, source=path)


def bundled():
    """Names of the worlds shipped with labkit."""
    return sorted(f[:-5] for f in os.listdir(WORLDS_DIR) if f.endswith(".yaml"))
