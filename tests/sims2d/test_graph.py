"""The chapter's commands end to end in virtual time: ign gazebo, parameter_bridge
with a remap, cmd_vel through the bridge, teleop_twist_keyboard, pictures."""
import pytest

import labkit
from labkit.sims import world2d
from labkit.sims.world2d import sim as sim_module, transport


@pytest.fixture
def gazebo():
    world2d.register()
    job = world2d.ign("gazebo -v 4 -r visualize_lidar.sdf")
    assert job.running()
    yield sim_module.current()
    labkit.reset()
    assert sim_module.running() == [] and transport.TRANSPORT.topics() == []


def ros_topics():
    return labkit.ros2("topic list").stdout.split()


def test_gazebo_topics_are_not_ros_topics(gazebo, capsys):
    world2d.ign("topic -l")
    out = capsys.readouterr().out.split()
    for name in ("/clock", "/lidar", "/lidar/points", "/lidar2", "/lidar2/points",
                 "/model/vehicle_blue/odometry", "/model/vehicle_blue/tf",
                 "/world/visualize_lidar_world/stats"):
        assert name in out
    assert "/model/vehicle_blue/cmd_vel" not in out          # only subscribed so far
    assert ros_topics() == ["/parameter_events", "/rosout"]


def test_bridge_remaps_lidar2_to_laser_scan(gazebo, capsys):
    spec = "/lidar2@sensor_msgs/msg/LaserScan[ignition.msgs.LaserScan"
    labkit.ros2(f"run ros_gz_bridge parameter_bridge {spec} --ros-args -r /lidar2:=/laser_scan")
    out = capsys.readouterr().err
    assert ("[ros_gz_bridge]: Creating GZ->ROS Bridge: [/lidar2 (ignition.msgs.LaserScan) -> "
            "/lidar2 (sensor_msgs/msg/LaserScan)] (Lazy 0)") in out
    assert "/laser_scan" in ros_topics() and "/lidar2" not in ros_topics()
    got = []
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    rclpy.init()
    node = rclpy.create_node("scan_listener")
    node.create_subscription(get_type("sensor_msgs/msg/LaserScan"), "/laser_scan", got.append, 10)
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=1.0)
    assert got
    scan = got[-1]
    assert len(scan.ranges) == 640
    assert scan.header.frame_id == "vehicle_blue/lidar_link/gpu_lidar"
    assert scan.header.stamp.sec < 5                       # sim time, from 0
    # straight ahead of vehicle_blue (at x=-4) the red box's face is not on the axis;
    # the east wall (inner face x=7.4) is out of range 10 m: the middle rays are inf
    assert scan.ranges[320] == float("inf")
    node.destroy_node()
    from labkit.sims.world2d import render
    image = render.laser_scan_image(scan, pixels=200)
    assert image.size == (200, 200)
    # the red box's corner region: hits to the front right are drawn white
    assert (255, 255, 255) in [c for _, c in image.getcolors(200 * 200)]


def test_cmd_vel_through_the_bridge_moves_the_robot(gazebo):
    labkit.ros2("run ros_gz_bridge parameter_bridge "
                "/model/vehicle_blue/cmd_vel@geometry_msgs/msg/Twist]ignition.msgs.Twist")
    x0, t0 = gazebo.vehicle().pose[0], gazebo.sim_time
    r = labkit.ros2("topic pub --once /model/vehicle_blue/cmd_vel geometry_msgs/Twist "
                    "'{linear: {x: 1.0}}'")
    assert r.returncode == 0
    labkit.sleep(1.0)
    moved = gazebo.vehicle().pose[0] - x0
    assert 1.0 <= moved <= gazebo.sim_time - t0 + 1e-9     # 1 m/s since the command came


