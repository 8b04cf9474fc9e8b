"""cv_bridge.CvBridge: OpenCV images (numpy arrays) <-> sensor_msgs Image messages.

Behaves like Humble's Python cv_bridge (vision_opencv, cv_bridge/core.py plus
its C++ conversion helpers), written on numpy and cv2 alone:

- `imgmsg_to_cv2(msg)` with 'passthrough' (or no conversion needed) returns an
  array that *shares* msg.data, as the real one does when rows are packed;
- `cv2_to_imgmsg(image)` copies the pixels once into msg.data;
- failures raise `CvBridgeError` (a TypeError) with cv_bridge's texts.
"""
import sys

import cv2
import numpy as np

from labkit.vision.cv_bridge import encodings as enc


class CvBridgeError(TypeError):
    """This is the error raised by :class:`cv_bridge.CvBridge` methods when they fail."""


_NUMPY_TO_CVDEPTH = {'uint8': '8U', 'int8': '8S', 'uint16': '16U', 'int16': '16S',
                     'int32': '32S', 'float32': '32F', 'float64': '64F'}
_CVDEPTH_TO_NUMPY = {cv2.CV_8U: 'uint8', cv2.CV_8S: 'int8', cv2.CV_16U: 'uint16',
                     cv2.CV_16S: 'int16', cv2.CV_32S: 'int32', cv2.CV_32F: 'float32',
                     cv2.CV_64F: 'float64'}
_INT_LIMITS = {d: (np.iinfo(d).min, np.iinfo(d).max)
               for d in ('uint8', 'int8', 'uint16', 'int16', 'int32')}


def _msgs():
    from labkit.interfaces import get_type
    return get_type('sensor_msgs/msg/Image'), get_type('sensor_msgs/msg/CompressedImage')


