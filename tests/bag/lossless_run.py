"""One recording for tests/bag/test_lossless.py, run as its own program (live or virtual time).

    python lossless_run.py STORAGE KIND COUNT RATE_HZ [BUSY]

A publisher process (its own labkit process, like `ros2 run`) waits until the
recorder has subscribed, then publishes COUNT messages at RATE_HZ (KIND `small`:
std_msgs/String 'n'; `image`: 640x480 rgb8 sensor_msgs/Image, frame_id 'n').
`ros2 bag record` records them; the program prints one JSON line: what was
published, and the recorder's warning lines. BUSY=1: meanwhile the notebook computes
(a thread that never waits), as a learner's cell may.
"""
import json
import sys
import threading

import labkit
from labkit import compat, plugins, process


def publisher(kind, count, rate):
    def main(args=None):
        import rclpy
        from sensor_msgs.msg import Image
        from std_msgs.msg import String
        rclpy.init(args=args)
        node = rclpy.create_node('lossless_publisher')
        if kind == 'image':
            pub = node.create_publisher(Image, '/data', 10)
            msg = Image(height=480, width=640, encoding='rgb8', step=640 * 3)
            msg.data = bytes(640 * 480 * 3)
        else:
            pub = node.create_publisher(String, '/data', 10)
            msg = String()
        sent = [0]

        def tick():
            if pub.get_subscription_count() == 0:      # the recorder has not found us yet
                return
            if sent[0] == count:
                raise SystemExit(0)
            if kind == 'image':
                msg.header.frame_id = str(sent[0])
            else:
                msg.data = str(sent[0])
            pub.publish(msg)
            sent[0] += 1

        node.create_timer(1.0 / rate, tick)
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
            rclpy.try_shutdown()
        return 0
    return main


def run(storage, kind, count, rate, busy=False):
    plugins.register_all()
    compat.activate(quiet=True)
    done = []
    if busy:
        def compute():
            total = 0
            while not done:
                total += 1
        threading.Thread(target=compute, daemon=True).start()
    rec = labkit.ros2(f'bag record -s {storage} -o lossless /data')
    pub = process.start(name='lossless_publisher', main=publisher(kind, count, rate))
    pub.wait(600)
    labkit.sleep(1.0)          # the recorder takes what is still queued
    rec.stop()
    done.append(True)
    warnings = [line.split(']: ', 1)[-1] for line in rec.output if line.startswith('[WARN]')]
    print(json.dumps({'published': count, 'publisher_rc': pub.returncode, 'warnings': warnings,
                      'lines': rec.output}))
    process.reset_all()


if __name__ == '__main__':
    storage, kind, count, rate = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
    run(storage, kind, count, rate, sys.argv[5:] == ['1'])
