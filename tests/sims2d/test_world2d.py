"""labkit's 2D stand-in for the Gazebo chapter: ray casting, diff drive, odometry,
the ros_gz_bridge and teleop_twist_keyboard."""
import math

import numpy as np
import pytest

from labkit.sims.world2d import bridge, transport, world as w2d
from labkit.sims.world2d.sim import Simulation
from labkit.sims.world2d.transport import Transport


def make_world(obstacles, samples=361, min_angle=-math.pi, max_angle=math.pi,
               pose=(0.0, 0.0, 0.0), range_min=0.08, range_max=10.0, odom_hz=10):
    return w2d.from_dict({
        "world": "test_world", "ground": [20, 20], "obstacles": obstacles,
        "models": {"vehicle_blue": {
            "pose": list(pose), "chassis": {"size": [0.4, 0.4], "offset": [0.0, 0.0]},
            "diff_drive": {"odom_publish_frequency": odom_hz},
            "lidar": {"samples": samples, "min_angle": min_angle, "max_angle": max_angle,
                      "range_min": range_min, "range_max": range_max}}}})


WALL_AHEAD = [{"name": "wall", "type": "box", "pose": [2.05, 0.0, 0.0], "size": [0.1, 10.0]}]


def one_degree_index(deg):
    return 180 + deg          # 361 rays from -180 deg to 180 deg, one per degree


# ---------------------------------------------------------------- ray casting
def test_wall_two_metres_ahead():
    world = make_world(WALL_AHEAD)
    lidar = world.vehicles[0].lidar
    assert lidar.angle_step == pytest.approx(math.radians(1.0))
    ranges = w2d.scan_ranges(world, lidar, (0.0, 0.0, 0.0))
    assert ranges[one_degree_index(0)] == pytest.approx(2.0)
    assert ranges[one_degree_index(30)] == pytest.approx(2.0 / math.cos(math.radians(30)))
    assert ranges[one_degree_index(-45)] == pytest.approx(2.0 * math.sqrt(2))
    # the wall ends at y = +-5: at 70 deg the ray passes its end (2 tan 70 = 5.49 > 5)
    assert math.isinf(ranges[one_degree_index(70)]) and ranges[one_degree_index(70)] > 0
    assert np.all(np.isinf(ranges[one_degree_index(90):]))      # nothing behind or beside


def test_cylinder_and_rotated_robot():
    world = make_world([{"name": "pillar", "type": "cylinder", "pose": [0.0, 3.0], "radius": 0.5}])
    lidar = world.vehicles[0].lidar
    # facing +y (yaw 90 deg): the pillar is straight ahead at 3 - 0.5
    ranges = w2d.scan_ranges(world, lidar, (0.0, 0.0, math.pi / 2))
    assert ranges[one_degree_index(0)] == pytest.approx(2.5)
    # tangent ray: sin(a) = 0.5 / 3 -> a = 9.59 deg; 9 deg hits, 10 deg misses
    assert np.isfinite(ranges[one_degree_index(9)])
    assert np.isinf(ranges[one_degree_index(10)])
    # facing +x, the same pillar is 90 deg to the left
    ranges = w2d.scan_ranges(world, lidar, (0.0, 0.0, 0.0))
    assert ranges[one_degree_index(90)] == pytest.approx(2.5)


def test_range_limits_give_infinities():
    world = make_world(WALL_AHEAD, range_max=1.5)
    ranges = w2d.scan_ranges(world, world.vehicles[0].lidar, (0.0, 0.0, 0.0))
    assert ranges[one_degree_index(0)] == np.inf           # beyond range_max
    world = make_world(WALL_AHEAD, range_min=2.5)
    ranges = w2d.scan_ranges(world, world.vehicles[0].lidar, (0.0, 0.0, 0.0))
    assert ranges[one_degree_index(0)] == -np.inf          # nearer than range_min


def test_seed_world_sensor_config():
    world = w2d.load("visualize_lidar.sdf")
    assert world.name == "visualize_lidar_world"
    (vehicle,) = world.vehicles
    assert vehicle.name == "vehicle_blue" and vehicle.pose == (-4.0, 0.0, 0.0)
    lidar = vehicle.lidar
    assert (lidar.topic, lidar.samples, lidar.update_rate) == ("lidar2", 640, 10)
    assert lidar.angles()[0] == pytest.approx(-1.396263)
    assert lidar.angles()[-1] == pytest.approx(1.396263)
    with pytest.raises(FileNotFoundError):
        w2d.find("no_such_world.sdf")