def test_teleop_twist_keyboard_keys(gazebo, capsys):
    labkit.ros2("run ros_gz_bridge parameter_bridge "
                "/model/vehicle_blue/cmd_vel@geometry_msgs/msg/Twist]ignition.msgs.Twist")
    labkit.ros2("run teleop_twist_keyboard teleop_twist_keyboard "
                "--ros-args -r /cmd_vel:=/model/vehicle_blue/cmd_vel")
    out = capsys.readouterr().out
    assert "as Twist messages. It works best with a US keyboard layout." in out
    assert "currently:\tspeed 0.5\tturn 1.0 " in out
    vehicle = gazebo.vehicle()
    world2d.press("j")                       # turn left at 1.0 rad/s
    labkit.sleep(1.0)
    assert vehicle.cmd_angular == 1.0 and vehicle.cmd_linear == 0.0
    world2d.press("q")                       # speeds up by 10 %, keeps the direction
    assert "currently:\tspeed 0.55\tturn 1.1 " in capsys.readouterr().out
    labkit.sleep(0.1)
    assert vehicle.cmd_angular == pytest.approx(1.1)
    world2d.press("k")                       # anything else: stop
    labkit.sleep(0.1)
    assert (vehicle.cmd_linear, vehicle.cmd_angular) == (0.0, 0.0)


def test_pictures_and_scan_points(gazebo):
    labkit.sleep(0.5)
    from labkit.sims.world2d import render
    assert render.png_bytes(gazebo).startswith(b"\x89PNG")
    assert render.gif_bytes(gazebo).startswith(b"GIF89a")
    points = world2d.scan_points()
    assert points.shape[1] == 3 and len(points) > 100


def test_bridge_usage_and_unknown_pair(gazebo, capsys):
    r = labkit.ros2("run ros_gz_bridge parameter_bridge")
    assert r.returncode == 255
    assert "    [  == a bridge from Gazebo to ROS," in r.stdout
    labkit.ros2("run ros_gz_bridge parameter_bridge /x@std_msgs/msg/String[ignition.msgs.Twist")
    assert ("Failed to create a bridge for topic [/x] with ROS2 type [std_msgs/msg/String] to "
            "topic [/x] with Gazebo Transport type [ignition.msgs.Twist]") in capsys.readouterr().err


