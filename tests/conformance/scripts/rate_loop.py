"""Conformance: the URDF tutorial's state_publisher loop: a node that calls
rclpy.spin_once(self) and loop_rate.sleep() in its own while loop (no other thread),
plus rclpy.time / rclpy.duration spellings used by the tf2 tutorials.

Plain rclpy: runs unchanged on ROS 2 Humble.
"""
from math import cos, sin

import rclpy
import rclpy.duration
import rclpy.time
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from rclpy.qos import QoSProfile
from sensor_msgs.msg import JointState


class StatePublisher(Node):

    def __init__(self):
        super().__init__('state_publisher')
        qos_profile = QoSProfile(depth=10)
        self.joint_pub = self.create_publisher(JointState, 'joint_states', qos_profile)

    def run(self, iterations):
        loop_rate = self.create_rate(30)
        joint_state = JointState()
        odom_trans = TransformStamped()
        odom_trans.header.frame_id = 'odom'
        odom_trans.child_frame_id = 'axis'
        angle = 0.0
        start = self.get_clock().now()
        for i in range(iterations):
            rclpy.spin_once(self)
            now = self.get_clock().now()
            joint_state.header.stamp = now.to_msg()
            joint_state.name = ['swivel', 'tilt', 'periscope']
            joint_state.position = [float(i), 0.0, 0.0]
            odom_trans.header.stamp = now.to_msg()
            odom_trans.transform.translation.x = cos(angle) * 2
            odom_trans.transform.translation.y = sin(angle) * 2
            self.joint_pub.publish(joint_state)
            angle += 0.01
            loop_rate.sleep()
        return (self.get_clock().now() - start).nanoseconds / 1e9


def main():
    rclpy.init(args=[])
    node = StatePublisher()
    # another node keeps what was published (queue of 10); spinning a subscription in
    # the loop's own node would take spin_once's turn from the rate's timer and hang
    listener = rclpy.create_node('listener')
    received = []
    listener.create_subscription(JointState, 'joint_states',
                                 lambda m: received.append(m.position[0]), 10)
    for _ in range(100):
        if node.joint_pub.get_subscription_count():
            break
        rclpy.spin_once(listener, timeout_sec=0.05)
    elapsed = node.run(10)
    # 10 loops at 30 Hz: about a third of a second of ROS time
    print('loops done; elapsed within [0.25 s, 2 s]:', 0.25 <= elapsed < 2.0)
    for _ in range(40):
        if len(received) >= 10:
            break
        rclpy.spin_once(listener, timeout_sec=0.05)
    print('listener received:', received)
    listener.destroy_node()

    # spellings from the tf2 tutorials
    when = node.get_clock().now() - rclpy.time.Duration(seconds=5.0)
    print('rclpy.time.Duration is rclpy.duration.Duration:',
          rclpy.time.Duration is rclpy.duration.Duration)
    print('now - 5 s is a Time:', type(when).__name__, when.clock_type.name)
    print('rclpy.time.Time():', repr(rclpy.time.Time()))
    print('timeout:', repr(rclpy.duration.Duration(seconds=0.05)))
    seconds, nanoseconds = rclpy.time.Time(seconds=12, nanoseconds=5).seconds_nanoseconds()
    print('seconds_nanoseconds:', seconds, nanoseconds)
    node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