def test_scan_points_in_robot_frame():
    world = make_world(WALL_AHEAD)
    lidar = world.vehicles[0].lidar
    ranges = w2d.scan_ranges(world, lidar, (0.0, 0.0, 0.0))
    points = w2d.scan_points(ranges, lidar)
    assert points.shape[1] == 3
    assert np.allclose(points[:, 0], 2.0)           # every hit lies on the wall's face x = 2


# ---------------------------------------------------------------- diff drive and odometry
def drive(sim, linear, angular, seconds):
    sim.transport.advertise("/model/vehicle_blue/cmd_vel", "ignition.msgs.Twist")(
        {"linear": {"x": linear}, "angular": {"z": angular}})
    sim.advance(seconds)


def test_one_second_at_one_metre_per_second_is_one_metre():
    sim = Simulation(make_world([], pose=(1.0, 2.0, 0.0)), transport=Transport())
    drive(sim, 1.0, 0.0, 1.0)
    x, y, yaw = sim.vehicle().pose
    assert (x, y, yaw) == (pytest.approx(2.0), pytest.approx(2.0), pytest.approx(0.0))
    assert sim.sim_time == pytest.approx(1.0)


def test_turning_and_arcs():
    sim = Simulation(make_world([]), transport=Transport())
    drive(sim, 0.0, math.pi / 2, 1.0)
    assert sim.vehicle().pose == (pytest.approx(0.0), pytest.approx(0.0),
                                  pytest.approx(math.pi / 2))
    sim = Simulation(make_world([]), transport=Transport())
    drive(sim, 1.0, math.pi / 3.0, 3.0)    # half a circle of radius 3/pi to the left
    x, y, yaw = sim.vehicle().pose
    assert (x, y) == (pytest.approx(0.0, abs=1e-9), pytest.approx(6.0 / math.pi))
    assert abs(yaw) == pytest.approx(math.pi)


def test_command_holds_and_obstacles_stop_the_robot():
    sim = Simulation(make_world(WALL_AHEAD), transport=Transport())
    drive(sim, 1.0, 0.0, 5.0)              # DiffDrive keeps the last command: drives into the wall
    x = sim.vehicle().pose[0]
    assert 1.7 <= x < 1.8                   # chassis half length 0.2: stops just short of x = 2
    assert sim.vehicle().linear == 0.0


def test_odometry_messages_relative_to_start():
    t = Transport()
    sim = Simulation(make_world([], pose=(-4.0, 1.0, math.pi / 2), odom_hz=1), transport=t)
    got = []
    t.subscribe("/model/vehicle_blue/odometry", "ignition.msgs.Odometry", got.append)
    drive(sim, 0.5, 0.0, 2.0)
    assert len(got) == 2                    # odom_publish_frequency 1 Hz
    odom = bridge.odometry_to_ros(got[-1])
    assert odom.header.frame_id == "vehicle_blue/odom"
    assert odom.child_frame_id == "vehicle_blue/chassis"
    assert (odom.header.stamp.sec, odom.header.stamp.nanosec) == (2, 0)
    assert odom.pose.pose.position.x == pytest.approx(1.0)   # 2 s at 0.5 m/s, along its heading
    assert odom.pose.pose.position.y == pytest.approx(0.0)
    assert odom.twist.twist.linear.x == pytest.approx(0.5)
    assert sim.vehicle().pose[1] == pytest.approx(2.0)       # in the world it went +y


def test_laser_scan_message_fields():
    t = Transport()
    sim = Simulation(make_world(WALL_AHEAD), transport=t)
    got = []
    t.subscribe("/lidar2", "ignition.msgs.LaserScan", got.append)
    sim.advance(0.3)
    assert len(got) == 3                                     # 10 Hz
    scan = bridge.laser_scan_to_ros(got[0])
    assert scan.header.frame_id == "vehicle_blue/lidar_link/gpu_lidar"
    assert (scan.header.stamp.sec, scan.header.stamp.nanosec) == (0, 100000000)
    assert len(scan.ranges) == 361 and len(scan.intensities) == 361
    assert scan.ranges[180] == pytest.approx(2.0)
    assert scan.angle_min == pytest.approx(-math.pi)
    assert scan.angle_increment == pytest.approx(math.radians(1.0))
    assert (scan.range_min, scan.range_max) == (pytest.approx(0.08), pytest.approx(10.0))


