"""robot_state_publisher and joint_state_publisher as Humble's, in virtual time."""
import math
import os

import pytest

import labkit.rclpy as rclpy
from labkit import process, robots
from labkit.interfaces import get_type
from labkit.rclpy.qos import DurabilityPolicy, QoSProfile
from labkit.robots import facer

TFMessage = get_type("tf2_msgs/msg/TFMessage")
JointState = get_type("sensor_msgs/msg/JointState")
String = get_type("std_msgs/msg/String")
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
PAN = os.path.join(robots.share_directory("facer_description"), "urdf", "06-pan-joint.urdf")


class Listener:
    def __init__(self):
        rclpy.init()
        self.node = rclpy.create_node("tester")
        self.tf, self.tf_static, self.descriptions, self.joint_states = [], [], [], []
        self.node.create_subscription(TFMessage, "/tf", self.tf.append, 100)
        self.node.create_subscription(TFMessage, "/tf_static", self.tf_static.append, LATCHED)
        self.node.create_subscription(String, "/robot_description", self.descriptions.append,
                                      LATCHED)
        self.node.create_subscription(JointState, "/joint_states", self.joint_states.append, 10)

    def spin_for(self, seconds):
        clock = self.node.get_clock()
        end = clock.now().nanoseconds + int(seconds * 1e9)
        while clock.now().nanoseconds < end:
            rclpy.spin_once(self.node, timeout_sec=(end - clock.now().nanoseconds) / 1e9)


def by_child(messages):
    return {t.child_frame_id: t for m in messages for t in m.transforms}


def test_executables_are_registered():
    from labkit import executables, plugins
    plugins.register_all()
    for pair in [("robot_state_publisher", "robot_state_publisher"),
                 ("joint_state_publisher", "joint_state_publisher"),
                 ("joint_state_publisher_gui", "joint_state_publisher_gui"), ("xacro", "xacro")]:
        assert executables.lookup(*pair) is not None


def test_rsp_static_dynamic_and_description():
    with open(facer.model_path()) as handle:
        description = handle.read()
    rsp = facer.start_robot_state_publisher(description, echo=False)
    tester = Listener()
    tester.spin_for(0.1)
    assert [line.split("]: ")[1] for line in rsp.output] == [
        "got segment " + n for n in ["base_link", "camera_link", "caster_link", "head_link",
                                     "left_wheel", "mast_link", "right_wheel"]]
    static = by_child(tester.tf_static)
    assert sorted((t.header.frame_id, c) for c, t in static.items()) == [
        ("base_link", "caster_link"), ("head_link", "camera_link")]
    assert static["caster_link"].transform.translation.z == pytest.approx(-0.025)
    assert tester.descriptions[-1].data == description
    assert tester.tf == []                         # nothing moves before a JointState

    pub = tester.node.create_publisher(JointState, "joint_states", 10)
    msg = JointState(name=["head_pan", "mast_lift", "left_wheel_joint", "right_wheel_joint",
                           "unknown"], position=[math.pi / 2, 0.05, -0.25, 0.0, 1.0])
    msg.header.stamp = tester.node.get_clock().now().to_msg()
    pub.publish(msg)
    tester.spin_for(0.1)
    moving = by_child(tester.tf)
    assert sorted(moving) == ["head_link", "left_wheel", "mast_link", "right_wheel"]
    head = moving["head_link"]
    assert head.header.frame_id == "mast_link"
    assert head.header.stamp == msg.header.stamp
    assert (head.transform.rotation.z, head.transform.rotation.w) == pytest.approx(
        (math.sin(math.pi / 4), math.cos(math.pi / 4)))
    assert moving["mast_link"].transform.translation.z == pytest.approx(0.07 + 0.05)
    assert moving["left_wheel"].transform.rotation.y == pytest.approx(math.sin(-0.125))


def test_rsp_throttles_by_publish_frequency_and_checks_lengths():
    with open(facer.model_path()) as handle:
        rsp = facer.start_robot_state_publisher(handle.read(), echo=False)
    tester = Listener()
    pub = tester.node.create_publisher(JointState, "joint_states", 10)
    stamp = tester.node.get_clock().now().to_msg()
    for _ in range(3):                          # same stamp: within 1/20 s -> one publish
        msg = JointState(name=["head_pan"], position=[0.5])
        msg.header.stamp = stamp
        pub.publish(msg)
        tester.spin_for(0.01)
    assert len(tester.tf) == 1
    pub.publish(JointState(name=["head_pan", "mast_lift"], position=[0.5]))
    tester.spin_for(0.01)
    pub.publish(JointState(name=["head_pan"]))
    tester.spin_for(0.01)
    assert len(tester.tf) == 1
    text = "\n".join(rsp.output)
    assert "Robot state publisher ignored an invalid JointState message" in text
    assert 'ignored a JointState message about joint(s) "head_pan"(,...) whose position' in text


def test_rsp_without_description_is_fatal():
    proc = process.start(["robot_state_publisher", "robot_state_publisher"], echo=False)
    labkit_sleep(0.1)
    text = "\n".join(proc.output)
    assert "[FATAL]" in text and "robot_description parameter must not be empty" in text
    assert proc.returncode not in (None, 0)


