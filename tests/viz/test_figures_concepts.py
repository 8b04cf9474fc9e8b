"""The concept pictures (ch01, 07, 11, 12, 13, 16, 17, 19, 25, connect_real_ros): each is
drawn from what labkit really has at that moment, and legible at the 720 px column."""
import html
import os
import re
import sys

import pytest

import labkit
from labkit import ament
from labkit.viz import figures_concepts as fig


def _legible(svg):
    s = str(svg)
    assert re.search(r'<svg[^>]* width="720"', s)
    fonts = [float(x) for x in re.findall(r'font-size="([\d.]+)"', s)]
    assert fonts and min(fonts) >= 12
    for x in re.findall(r'<text x="([\d.-]+)"', s):
        assert 0 <= float(x) <= 720
    return s


sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "workspace"))
from conftest_ws import clean_env  # noqa: E402,F401  (what `source` changes is put back)


@pytest.fixture
def home(tmp_path, clean_env):
    from labkit.ament import source
    labkit.reset()
    sourced = list(source._sourced)
    ament.use_home(str(tmp_path / "home"))
    yield
    labkit.reset()
    ament.leave_home()
    source._sourced[:] = sourced


@pytest.fixture
def rclpy():
    import labkit.compat
    labkit.compat.activate(quiet=True)
    import rclpy as real_name
    real_name.init()
    yield real_name
    labkit.reset()


def test_installed_layout_counts_what_the_underlay_has():
    from labkit import executables
    from labkit.ament import index
    s = _legible(fig.installed_layout())
    assert f"{len(index.bundled_package_names())} 个功能包" in s
    assert f"{len(executables.executables())} 个可执行文件" in s
    assert "/opt/ros/humble/setup.bash" in s


def test_parameter_services_are_read_from_the_graph(rclpy):
    rclpy.create_node("with_params")
    rclpy.create_node("without_params", start_parameter_services=False)
    s = _legible(fig.parameter_services("/with_params"))
    assert "/with_params/set_parameters_atomically" in s and "没有找到" not in s
    s = _legible(fig.parameter_services("without_params"))
    assert s.count("没有找到") == 6


def test_workspace_layout_follows_the_disk(home):
    ament.mkdir("~/ws/src")
    before = _legible(fig.workspace_layout("~/ws"))
    assert before.count("还没有：第一次 colcon build 时出现") == 3
    ament.cd("~/ws/src")
    assert labkit.ros2("pkg create --build-type ament_python tiny_pkg").returncode == 0
    ament.cd("~/ws")
    assert labkit.colcon("build").returncode == 0
    after = _legible(fig.workspace_layout("~/ws"))
    assert "还没有" not in after
    assert "tiny_pkg/" in after            # src/ and install/ list the package
    assert "/root/ws/" in after            # the simulated home, as the book prints it


def test_rosidl_outputs_name_the_generated_files(home):
    ament.mkdir("~/ws/src/my_ifaces/srv", "~/ws/src/my_ifaces/action", "~/ws/src/my_ifaces/msg")
    for rel, text in (("srv/FaceResult.srv", "bool a\n---\nstring b\n"),
                      ("action/CameraState.action", "bool s\n---\nstring f\n---\nstring x\n"),
                      ("msg/IMUData.msg", "float64 x\n")):
        with open(ament.files.expand("~/ws/src/my_ifaces/" + rel), "w", encoding="utf-8") as f:
            f.write(text)
    s = _legible(fig.rosidl_outputs("~/ws/src/my_ifaces"))
    assert "my_ifaces/srv/_face_result.py" in s
    assert "include/my_ifaces/my_ifaces/action/camera_state.hpp" in s
    assert "my_ifaces/msg/_imu_data.py" in s          # rosidl's snake case of IMUData
    assert "FaceResult_Request" in s and "CameraState_Goal" in s
    assert fig._snake("FaceResult") == "face_result"
    assert fig._snake("IMUData") == "imu_data"