# ---------------------------------------------------------------- bridge syntax
@pytest.mark.parametrize("spec, direction, ros_type, gz_type", [
    ("/lidar2@sensor_msgs/msg/LaserScan[ignition.msgs.LaserScan", "[",
     "sensor_msgs/msg/LaserScan", "ignition.msgs.LaserScan"),
    ("/model/vehicle_blue/cmd_vel@geometry_msgs/msg/Twist]ignition.msgs.Twist", "]",
     "geometry_msgs/msg/Twist", "ignition.msgs.Twist"),
    ("/chatter@std_msgs/msg/String@gz.msgs.StringMsg", "@", "std_msgs/msg/String",
     "gz.msgs.StringMsg"),
])
def test_parse_bridge_spec(spec, direction, ros_type, gz_type):
    config = bridge.parse_spec(spec)
    assert (config.direction, config.ros_type_name, config.gz_type_name) == \
        (direction, ros_type, gz_type)
    assert config.ros_topic_name == config.gz_topic_name == spec.split("@")[0]


@pytest.mark.parametrize("spec", ["/lidar2", "@sensor_msgs/msg/LaserScan[x", "/t@[x",
                                  "/t@std_msgs/msg/String", "/t@std_msgs/msg/String[",
                                  "/t@]x", "/t@std_msgs/srv/Empty@a@b"])
def test_bad_bridge_specs(spec):
    with pytest.raises(bridge.UsageError):
        bridge.parse_spec(spec)


def test_gz_type_prefixes_are_equivalent():
    assert transport.normalize_type("gz.msgs.Twist") == "ignition.msgs.Twist"
    assert bridge.factory("geometry_msgs/msg/Twist", "gz.msgs.Twist") is not None
    assert bridge.factory("geometry_msgs/Twist", "ignition.msgs.Twist") is None


def test_meshcat_scan_command():
    from labkit.sims.world2d import meshcat_scan
    world = make_world(WALL_AHEAD)
    lidar = world.vehicles[0].lidar
    points = w2d.scan_points(w2d.scan_ranges(world, lidar, (0.0, 0.0, 0.0)), lidar)
    command = meshcat_scan.set_scan_command(points)
    assert command["type"] == "set_object" and command["path"] == "/meshcat/scan"
    position = command["object"]["geometries"][0]["data"]["attributes"]["position"]
    back = np.frombuffer(position["array"].data, dtype=np.float32).reshape(-1, 3)
    assert np.allclose(back, points)
    assert command["object"]["object"]["type"] == "Points"


# ---------------------------------------------------------------- visualize_lidar.sdf's topics
FORTRESS_TOPICS = [      # `ign topic -l` for visualize_lidar.sdf (Fortress), less the GUI's own
    "/clock", "/gazebo/resource_paths", "/lidar", "/lidar/points", "/lidar2", "/lidar2/points",
    "/model/vehicle_blue/odometry", "/model/vehicle_blue/tf", "/stats",
    "/world/visualize_lidar_world/clock", "/world/visualize_lidar_world/dynamic_pose/info",
    "/world/visualize_lidar_world/pose/info", "/world/visualize_lidar_world/scene/deletion",
    "/world/visualize_lidar_world/scene/info", "/world/visualize_lidar_world/state",
    "/world/visualize_lidar_world/stats"]


def test_topic_list_is_the_advertised_topics_of_visualize_lidar():
    """Both lidars (model_with_lidar's /lidar, vehicle_blue's /lidar2) and their /points;
    cmd_vel, only subscribed by DiffDrive, appears once a ROS->GZ bridge advertises it."""
    t = Transport()
    sim = Simulation(w2d.load("visualize_lidar.sdf"), transport=t)
    assert t.topics() == FORTRESS_TOPICS
    assert t.info("/model/vehicle_blue/cmd_vel") == ("ignition.msgs.Twist", 0, 1)
    publish = t.advertise("/model/vehicle_blue/cmd_vel", "ignition.msgs.Twist")
    assert t.topics() == sorted(FORTRESS_TOPICS + ["/model/vehicle_blue/cmd_vel"])
    t.unadvertise(publish)
    sim.close()
    assert t.topics() == []


