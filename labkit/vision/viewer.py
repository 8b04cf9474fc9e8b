"""ImageViewer: show a sensor_msgs/Image topic in a notebook (what rqt_image_view does).

    viewer = ImageViewer('face_image')   # starts a small subscriber process
    viewer                               # live widget in JupyterLab, a PNG in the book
    viewer.frame                         # the newest frame as a BGR numpy array

The subscriber is an ordinary rclpy node (`/image_viewer`) in its own labkit
process, so it shows up in `ros2 node list` like the real tool would.
"""
import threading
import time

import cv2
import numpy as np

from labkit.viz.canvas import PNG


class ImageViewer:
    """The newest image on `topic`, as a live widget and as a static picture."""

    def __init__(self, topic='image_raw', fps=10.0, node_name='image_viewer'):
        self.topic = topic
        self.fps = fps
        self.node_name = node_name
        self.frame = None            # newest frame, BGR (what cv2.imshow would show)
        self.frames_received = 0
        self._widget = None
        self._last_push = 0.0
        self._lock = threading.Lock()
        from labkit import process
        self.process = process.start(name=node_name, main=self._main, args=[node_name], echo=False)

    # -- the subscriber process -----------------------------------------------------------
    def _main(self, args=None):
        from labkit.vision.cv_bridge import CvBridge, CvBridgeError

        bridge = CvBridge()

        def on_image(msg):
            try:
                frame = bridge.imgmsg_to_cv2(msg, 'bgr8')
            except CvBridgeError as e:  # e.g. a 32FC1 depth image: show it scaled to grey
                frame = _grey_for_display(bridge.imgmsg_to_cv2(msg), e)
            with self._lock:
                self.frame = frame
                self.frames_received += 1
            self._push()

        _spin_image_subscriber(args, self.node_name, self.topic, lambda node: on_image)

    # -- static face ----------------------------------------------------------------------
    def snapshot(self):
        """The newest frame as PNG bytes (a grey 'no image' picture before the first one)."""
        with self._lock:
            frame = self.frame
        if frame is None:
            frame = np.full((240, 320, 3), 64, np.uint8)
            cv2.putText(frame, 'waiting for ' + self.topic, (10, 125),
                        cv2.FONT_HERSHEY_SIMPLEX, 0.6, (220, 220, 220), 1, cv2.LINE_AA)
        return PNG(cv2.imencode('.png', frame)[1].tobytes())

    def _repr_png_(self):
        return bytes(self.snapshot())

    # -- live face ------------------------------------------------------------------------
    @property
    def widget(self):
        if self._widget is None:
            from ipywidgets import Image as ImageWidget
            # JPEG: the widget's first picture is also kept in the notebook's saved state
            self._widget = ImageWidget(value=self.jpeg(), format='jpeg')
        return self._widget

    def _push(self):
        """Send the newest frame to the widget, at most `fps` times a wall-clock second."""
        if self._widget is None:
            return
        now = time.monotonic()
        if now - self._last_push < 1.0 / self.fps:
            return
        self._last_push = now
        with self._lock:
            frame = self.frame
        ok, jpeg = cv2.imencode('.jpg', frame, [cv2.IMWRITE_JPEG_QUALITY, 85])
        try:
            self._widget.format = 'jpeg'
            self._widget.value = jpeg.tobytes()
        except Exception:  # a closed widget: stop pushing
            self._widget = None

    def jpeg(self, quality=80):
        """The newest frame as JPEG bytes: the static face stored in notebooks (a camera
        frame as PNG is ~0.5 MB, as JPEG ~40 KB)."""
        frame = cv2.imdecode(np.frombuffer(bytes(self.snapshot()), np.uint8), cv2.IMREAD_COLOR)
        return cv2.imencode('.jpg', frame, [cv2.IMWRITE_JPEG_QUALITY, quality])[1].tobytes()

    def _ipython_display_(self):
        from labkit.viz.display import show
        show(self.widget, jpeg=self.jpeg(), text='<image viewer: %s>' % self.topic)

    def close(self):
        """Stop the subscriber process and the widget."""
        if self.process is not None:
            self.process.stop()
            self.process = None
        if self._widget is not None:
            self._widget.close()
            self._widget = None


def _spin_image_subscriber(args, node_name, topic, make_callback):
    """The body of a subscriber process: a node `node_name` on an Image `topic`, spun until
    stopped. `make_callback(node)` returns the message callback (it may read the node's clock)."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type

    rclpy.init(args=args)
    node = rclpy.create_node(node_name)
    node.create_subscription(get_type('sensor_msgs/msg/Image'), topic, make_callback(node), 10)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


def _grey_for_display(image, _error):
    """Scale any one-channel image to 0..255 grey, then to BGR (rqt_image_view does similar)."""
    if image.ndim == 3:
        image = image[:, :, 0]
    image = np.nan_to_num(image.astype(np.float64))
    lo, hi = float(image.min()), float(image.max())
    grey = np.zeros(image.shape, np.uint8) if hi <= lo else \
        ((image - lo) * (255.0 / (hi - lo))).astype(np.uint8)
    return cv2.cvtColor(grey, cv2.COLOR_GRAY2BGR)


class FrameLog:
    """When each message of a topic arrived (node clock, seconds): frame rates over time.

        log = FrameLog('frame_image')    # a small subscriber process, node /frame_log
        labkit.sleep(9)
        log.count(0, 9)                  # messages that arrived in [0, 9) s of its clock
        log.rates()                      # [(second, messages in that second), ...]

    Like ImageViewer, an ordinary rclpy node in its own labkit process; it keeps
    only the arrival times, never the pixels.
    """

    def __init__(self, topic='frame_image', node_name='frame_log'):
        self.topic = topic
        self.node_name = node_name
        self.times = []
        self.start = None            # the node clock when the subscriber started
        self._clock = None
        from labkit import process
        self.process = process.start(name=node_name, main=self._main, args=[node_name], echo=False)

    def _main(self, args=None):
        def started(node):
            clock = self._clock = node.get_clock()
            self.start = clock.now().nanoseconds * 1e-9
            return lambda _msg: self.times.append(clock.now().nanoseconds * 1e-9)

        _spin_image_subscriber(args, self.node_name, self.topic, started)

    def elapsed(self):
        """Seconds of the node's clock since the log started."""
        if self._clock is None:
            return 0.0
        return self._clock.now().nanoseconds * 1e-9 - self.start

    def count(self, begin=None, end=None):
        """Messages that arrived in [begin, end) seconds after the log started."""
        start = self.start or 0.0
        return sum(1 for t in list(self.times)
                   if (begin is None or t - start >= begin) and (end is None or t - start < end))

    def rates(self):
        """Messages per whole second since the log started: [(second, count), ...]."""
        times = [t - (self.start or 0.0) for t in list(self.times)]
        if not times:
            return []
        last = int(max(times))
        counts = [0] * (last + 1)
        for t in times:
            counts[int(t)] += 1
        return list(enumerate(counts))

    def close(self):
        if self.process is not None:
            self.process.stop()
            self.process = None