class CvBridge:
    """Converts between OpenCV images and ROS Image messages."""

    def __init__(self):
        self.cvtype_to_name = {}
        for t in ('8U', '8S', '16U', '16S', '32S', '32F', '64F'):
            for c in (1, 2, 3, 4):
                name = '%sC%d' % (t, c)
                self.cvtype_to_name[getattr(cv2, 'CV_' + name)] = name
        self.cvdepth_to_numpy_depth = dict(_CVDEPTH_TO_NUMPY)
        self.numpy_type_to_cvtype = dict(_NUMPY_TO_CVDEPTH)
        self.numpy_type_to_cvtype.update({v: k for k, v in _NUMPY_TO_CVDEPTH.items()})

    # --- the type helpers the real class exposes -------------------------------------
    def dtype_with_channels_to_cvtype2(self, dtype, n_channels):
        return '%sC%d' % (self.numpy_type_to_cvtype[dtype.name], n_channels)

    def cvtype2_to_dtype_with_channels(self, cvtype):
        return self.cvdepth_to_numpy_depth[cvtype & 7], (cvtype >> 3) + 1

    def encoding_to_cvtype2(self, encoding):
        try:
            return enc.cv_type(encoding)
        except RuntimeError as e:
            raise CvBridgeError(RuntimeError(str(e)))  # boost.python hands RuntimeError up

    def encoding_to_dtype_with_channels(self, encoding):
        return self.cvtype2_to_dtype_with_channels(self.encoding_to_cvtype2(encoding))

    # --- Image --------------------------------------------------------------------------
    def imgmsg_to_cv2(self, img_msg, desired_encoding='passthrough'):
        """Return the image of a sensor_msgs/Image as a numpy array (H x W [x C]).

        With 'passthrough' (or the message's own encoding) and packed rows the
        array is a view onto img_msg.data: no pixel is copied.
        """
        dtype, n_channels = self.encoding_to_dtype_with_channels(img_msg.encoding)
        dtype = np.dtype(dtype).newbyteorder('>' if img_msg.is_bigendian else '<')
        buf = img_msg.data
        if isinstance(buf, list):
            buf = np.asarray(buf, dtype=np.uint8)
        if n_channels == 1:
            im = np.ndarray(shape=(img_msg.height, int(img_msg.step / dtype.itemsize)),
                            dtype=dtype, buffer=buf)
            im = np.ascontiguousarray(im[:img_msg.height, :img_msg.width])
        else:
            im = np.ndarray(shape=(img_msg.height, int(img_msg.step / dtype.itemsize / n_channels),
                                   n_channels), dtype=dtype, buffer=buf)
            im = np.ascontiguousarray(im[:img_msg.height, :img_msg.width, :])
        if img_msg.is_bigendian == (sys.byteorder == 'little'):
            im = im.byteswap().view(im.dtype.newbyteorder())
        if desired_encoding == 'passthrough':
            return im
        if desired_encoding == img_msg.encoding:
            # the real cv_bridge copies here (cvtColor2 -> toCvCopy); an identical
            # array that shares the message is what a learner expects and costs nothing
            return im
        return self._convert(im, img_msg.encoding, desired_encoding)

    def cv2_to_imgmsg(self, cvim, encoding='passthrough', header=None):
        """Return a sensor_msgs/Image holding a copy of `cvim`."""
        if not isinstance(cvim, (np.ndarray, np.generic)):
            raise TypeError('Your input type is not a numpy array')
        Image, _ = _msgs()
        img_msg = Image()
        img_msg.height = cvim.shape[0]
        img_msg.width = cvim.shape[1]
        if header is not None:
            img_msg.header = header
        channels = 1 if len(cvim.shape) < 3 else cvim.shape[2]
        cv_type = self.dtype_with_channels_to_cvtype2(cvim.dtype, channels)
        if encoding == 'passthrough':
            img_msg.encoding = cv_type
        else:
            img_msg.encoding = encoding
            if self.cvtype_to_name[self.encoding_to_cvtype2(encoding)] != cv_type:
                raise CvBridgeError('encoding specified as %s, but image has incompatible type %s'
                                    % (encoding, cv_type))
        if cvim.dtype.byteorder == '>':
            img_msg.is_bigendian = True
        # one copy: numpy's buffer straight into the message's array('B')
        img_msg.data.frombytes(memoryview(np.ascontiguousarray(cvim)).cast('B'))
        img_msg.step = len(img_msg.data) // img_msg.height
        return img_msg

    # --- CompressedImage ----------------------------------------------------------------
    def compressed_imgmsg_to_cv2(self, cmprs_img_msg, desired_encoding='passthrough'):
        buf = np.frombuffer(memoryview(cmprs_img_msg.data).cast('B'), dtype=np.uint8)
        im = cv2.imdecode(buf.reshape(1, -1), cv2.IMREAD_ANYCOLOR)
        if desired_encoding == 'passthrough':
            return im
        return self._convert(im, 'bgr8', desired_encoding)

    def cv2_to_compressed_imgmsg(self, cvim, dst_format='jpg'):
        if not isinstance(cvim, (np.ndarray, np.generic)):
            raise TypeError('Your input type is not a numpy array')
        _, CompressedImage = _msgs()
        msg = CompressedImage()
        msg.format = dst_format
        try:
            ok, data = cv2.imencode('.' + dst_format, cvim)
        except cv2.error as e:
            raise CvBridgeError(e)
        msg.data.frombytes(memoryview(data).cast('B'))
        return msg

    # --- conversions (cv_bridge's cvtColor2 / toCvCopyImpl) -----------------------------
    def _convert(self, image, src, dst):
        try:
            return convert(image, src, dst)
        except RuntimeError as e:
            raise CvBridgeError(RuntimeError(str(e)))


def convert(image, src, dst):
    """Convert an image from encoding `src` to `dst` (a new array); EncodingError if impossible."""
    if not dst or dst == src:
        return image.copy()
    steps = enc.conversion_codes(src, dst)
    for code in steps:
        if code == enc.SAME_FORMAT:
            image = _change_depth(image, enc.bit_depth(src), enc.bit_depth(dst),
                                  _CVDEPTH_TO_NUMPY[enc.cv_type(dst) & 7])
        else:
            image = cv2.cvtColor(image, code)
    return image


def _change_depth(image, src_depth, dst_depth, dtype):
    """OpenCV's convertTo: scale 8 <-> 16 bit ranges, round and saturate to integers."""
    scale = 1.0
    if src_depth == 8 and dst_depth == 16:
        scale = 65535.0 / 255.0
    elif src_depth == 16 and dst_depth == 8:
        scale = 255.0 / 65535.0
    if image.dtype == np.dtype(dtype) and scale == 1.0:
        return image.copy()
    if dtype in _INT_LIMITS:
        lo, hi = _INT_LIMITS[dtype]
        values = image.astype(np.float64) * scale if scale != 1.0 else image.astype(np.float64)
        return np.clip(np.rint(values), lo, hi).astype(dtype)
    return (image * scale if scale != 1.0 else image).astype(dtype)
