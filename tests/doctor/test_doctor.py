"""ros2 doctor: ros2doctor's checks, report sections and output shape, on labkit."""
import platform
import re

import labkit
from labkit.doctor.api import Report, format_report


def _turtlesim_with_publisher():
    labkit.ros2("run turtlesim turtlesim_node")
    labkit.ros2("topic pub -r 1 /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'")
    labkit.sleep(0.5)


def test_empty_graph_all_checks_pass():
    result = labkit.ros2("doctor")
    assert result.returncode == 0
    assert result.stdout == "\nAll 5 checks passed\n\n"
    assert result.stderr == ""


def test_topic_warnings_do_not_fail_without_include_warnings():
    _turtlesim_with_publisher()
    result = labkit.ros2("doctor")
    warnings = result.stderr.splitlines()
    # the file and line of Humble's ros2doctor that prints this warning, as on a real install
    assert "/opt/ros/humble/lib/python3.10/site-packages/ros2doctor/api/topic.py: 42: " \
        "UserWarning: Publisher without subscriber detected on /turtle1/pose." in warnings
    assert not any("/turtle1/cmd_vel" in w for w in warnings)   # turtlesim subscribes to it
    assert result.stdout == "\nAll 5 checks passed\n\n"


def test_subscriber_without_publisher_and_include_warnings():
    labkit.ros2("run turtlesim turtlesim_node")
    result = labkit.ros2("doctor --include-warnings")
    assert "UserWarning: Subscriber without publisher detected on /turtle1/cmd_vel." \
        in result.stderr
    assert result.stdout == "\n1/5 check(s) failed\n\nFailed modules: topic\n"
    failed = labkit.ros2("wtf -iw -rf")
    assert failed.stdout.startswith("\n1/5 check(s) failed\n\nFailed modules: topic\n\n"
                                    "   TOPIC LIST\n")
    assert "   PLATFORM INFORMATION" not in failed.stdout