def test_model_with_lidar_sees_vehicle_blue_coming():
    t = Transport()
    world = w2d.load("visualize_lidar.sdf")
    assert [s.name for s in world.sensors] == ["model_with_lidar"]
    sim = Simulation(world, transport=t)
    scans = []
    t.subscribe("/lidar", "ignition.msgs.LaserScan", scans.append)
    sim.advance(0.1)
    scan = scans[-1]
    assert scan["header"]["data"][0]["value"] == ["model_with_lidar::link::gpu_lidar"]
    assert (scan["count"], scan["vertical_count"], len(scan["ranges"])) == (640, 16, 640 * 16)
    middle = scan["ranges"][319:321]          # straight ahead: along -x, at y = -0.05
    # vehicle_blue's chassis front: -4 + (-0.151427 + 2.01142 / 2) = -3.1457 m
    assert middle == pytest.approx([3.95 + 3.1457] * 2, abs=0.02)
    sim.vehicle().on_cmd_vel({"linear": {"x": 1.0}, "angular": {"z": 0.0}})
    sim.advance(1.0)
    assert scans[-1]["ranges"][319:321] == pytest.approx([3.95 + 3.1457 - 1.0] * 2, abs=0.03)
    sim.close()


# ---------------------------------------------------------------- ROS -> Gazebo
def _ros_samples():
    from labkit.interfaces import get_type
    scan = get_type("sensor_msgs/msg/LaserScan")()
    scan.header.frame_id, scan.header.stamp.sec, scan.header.stamp.nanosec = "robot/lidar", 3, 500
    scan.angle_min, scan.angle_max, scan.angle_increment = -1.0, 1.0, 0.5
    scan.range_min, scan.range_max = 0.1, 8.0
    scan.ranges, scan.intensities = [1.0, 2.0, 3.0, 4.0, 5.0], [0.0, 1.0, 0.0, 1.0, 0.0]
    odom = get_type("nav_msgs/msg/Odometry")()
    odom.header.frame_id, odom.child_frame_id = "vehicle_blue/odom", "vehicle_blue/chassis"
    odom.header.stamp.sec = 7
    odom.pose.pose.position.x, odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = 1.5, 0.6, 0.8
    odom.twist.twist.linear.x, odom.twist.twist.angular.z = 0.5, -0.25
    tf = get_type("tf2_msgs/msg/TFMessage")()
    t = get_type("geometry_msgs/msg/TransformStamped")()
    t.header.frame_id, t.child_frame_id = "world", "vehicle_blue/chassis"
    t.transform.translation.y, t.transform.rotation.w = 2.0, 1.0
    tf.transforms = [t]
    clock = get_type("rosgraph_msgs/msg/Clock")()
    clock.clock.sec, clock.clock.nanosec = 12, 340000000
    return [("sensor_msgs/msg/LaserScan", "ignition.msgs.LaserScan", scan),
            ("nav_msgs/msg/Odometry", "ignition.msgs.Odometry", odom),
            ("tf2_msgs/msg/TFMessage", "ignition.msgs.Pose_V", tf),
            ("rosgraph_msgs/msg/Clock", "ignition.msgs.Clock", clock)]


@pytest.mark.parametrize("index", range(4), ids=["LaserScan", "Odometry", "TFMessage", "Clock"])
def test_every_bridged_type_converts_both_ways(index):
    """ros_gz_bridge converts these types ROS -> Gazebo too (a ']' bridge): back and
    forth gives the same ROS message, '/' in frame names becoming Gazebo's '::'."""
    ros_type, gz_type, msg = _ros_samples()[index]
    to_ros, to_gz = bridge.factory(ros_type, gz_type)
    assert to_gz is not None
    gz_msg = to_gz(msg)
    assert to_ros(gz_msg) == msg
    if index == 1:
        assert gz_msg["header"]["data"] == [{"key": "frame_id", "value": ["vehicle_blue::odom"]},
                                            {"key": "child_frame_id", "value": ["vehicle_blue::chassis"]}]
