"""The exercise checks that watch traffic: log lines on /rosout, messages, the turtle's pose."""
import labkit
from labkit import exercises, process
from labkit.exercises import Checker


def ticker_main(period, text):
    def main(args=None):
        import labkit.rclpy as rclpy
        rclpy.init(args=args)
        node = rclpy.create_node("ticker")
        node.create_timer(period, lambda: node.get_logger().info(text))
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
            rclpy.try_shutdown()
    return main


def test_logs_counts_only_that_nodes_lines_during_the_window(capsys):
    ticker = process.start(main=ticker_main(0.5, "tick"), name="ticker")
    labkit.sleep(0.1)
    lines = exercises.logs("/ticker", 2.0)
    assert 3 <= len(lines) <= 5 and all(m.msg == "tick" for m in lines)
    assert exercises.logs("/someone_else", 1.0) == []
    c = Checker("t")
    assert len(c.logs("/ticker", 1.0, at_least=2, contains="tick")) >= 2
    assert not c.logs("/ticker", 1.0, contains="tock")
    assert [ok for ok, _ in c.results] == [True, False]
    ticker.stop()


def test_turtle_pose_reads_the_live_turtle_and_none_without_one():
    assert exercises.turtle_pose() is None
    job = labkit.ros2("run turtlesim turtlesim_node")
    labkit.sleep(0.2)
    labkit.ros2("service call /turtle1/teleport_absolute turtlesim/srv/TeleportAbsolute "
                "'{x: 2.0, y: 9.0, theta: 0.5}'")
    labkit.sleep(0.1)
    pose = exercises.turtle_pose()
    assert abs(pose["x"] - 2.0) < 1e-4 and abs(pose["y"] - 9.0) < 1e-4 and abs(pose["theta"] - 0.5) < 1e-4
    job.stop()