def test_qos_incompatibility_is_an_error():
    from labkit import rclpy
    from labkit.interfaces import get_type
    from labkit.rclpy.qos import QoSProfile, ReliabilityPolicy
    String = get_type("std_msgs/msg/String")
    rclpy.init()
    node = rclpy.create_node("qos_demo")
    node.create_publisher(String, "chatter",
                          QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
    node.create_subscription(String, "chatter", lambda m: None, QoSProfile(depth=10))
    result = labkit.ros2("doctor")
    assert "UserWarning: ERROR: QoS compatibility error found on topic '/chatter': " \
        "Best effort publisher and reliable subscription;" in result.stderr
    assert "Failed modules: middleware" in result.stdout
    report = labkit.ros2("doctor --report").stdout
    section = report.split("   QOS COMPATIBILITY LIST\n")[1].split("\n\n")[0].splitlines()
    assert section == [
        "topic [type]            : /chatter [std_msgs/msg/String]",
        "publisher node          : qos_demo",
        "subscriber node         : qos_demo",
        "compatibility status    : ERROR: Best effort publisher and reliable subscription;"]


def test_report_sections_order_and_alignment():
    _turtlesim_with_publisher()
    out = labkit.ros2("doctor --report").stdout
    names = re.findall(r"^   ([A-Z0-9 ]+)$", out, re.M)
    assert names == ["NETWORK CONFIGURATION", "PACKAGE VERSIONS", "PLATFORM INFORMATION",
                     "QOS COMPATIBILITY LIST", "RMW MIDDLEWARE", "ROS 2 INFORMATION",
                     "TOPIC LIST"]
    assert "\n   RMW MIDDLEWARE\nmiddleware name    : labkit in-process graph\n" in out
    assert "device       : loopback only\n" in out
    assert f"system           : {platform.system()}\n" in out
    assert f"platform info    : {platform.platform()}\n" in out
    assert "distribution name      : humble\n" in out
    topics = out.split("   TOPIC LIST\n")[1].splitlines()
    assert topics[:3] == ["topic               : /turtle1/cmd_vel",
                          "publisher count     : 1",
                          "subscriber count    : 1"]
    assert "topic               : /rosout" not in out
    assert re.search(r"^labkit +: local=\d", out, re.M)
    assert re.search(r"^numpy +: local=\d[^,]*, required: >=1\.26$", out, re.M)


def test_empty_topic_list_report():
    out = labkit.ros2("doctor -r").stdout
    assert out.endswith("   TOPIC LIST\ntopic               : none\n"
                        "publisher count     : 0\nsubscriber count    : 0\n")
    assert "compatibility status    : No publisher/subscriber pairs found" in out


def test_format_report_padding_rule():
    short = Report("X")
    short.add_to_report("a", 1)
    assert format_report(short) == ["", "   X", "a       : 1"]
    long = Report("Y")
    long.add_to_report("eightchr", "v")
    assert format_report(long)[2] == "eightchr    : v"


def test_domain_id_is_not_a_doctor_check(monkeypatch, capsys):
    # Humble's ros2doctor never looks at ROS_DOMAIN_ID (its network check reads interfaces)
    monkeypatch.setenv("ROS_DOMAIN_ID", "101")
    result = labkit.ros2("doctor")
    assert result.stderr == "" and result.stdout == "\nAll 5 checks passed\n\n"
    # but its own node needs a participant: on a domain Fast DDS cannot map to ports
    # (> 232) Fast DDS prints its line and ends the process with status 1, checks unrun
    capsys.readouterr()
    monkeypatch.setenv("ROS_DOMAIN_ID", "999")
    result = labkit.ros2("doctor")
    assert result.returncode == 1 and "checks passed" not in result.stdout
    assert "Calculated port number is too high" in capsys.readouterr().out


API = "/opt/ros/humble/lib/python3.10/site-packages/ros2doctor/api"


def test_ros_distro_unset_fails_package_and_platform_as_humble(monkeypatch):
    monkeypatch.setenv("ROS_DISTRO", "")
    result = labkit.ros2("doctor")
    assert result.stderr.splitlines() == [
        f"{API}/package.py: 40: UserWarning: ERROR: ROS_DISTRO is not set.",
        f"{API}/package.py: 150: UserWarning: ERROR: distro packages info is not found.",
        f"{API}/platform.py: 37: UserWarning: ERROR: ROS_DISTRO is not set.",
        f"{API}/platform.py: 69: UserWarning: ERROR: Missing rosdistro info. "
        "Unable to check platform."]
    assert result.stdout == "\n2/5 check(s) failed\n\nFailed modules: package platform\n"
    report = labkit.ros2("doctor --report").stdout
    assert "   ROS 2 INFORMATION\n\n" in report        # printed empty, as Humble does
    assert "   PACKAGE VERSIONS\n\n" in report


def test_misspelt_distro_is_not_found(monkeypatch):
    monkeypatch.setenv("ROS_DISTRO", "humbel")
    result = labkit.ros2("doctor")
    assert f"{API}/platform.py: 49: UserWarning: Distribution name humbel is not found" \
        in result.stderr.splitlines()
    assert "Failed modules: package platform" in result.stdout


def test_unset_variable_means_the_sourced_underlay(monkeypatch):
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    assert labkit.ros2("doctor").stdout == "\nAll 5 checks passed\n\n"


def test_other_distro_is_a_platform_warning(monkeypatch):
    monkeypatch.setenv("ROS_DISTRO", "jazzy")
    result = labkit.ros2("doctor --include-warnings")
    assert "UserWarning: ROS_DISTRO is jazzy, but labkit emulates humble." in result.stderr
    assert "Failed modules: platform" in result.stdout


def test_doctor_listed_in_ros2_help():
    help_text = labkit.ros2("--help").stdout
    assert re.search(r"^  doctor +Check ROS setup and other potential issues$", help_text, re.M)
    assert re.search(r"^  wtf +Use `wtf` as alias to `doctor`$", help_text, re.M)
    assert "  --include-warnings, -iw" in labkit.ros2("doctor -h").stdout


def test_package_check_compares_installed_versions_with_requirements(monkeypatch):
    from labkit.doctor import package
    real = package.local_version
    monkeypatch.setattr(package, "local_version",
                        lambda name: "1.0" if name == "numpy" else
                        None if name == "xacro" else real(name))
    result = labkit.ros2("doctor")
    assert "UserWarning: numpy does not meet labkit's requirement. local: 1.0, " \
        "required: >=1.26" in result.stderr
    assert "UserWarning: ERROR: xacro is not installed (labkit needs xacro>=2)." in result.stderr
    assert "Failed modules: package" in result.stdout
    report = labkit.ros2("doctor -r").stdout
    assert re.search(r"^xacro +: local=not installed, required: >=2$", report, re.M)
