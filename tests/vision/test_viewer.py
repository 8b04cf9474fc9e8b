"""ImageViewer: an image topic as a picture (static PNG) and a live widget."""
import cv2
import numpy as np

import labkit
from labkit.vision import SAMPLE_CLIP
from labkit.vision.viewer import ImageViewer


def test_viewer_shows_the_newest_frame(virtual):
    from facer_input import capture_image
    viewer = ImageViewer('frame_image')
    before = bytes(viewer.snapshot())
    assert before.startswith(b'\x89PNG')  # a 'waiting' picture before any frame
    assert viewer.frame is None
    widget = viewer.widget
    labkit.process.start(name='capture_image', main=capture_image.main, echo=False,
                         args=['capture_image', '--ros-args', '-p', f'source:={SAMPLE_CLIP}'])
    labkit.sleep(0.35)
    assert viewer.frames_received == 3
    cap = cv2.VideoCapture(SAMPLE_CLIP)
    frames = [cap.read()[1] for _ in range(3)]
    cap.release()
    np.testing.assert_array_equal(viewer.frame, frames[2])
    png = cv2.imdecode(np.frombuffer(viewer.snapshot(), np.uint8), cv2.IMREAD_COLOR)
    np.testing.assert_array_equal(png, frames[2])
    assert widget.format == 'jpeg' and bytes(widget.value[:2]) == b'\xff\xd8'
    out = labkit.ros2('node list').stdout.split()
    assert '/image_viewer' in out and '/capture_image' in out
    viewer.close()
    assert '/image_viewer' not in labkit.ros2('node list').stdout.split()


def test_viewer_shows_depth_images_as_grey(virtual, hook):
    import rclpy
    from cv_bridge import CvBridge
    from sensor_msgs.msg import Image
    viewer = ImageViewer('depth')
    rclpy.init(args=[])
    node = rclpy.create_node('depth_camera')
    pub = node.create_publisher(Image, 'depth', 10)
    depth = np.linspace(0.5, 4.0, 12, dtype=np.float32).reshape(3, 4)
    pub.publish(CvBridge().cv2_to_imgmsg(depth, '32FC1'))
    labkit.sleep(0.1)
    assert viewer.frame.shape == (3, 4, 3)
    assert viewer.frame[0, 0, 0] == 0 and viewer.frame[2, 3, 0] == 255
    node.destroy_node()
    rclpy.shutdown()
    viewer.close()


def test_frame_log_counts_frames_per_second(virtual):
    from labkit.vision.viewer import FrameLog
    from test_facer_nodes import _camera
    _camera(timer_period=0.25)
    log = FrameLog('frame_image')
    labkit.sleep(3.0)
    assert labkit.ros2('node list').stdout.split() == ['/capture_image', '/frame_log']
    assert log.count() in (11, 12, 13)
    assert [n for _, n in log.rates()[1:3]] == [4, 4]     # whole seconds at 4 Hz
    assert log.count(1, 2) == 4
    log.close()
    assert labkit.ros2('node list').stdout.split() == ['/capture_image']


def test_frame_rate_chart_fits_the_column_with_legible_labels():
    import re
    from labkit.vision.rate_chart import frame_rate_svg
    svg = frame_rate_svg([(t, 10 if t < 4 else 2) for t in range(8)], [(0, '0.1 秒'), (4, '0.5 秒')])
    assert 'width="720"' in svg
    sizes = [int(s) for s in re.findall(r'font-size="(\d+)"', svg)]
    assert sizes and min(sizes) >= 12
    assert 'timer_period = 0.1 秒' in svg and 'timer_period = 0.5 秒' in svg
    assert svg.count('fill="#4a78b0"') == 8          # one bar a second