def test_node_anatomy_shows_the_nodes_own_callbacks(rclpy):
    from std_msgs.msg import String
    node = rclpy.create_node("anatomy")
    node.create_timer(0.25, lambda: None)
    node.create_subscription(String, "heard", lambda m: None, 10)
    node.create_publisher(String, "said", 10)
    s = _legible(fig.node_anatomy(node))
    assert "定时器 每 0.25 秒" in s and "订阅 /heard" in s and "/said" in s
    assert _legible(fig.node_anatomy("/anatomy")) == s      # found by name too
    with pytest.raises(LookupError):
        fig.node_anatomy("/nobody")


def test_package_lookup_first_prefix_wins(home):
    s = _legible(fig.package_lookup("turtlesim"))
    assert "/opt/ros/humble" in s and "用这里的" in s
    s = _legible(fig.package_lookup("no_such_package"))
    assert "Package 'no_such_package' not found" in html.unescape(s)
    # a workspace package of the same name as an underlay one hides it
    ament.mkdir("~/ws/src")
    ament.cd("~/ws/src")
    assert labkit.ros2("pkg create --build-type ament_python turtlesim").returncode == 0
    ament.cd("~/ws")
    labkit.colcon("build")
    labkit.source("install/setup.bash")
    s = _legible(fig.package_lookup("turtlesim"))
    rows = re.findall(r">(/[^<]+)</text><text[^>]*>([^<]+)</text>", s)
    assert rows[0][0] == "/root/ws/install/turtlesim" and "用这里的" in rows[0][1]
    assert rows[-1][0] == "/opt/ros/humble" and "被上面的遮住" in rows[-1][1]


def test_rosdep_resolution_maps_keys_to_packages(home):
    ament.mkdir("~/ws/src")
    ament.cd("~/ws/src")
    r = labkit.ros2("pkg create deps_pkg --build-type ament_python --dependencies rclpy "
                    "python3-numpy no_such_key_xyz")
    assert r.returncode == 0
    s = _legible(fig.rosdep_resolution("~/ws/src"))
    assert "apt: ros-humble-rclpy" in s
    assert "apt: python3-numpy" in s
    assert "找不到规则" in s                  # no_such_key_xyz


def test_doctor_checks_run_on_the_live_graph(rclpy):
    from std_msgs.msg import String
    s = _legible(fig.doctor_checks())
    assert "All 5 checks passed" in s
    node = rclpy.create_node("lonely")
    node.create_publisher(String, "nobody_listens", 10)
    s = _legible(fig.doctor_checks())
    row = re.search(r"TopicCheck</text>.*?>(通过|有警告|失败)</text>", s).group(1)
    assert row == "有警告"


def test_colcon_test_flow_lists_the_packages_tests(home):
    ament.mkdir("~/ws/src")
    ament.cd("~/ws/src")
    assert labkit.ros2("pkg create --build-type ament_python tested_pkg").returncode == 0
    s = _legible(fig.colcon_test_flow("~/ws"))
    assert "tested_pkg" in s and "test_flake8.py" in s and "build/tested_pkg/pytest.xml" in s


def test_dds_ports_follow_the_rtps_formula():
    assert fig.dds_ports(0) == {"discovery multicast": 7400, "discovery unicast": 7410,
                                "user multicast": 7401, "user unicast": 7411}
    assert fig.dds_ports(1, participant_id=2)["discovery unicast"] == 7664
    s = _legible(fig.dds_discovery(domain_id=5))
    assert "ROS_DOMAIN_ID=5" in s and "UDP 8650" in s and "收不到" in s
    assert "收不到" not in _legible(fig.dds_discovery(domain_id=5, localhost_only=False))


def test_drawing_leaves_no_node_behind(rclpy):
    """The probes are hidden nodes of their own, gone when the picture is drawn: a later
    `ros2 doctor --report` must not list them as publishers of /parameter_events."""
    from labkit.graph.registry import GRAPH
    rclpy.create_node("someone")
    before = sorted(n.fqn for n in GRAPH.nodes)
    fig.doctor_checks()
    fig.parameter_services("/someone")
    assert sorted(n.fqn for n in GRAPH.nodes) == before