def test_rsp_with_malformed_description(tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='x'><link name='a'/><link name='b'/></robot>")
    proc = process.start(["robot_state_publisher", "robot_state_publisher", str(bad)], echo=False)
    labkit_sleep(0.1)
    text = "\n".join(proc.output)
    assert "Unable to initialize urdf::model from robot description" in text
    assert "root link" in text


def labkit_sleep(seconds):
    import labkit
    labkit.sleep(seconds)


def test_rsp_file_argument_and_jsp_pipeline():
    """joint_state_publisher reads /robot_description and drives robot_state_publisher."""
    process.start(["robot_state_publisher", "robot_state_publisher", PAN], echo=False)
    jsp = process.start(["joint_state_publisher", "joint_state_publisher"], echo=False)
    tester = Listener()
    tester.spin_for(0.35)
    assert "Waiting for robot_description" in jsp.output[0]
    assert len(tester.joint_states) in (3, 4)              # 10 Hz
    js = tester.joint_states[-1]
    assert list(js.name) == ["left_wheel_joint", "right_wheel_joint", "mast_lift", "head_pan"]
    assert list(js.position) == [0.0] * 4      # zero lies inside every range (mast: 0..0.08)
    assert sorted(by_child(tester.tf)) == ["head_link", "left_wheel", "mast_link", "right_wheel"]
    assert sorted(by_child(tester.tf_static)) == ["camera_link", "caster_link"]


def test_jsp_centres_limits_and_zeros_parameter(tmp_path):
    from labkit.robots.joint_state_publisher import free_joints_of
    text = ("<robot name='c'><link name='a'/><link name='b'/><link name='c'/>"
            "<joint name='lift' type='prismatic'><parent link='a'/><child link='b'/>"
            "<limit lower='0.2' upper='1.0' effort='1' velocity='1'/></joint>"
            "<joint name='spin' type='continuous'><parent link='b'/><child link='c'/></joint>"
            "</robot>")
    free, order, _ = free_joints_of(text)
    assert order == ["lift", "spin"]
    assert free["lift"]["position"] == pytest.approx(0.6)
    assert (free["spin"]["min"], free["spin"]["max"]) == (-math.pi, math.pi)
    free, _, _ = free_joints_of(text, {"lift": 0.3})
    assert free["lift"]["position"] == 0.3
    with pytest.raises(ValueError, match='Limits must be specified for joint "j"'):
        free_joints_of("<robot name='x'><joint name='j' type='revolute'/></robot>")


def test_gui_sliders_move_the_joints():
    pytest.importorskip("ipywidgets")
    from labkit.robots import sliders
    process.start(["robot_state_publisher", "robot_state_publisher", PAN], echo=False)
    process.start(["joint_state_publisher_gui", "joint_state_publisher_gui"], echo=False)
    tester = Listener()
    tester.spin_for(0.15)
    panel = sliders.panel()
    assert sorted(panel.sliders) == sorted(tester.joint_states[-1].name)
    panel.sliders["head_pan"].value = 1.0
    tester.spin_for(0.15)
    js = tester.joint_states[-1]
    assert dict(zip(js.name, js.position))["head_pan"] == pytest.approx(1.0)
    head = by_child(tester.tf)["head_link"]
    assert head.transform.rotation.z == pytest.approx(math.sin(0.5))


def test_rsp_parameters_and_new_description():
    with open(facer.model_path("01-one-shape.urdf")) as handle:
        facer.start_robot_state_publisher(handle.read(), echo=False)
    import labkit
    names = labkit.ros2("param list /robot_state_publisher").stdout.split()
    assert {"frame_prefix", "ignore_timestamp", "publish_frequency", "robot_description",
            "use_sim_time", "qos_overrides./tf.publisher.depth",
            "qos_overrides./joint_states.subscription.reliability"} <= set(names)
    result = labkit.ros2("param set /robot_state_publisher publish_frequency 2000.0")
    assert "publish_frequency must be between 0.0 and 1000.0" in result.stdout + result.stderr
    tester = Listener()
    tester.spin_for(0.05)
    tester.tf_static.clear()
    from labkit.robots.urdf import load
    flexible = open(PAN).read()
    SetParameters = get_type("rcl_interfaces/srv/SetParameters")
    Parameter = get_type("rcl_interfaces/msg/Parameter")
    ParameterValue = get_type("rcl_interfaces/msg/ParameterValue")
    client = tester.node.create_client(SetParameters, "/robot_state_publisher/set_parameters")
    assert client.wait_for_service(timeout_sec=1.0)
    future = client.call_async(SetParameters.Request(parameters=[Parameter(
        name="robot_description", value=ParameterValue(type=4, string_value=flexible))]))
    rclpy.spin_until_future_complete(tester.node, future, timeout_sec=1.0)
    assert future.result().results[0].successful
    tester.spin_for(0.1)
    assert len(by_child(tester.tf_static)) == len(load(flexible).fixed_joints())
    assert tester.descriptions[-1].data == flexible


def test_jsp_source_list_and_zeros_parameters():
    process.start(["robot_state_publisher", "robot_state_publisher", PAN], echo=False)
    process.start(["joint_state_publisher", "joint_state_publisher", "--ros-args",
                   "-p", "source_list:=[walker]", "-p", "zeros.head_pan:=0.5"], echo=False)
    tester = Listener()
    tester.spin_for(0.15)
    first = dict(zip(tester.joint_states[-1].name, tester.joint_states[-1].position))
    assert first == {"left_wheel_joint": 0.0, "right_wheel_joint": 0.0, "mast_lift": 0.0,
                     "head_pan": 0.5}
    pub = tester.node.create_publisher(JointState, "walker", 10)
    pub.publish(JointState(name=["mast_lift", "nothing"], position=[0.03, 9.0]))
    tester.spin_for(0.15)
    last = dict(zip(tester.joint_states[-1].name, tester.joint_states[-1].position))
    assert last == {"left_wheel_joint": 0.0, "right_wheel_joint": 0.0, "mast_lift": 0.03,
                    "head_pan": 0.5}
