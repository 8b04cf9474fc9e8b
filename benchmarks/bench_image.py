"""Camera-frame latency: a 640x480 bgr8 sensor_msgs/Image, publish -> callback, one
process, one SingleThreadedExecutor. Prints median and p95 in microseconds on labkit and,
when the reference venv exists, on real rclpy (target: labkit median < 100 us).

    python benchmarks/bench_image.py
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

FRAMES = 300


def worker():
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from sensor_msgs.msg import Image

    rclpy.init(args=[])
    node = rclpy.create_node('bench_image')
    latencies = []
    sent_at = [0.0]

    def on_image(msg):
        latencies.append(time.perf_counter() - sent_at[0])
        assert len(msg.data) == 640 * 480 * 3

    pub = node.create_publisher(Image, 'image_raw', 10)
    node.create_subscription(Image, 'image_raw', on_image, 10)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    for _ in range(200):  # real DDS needs a moment to match
        if pub.get_subscription_count():
            break
        executor.spin_once(timeout_sec=0.05)
    frame = Image(height=480, width=640, encoding='bgr8', step=640 * 3,
                  data=bytes(range(256)) * (640 * 480 * 3 // 256))
    frame.header.frame_id = 'camera'
    for i in range(FRAMES + 20):
        if i == 20:
            latencies.clear()  # the first frames warm caches up
        before = len(latencies)
        sent_at[0] = time.perf_counter()
        pub.publish(frame)
        while len(latencies) == before:
            executor.spin_once(timeout_sec=1.0)
    executor.shutdown()
    node.destroy_node()
    rclpy.shutdown()
    from _common import emit, percentile
    us = [x * 1e6 for x in latencies]
    emit({'median_us': percentile(us, 0.5), 'p95_us': percentile(us, 0.95), 'frames': len(us)})


def main():
    from _common import run_labkit, run_reference
    rows = [('labkit (live time)', run_labkit(__file__, 'live')),
            ('labkit (virtual time)', run_labkit(__file__, 'virtual')),
            ('real rclpy (Jazzy)', run_reference(__file__))]
    for label, f in rows:
        if f is None:
            print(f'{label}: reference venv not found (set ROSREF_PYTHON)')
            continue
        print(f"{label:<22} 640x480 bgr8: median {f['median_us']:>8.1f} us, "
              f"p95 {f['p95_us']:>8.1f} us ({f['frames']} frames)")
    print('target: labkit median < 100 us')


if __name__ == '__main__':
    worker() if '--worker' in sys.argv else main()
