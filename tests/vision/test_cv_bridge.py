"""cv_bridge under labkit: round trips, conversions, the real error texts, shared buffers."""
import sys

import cv2
import numpy as np
import pytest


def _image(shape, dtype, seed=0):
    rng = np.random.default_rng(seed)
    if np.dtype(dtype).kind == 'f':
        return rng.random(shape).astype(dtype)
    info = np.iinfo(dtype)
    return rng.integers(info.min, info.max, size=shape, endpoint=True).astype(dtype)


def test_import_cv_bridge_resolves_to_labkit(hook):
    import cv_bridge
    assert cv_bridge.CvBridge.__module__ == 'labkit.vision.cv_bridge.core'
    assert issubclass(cv_bridge.CvBridgeError, TypeError)
    assert cv_bridge.getCvType('bgr8') == cv2.CV_8UC3
    assert cv_bridge.getCvType('32FC1') == cv2.CV_32FC1
    assert cv_bridge.getCvType('16SC3') == cv2.CV_16SC3


@pytest.mark.parametrize('encoding, shape, dtype', [
    ('bgr8', (48, 64, 3), np.uint8), ('rgb8', (48, 64, 3), np.uint8),
    ('mono8', (48, 64), np.uint8), ('bgra8', (48, 64, 4), np.uint8),
    ('rgba8', (48, 64, 4), np.uint8), ('mono16', (48, 64), np.uint16),
    ('16UC1', (48, 64), np.uint16), ('32FC1', (48, 64), np.float32),
])
def test_round_trip(bridge, encoding, shape, dtype):
    image = _image(shape, dtype)
    msg = bridge.cv2_to_imgmsg(image, encoding)
    itemsize = np.dtype(dtype).itemsize
    channels = shape[2] if len(shape) == 3 else 1
    assert (msg.height, msg.width, msg.encoding) == (48, 64, encoding)
    assert msg.step == 64 * channels * itemsize
    assert len(msg.data) == msg.step * msg.height
    assert msg.is_bigendian == 0
    back = bridge.imgmsg_to_cv2(msg)
    assert back.dtype == dtype and back.shape == shape
    np.testing.assert_array_equal(back, image)
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg, encoding), image)


def test_passthrough_names_the_opencv_type(bridge):
    assert bridge.cv2_to_imgmsg(np.zeros((2, 3, 3), np.uint8)).encoding == '8UC3'
    assert bridge.cv2_to_imgmsg(np.zeros((2, 3), np.float32)).encoding == '32FC1'
    assert bridge.cv2_to_imgmsg(np.zeros((2, 3, 2), np.int16)).encoding == '16SC2'


def test_header_is_kept(bridge, hook):
    from std_msgs.msg import Header
    header = Header(frame_id='camera')
    header.stamp.sec = 42
    msg = bridge.cv2_to_imgmsg(np.zeros((2, 3, 3), np.uint8), 'bgr8', header=header)
    assert msg.header.frame_id == 'camera' and msg.header.stamp.sec == 42


def test_colour_conversions(bridge):
    bgr = _image((30, 40, 3), np.uint8)
    msg = bridge.cv2_to_imgmsg(bgr, 'bgr8')
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg, 'rgb8'), bgr[:, :, ::-1])
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg, 'mono8'),
                                  cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY))
    bgra = bridge.imgmsg_to_cv2(msg, 'bgra8')
    assert bgra.shape == (30, 40, 4) and (bgra[:, :, 3] == 255).all()
    # colour to 16 bit: convert, then scale 0..255 onto 0..65535 as OpenCV's convertTo
    mono16 = bridge.imgmsg_to_cv2(msg, 'mono16')
    assert mono16.dtype == np.uint16
    grey = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY).astype(np.uint32)
    np.testing.assert_array_equal(mono16, grey * 257)
    # 16 bit grey to 8 bit colour scales back down
    m16 = bridge.cv2_to_imgmsg(np.array([[0, 257, 65535]], np.uint16), 'mono16')
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(m16, 'bgr8')[0, :, 0], [0, 1, 255])
    # the same family at another depth: bgr8 -> bgr16
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg, 'bgr16'), bgr.astype(np.uint16) * 257)


def test_non_colour_conversion_changes_depth_only(bridge):
    depth = np.array([[1.4, 2.6, -3.0, 70000.0]], np.float32)
    msg = bridge.cv2_to_imgmsg(depth, '32FC1')
    # OpenCV's convertTo rounds and saturates
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg, '16UC1'), [[1, 3, 0, 65535]])