def take(topic, type_name, spins=20):
    """Messages a fresh subscription gets on `topic` while the graph runs a little."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    if not rclpy.ok():
        rclpy.init()
    node = rclpy.create_node("probe")
    got = []
    node.create_subscription(get_type(type_name), topic, got.append, 10)
    for _ in range(spins):
        rclpy.spin_once(node, timeout_sec=0.1)
    node.destroy_node()
    return got


def test_tf_and_clock_bridges(gazebo):
    labkit.ros2("run ros_gz_bridge parameter_bridge "
                "/model/vehicle_blue/tf@tf2_msgs/msg/TFMessage[ignition.msgs.Pose_V "
                "/clock@rosgraph_msgs/msg/Clock[ignition.msgs.Clock")
    clocks = take("/clock", "rosgraph_msgs/msg/Clock", spins=5)
    assert clocks and clocks[0].clock.sec == 0 and clocks[0].clock.nanosec > 0
    tfs = take("/model/vehicle_blue/tf", "tf2_msgs/msg/TFMessage", spins=25)
    assert tfs                                       # 1 Hz, like the world's DiffDrive
    (t,) = tfs[-1].transforms
    assert (t.header.frame_id, t.child_frame_id) == ("vehicle_blue/odom", "vehicle_blue/chassis")
    assert t.transform.rotation.w == 1.0


def test_teleop_ctrl_c_stops_robot_and_ends(gazebo):
    labkit.ros2("run ros_gz_bridge parameter_bridge "
                "/model/vehicle_blue/cmd_vel@geometry_msgs/msg/Twist]ignition.msgs.Twist")
    job = labkit.ros2("run teleop_twist_keyboard teleop_twist_keyboard "
                      "--ros-args -r /cmd_vel:=/model/vehicle_blue/cmd_vel")
    world2d.press("i")
    labkit.sleep(0.2)
    assert gazebo.vehicle().cmd_linear == 0.5
    world2d.press("\x03")
    labkit.sleep(0.2)
    assert not job.running()
    assert gazebo.vehicle().cmd_linear == 0.0        # the zero Twist on the way out


def test_without_r_the_world_starts_paused():
    world2d.register()
    world2d.ign("gazebo visualize_lidar.sdf")
    sim = sim_module.current()
    labkit.sleep(0.5)
    assert sim.paused and sim.sim_time == 0.0
    sim.play()
    labkit.sleep(0.5)
    assert sim.sim_time == pytest.approx(0.5, abs=0.011)
    labkit.reset()


def test_unknown_world_and_magic(capsys):
    world2d.register()
    from labkit.cli import magics
    assert "ign" in magics.MAGICS
    result = world2d.ign("gazebo -r no_such_world.sdf")
    assert result.returncode == 255
    assert "Unable to find or download file[no_such_world.sdf]" in result.stderr
    assert sim_module.running() == []


def test_ign_magic_prints_like_a_terminal(capsys):
    world2d.register()
    from labkit.cli import magics
    assert magics.MAGICS["ign"]("gazebo -r no_such_world.sdf") is None
    assert "Unable to find or download file[no_such_world.sdf]" in capsys.readouterr().err
    assert magics.MAGICS["ign"]("gazebo -r visualize_lidar.sdf") is None
    magics.MAGICS["ign"]("topic -l")
    assert "/model/vehicle_blue/odometry" in capsys.readouterr().out.split()
    labkit.reset()


def test_two_way_string_bridge_carries_each_message_once(gazebo):
    """/chatter@std_msgs/msg/String@ignition.msgs.StringMsg: a Gazebo message reaches ROS
    once, a ROS message reaches Gazebo once, and the bridge never bounces its own back."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    String = get_type("std_msgs/msg/String")
    labkit.ros2("run ros_gz_bridge parameter_bridge /chatter@std_msgs/msg/String@ignition.msgs.StringMsg")
    labkit.sleep(0.1)
    info = labkit.ros2("topic info /chatter").stdout
    assert "Publisher count: 1" in info and "Subscription count: 1" in info
    on_gz = []
    transport.TRANSPORT.subscribe("/chatter", "ignition.msgs.StringMsg", on_gz.append)
    gz_publish = transport.TRANSPORT.advertise("/chatter", "ignition.msgs.StringMsg")
    if not rclpy.ok():
        rclpy.init()
    node = rclpy.create_node("chatter_probe")
    on_ros = []
    node.create_subscription(String, "/chatter", lambda m: on_ros.append(m.data), 10)
    pub = node.create_publisher(String, "/chatter", 10)
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0.1)
    gz_publish({"data": "from gazebo"})
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=0.1)
    assert on_ros == ["from gazebo"]
    assert [m["data"] for m in on_gz] == ["from gazebo"]          # not bounced back
    pub.publish(String(data="from ros"))
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=0.1)
    assert [m["data"] for m in on_gz] == ["from gazebo", "from ros"]
    assert on_ros == ["from gazebo", "from ros"]                  # its own, once
    transport.TRANSPORT.unadvertise(gz_publish)
    node.destroy_node()


def test_ros_to_gz_bridge_of_odometry_subscribes_on_the_ros_side(gazebo, capsys):
    """Written the wrong way round for the simulator's odometry (']': ROS -> Gazebo),
    Humble's bridge still creates it: a ROS subscriber on the topic and a Gazebo
    publisher that forwards what ROS sends."""
    labkit.ros2("run ros_gz_bridge parameter_bridge /odom_in@nav_msgs/msg/Odometry]ignition.msgs.Odometry")
    assert ("[ros_gz_bridge]: Creating ROS->GZ Bridge: [/odom_in (nav_msgs/msg/Odometry) -> "
            "/odom_in (ignition.msgs.Odometry)] (Lazy 0)") in capsys.readouterr().err
    info = labkit.ros2("topic info /odom_in").stdout
    assert "Publisher count: 0" in info and "Subscription count: 1" in info
    got = []
    transport.TRANSPORT.subscribe("/odom_in", "ignition.msgs.Odometry", got.append)
    r = labkit.ros2("topic pub --once /odom_in nav_msgs/msg/Odometry "
                    "'{header: {frame_id: odom}, pose: {pose: {position: {x: 2.5}}}}'")
    assert r.returncode == 0
    labkit.sleep(0.5)
    assert got and got[-1]["pose"]["position"]["x"] == 2.5
    assert got[-1]["header"]["data"][0] == {"key": "frame_id", "value": ["odom"]}
