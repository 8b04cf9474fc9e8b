"""`ros2 topic hz` measures when messages arrive, not when its callback got to them:
messages that queued while the callback was busy are not a burst (`min: 0.000s`)."""
import labkit


def test_queued_messages_keep_their_real_intervals():
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    String = get_type("std_msgs/msg/String")
    rclpy.init()
    node = rclpy.create_node("talker")
    pub = node.create_publisher(String, "/t", 10)
    sent = []

    def tick():
        msg = String()
        msg.data = "slow" if not sent else "x"     # the first one keeps hz busy 0.35 s
        sent.append(msg.data)
        pub.publish(msg)
    node.create_timer(0.1, tick)
    job = labkit.ros2("topic hz /t --filter "
                      "\"m.data != 'slow' or __import__('time').sleep(0.35) or True\"")
    end = node.get_clock().now().nanoseconds + 3_000_000_000
    while node.get_clock().now().nanoseconds < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    mins = [line for line in job.output if line.startswith("\tmin: ")]
    assert mins, job.output
    assert all(line.startswith("\tmin: 0.100s max: 0.100s") for line in mins), mins
    assert job.output[0].startswith("average rate: 10.0")
    job.stop()
    node.destroy_node()
    rclpy.shutdown()