@pytest.mark.parametrize('call, text', [
    (lambda b, m: b.imgmsg_to_cv2(m, 'foo'), 'Unknown encoding foo'),
    (lambda b, m: b.imgmsg_to_cv2(m, '32FC1'),
     '[bgr8] is a color format but [32FC1] is not so they must have the same OpenCV type, '
     'CV_8UC3, CV16UC1 ....'),
    (lambda b, m: b.cv2_to_imgmsg(np.zeros((2, 2, 3), np.uint8), 'mono8'),
     'encoding specified as mono8, but image has incompatible type 8UC3'),
    (lambda b, m: b.cv2_to_imgmsg(np.zeros((2, 2), np.uint8), 'bgr99'),
     'Unrecognized image encoding [bgr99]'),
    (lambda b, m: b.cv2_to_imgmsg(np.zeros((2, 2), np.float32), 'mono16'),
     'encoding specified as mono16, but image has incompatible type 32FC1'),
])
def test_errors_have_cv_bridge_texts(bridge, call, text):
    from cv_bridge import CvBridgeError
    msg = bridge.cv2_to_imgmsg(np.zeros((2, 2, 3), np.uint8), 'bgr8')
    with pytest.raises(CvBridgeError) as info:
        call(bridge, msg)
    assert str(info.value) == text


def test_more_errors(bridge):
    from cv_bridge import CvBridgeError
    depth = bridge.cv2_to_imgmsg(np.zeros((2, 2), np.float32))
    with pytest.raises(CvBridgeError, match=r'^\[32FC1\] is not a color format. but \[bgr8\] is. '
                                            r'The conversion does not make sense$'):
        bridge.imgmsg_to_cv2(depth, 'bgr8')
    with pytest.raises(CvBridgeError, match=r'do not have the same number of channel'):
        bridge.imgmsg_to_cv2(depth, '32FC3')
    bad = bridge.cv2_to_imgmsg(np.zeros((2, 2), np.uint8))
    bad.encoding = 'nonsense'
    with pytest.raises(CvBridgeError, match=r'^Unrecognized image encoding \[nonsense\]$'):
        bridge.imgmsg_to_cv2(bad)
    with pytest.raises(TypeError, match='Your input type is not a numpy array'):
        bridge.cv2_to_imgmsg([[1, 2], [3, 4]])


def test_imgmsg_to_cv2_shares_the_message_buffer(bridge):
    msg = bridge.cv2_to_imgmsg(_image((48, 64, 3), np.uint8), 'bgr8')
    data = np.frombuffer(msg.data, np.uint8)
    view = bridge.imgmsg_to_cv2(msg)
    assert np.shares_memory(view, data)
    assert np.shares_memory(bridge.imgmsg_to_cv2(msg, 'bgr8'), data)  # nothing to convert
    view[0, 0] = (1, 2, 3)
    assert list(msg.data[:3]) == [1, 2, 3]
    assert not np.shares_memory(bridge.imgmsg_to_cv2(msg, 'rgb8'), data)


def test_cv2_to_imgmsg_copies(bridge):
    image = _image((4, 5, 3), np.uint8)
    msg = bridge.cv2_to_imgmsg(image, 'bgr8')
    image[:] = 0
    assert any(msg.data)
    # a non-contiguous view (every other column) is packed into the message
    wide = _image((4, 10, 3), np.uint8)
    msg = bridge.cv2_to_imgmsg(wide[:, ::2], 'bgr8')
    assert msg.step == 15
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg), wide[:, ::2])


def test_padded_rows_and_big_endian(bridge, hook):
    from sensor_msgs.msg import Image
    # rows padded to 8 bytes: the bridge cuts the padding off
    msg = Image(height=2, width=3, encoding='mono8', step=8)
    msg.data.frombytes(bytes([1, 2, 3, 0, 0, 0, 0, 0, 4, 5, 6, 0, 0, 0, 0, 0]))
    np.testing.assert_array_equal(bridge.imgmsg_to_cv2(msg), [[1, 2, 3], [4, 5, 6]])
    # a big-endian 16 bit image comes back in this machine's byte order
    big = Image(height=1, width=2, encoding='16UC1', step=4, is_bigendian=1)
    big.data.frombytes(np.array([[1, 513]], '>u2').tobytes())
    out = bridge.imgmsg_to_cv2(big)
    np.testing.assert_array_equal(out, [[1, 513]])
    assert out.dtype.byteorder in ('=', '|', '<' if sys.byteorder == 'little' else '>')


def test_compressed_round_trip(bridge):
    image = _image((20, 30, 3), np.uint8)
    msg = bridge.cv2_to_compressed_imgmsg(image, 'png')
    assert msg.format == 'png' and bytes(msg.data[:4]) == b'\x89PNG'
    np.testing.assert_array_equal(bridge.compressed_imgmsg_to_cv2(msg), image)
    np.testing.assert_array_equal(bridge.compressed_imgmsg_to_cv2(msg, 'rgb8'), image[:, :, ::-1])
    assert bridge.cv2_to_compressed_imgmsg(image).format == 'jpg'
