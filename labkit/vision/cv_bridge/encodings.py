"""Image encodings as sensor_msgs/image_encodings.hpp and cv_bridge define them.

Only what the Python cv_bridge needs: the OpenCV type of an encoding, its
channel count and bit depth, and the list of cv2 colour conversions that turn
one encoding into another (cv_bridge's getConversionCode).
"""
import re

import cv2

COLOR = ('rgb8', 'bgr8', 'rgba8', 'bgra8', 'rgb16', 'bgr16', 'rgba16', 'bgra16')
MONO = ('mono8', 'mono16')
BAYER = ('bayer_rggb8', 'bayer_bggr8', 'bayer_gbrg8', 'bayer_grbg8',
         'bayer_rggb16', 'bayer_bggr16', 'bayer_gbrg16', 'bayer_grbg16')
YUV = ('yuv422', 'yuv422_yuy2')
_ABSTRACT_PREFIXES = ('8UC', '8SC', '16UC', '16SC', '32SC', '32FC', '64FC')
_DEPTHS = {'8U': cv2.CV_8U, '8S': cv2.CV_8S, '16U': cv2.CV_16U, '16S': cv2.CV_16S,
           '32S': cv2.CV_32S, '32F': cv2.CV_32F, '64F': cv2.CV_64F}
_GENERIC = re.compile(r'(8U|8S|16U|16S|32S|32F|64F)(?:C([0-9]+))?')

# encodings with a fixed OpenCV type (cv_bridge's getCvType, common cases first)
_NAMED_TYPES = {
    'bgr8': cv2.CV_8UC3, 'mono8': cv2.CV_8UC1, 'rgb8': cv2.CV_8UC3,
    'mono16': cv2.CV_16UC1, 'bgr16': cv2.CV_16UC3, 'rgb16': cv2.CV_16UC3,
    'bgra8': cv2.CV_8UC4, 'rgba8': cv2.CV_8UC4, 'bgra16': cv2.CV_16UC4, 'rgba16': cv2.CV_16UC4,
    'yuv422': cv2.CV_8UC2, 'yuv422_yuy2': cv2.CV_8UC2,
}
_NAMED_TYPES.update({b: cv2.CV_8UC1 if b.endswith('8') else cv2.CV_16UC1 for b in BAYER})


class EncodingError(RuntimeError):
    """What cv_bridge's C++ side throws; the Python layer turns it into CvBridgeError."""


def make_type(depth, channels):
    return depth + ((channels - 1) << 3)  # OpenCV's CV_MAKETYPE


def cv_type(encoding):
    """OpenCV type number of an encoding (cv_bridge::getCvType)."""
    if encoding in _NAMED_TYPES:
        return _NAMED_TYPES[encoding]
    m = _GENERIC.fullmatch(encoding)
    if m:
        return make_type(_DEPTHS[m.group(1)], int(m.group(2) or 1))
    raise EncodingError('Unrecognized image encoding [%s]' % encoding)


def num_channels(encoding):
    if encoding in MONO or encoding in BAYER:
        return 1
    if encoding in ('bgr8', 'rgb8', 'bgr16', 'rgb16'):
        return 3
    if encoding in ('bgra8', 'rgba8', 'bgra16', 'rgba16'):
        return 4
    for prefix in _ABSTRACT_PREFIXES:
        if encoding.startswith(prefix):
            rest = encoding[len(prefix):]
            if not rest:
                return 1
            n = _atoi(rest)
            if n:
                return n
    if encoding in YUV or encoding in ('nv21', 'nv24'):
        return 2
    raise EncodingError('Unknown encoding ' + encoding)


def bit_depth(encoding):
    if encoding in BAYER:
        return 8 if encoding.endswith('8') else 16
    if encoding in ('mono8', 'bgr8', 'rgb8', 'bgra8', 'rgba8'):
        return 8
    if encoding in ('mono16', 'bgr16', 'rgb16', 'bgra16', 'rgba16'):
        return 16
    for prefix in _ABSTRACT_PREFIXES:
        if encoding.startswith(prefix) and (encoding == prefix or _atoi(encoding[len(prefix):])):
            return _atoi(prefix)
    if encoding in YUV or encoding in ('nv21', 'nv24'):
        return 8
    raise EncodingError('Unknown encoding ' + encoding)


def _atoi(text):
    """C's atoi: leading digits, 0 when there are none."""
    m = re.match(r'\s*([+-]?[0-9]+)', text)
    return int(m.group(1)) if m else 0


def _family(encoding):
    """The colour family cv_bridge's getEncoding() sorts an encoding into (None: no colour)."""
    for family in ('mono', 'bgra', 'rgba', 'bgr', 'rgb'):
        if encoding in (family + '8', family + '16'):
            return 'gray' if family == 'mono' else family
    if encoding in YUV:
        return encoding
    if encoding in BAYER:
        return encoding.rstrip('0123456789')  # bayer_rggb8 -> bayer_rggb
    return None


SAME_FORMAT = -1  # "only change the depth" step

_C = cv2
_CODES = {
    ('gray', 'rgb'): _C.COLOR_GRAY2RGB, ('gray', 'bgr'): _C.COLOR_GRAY2BGR,
    ('gray', 'rgba'): _C.COLOR_GRAY2RGBA, ('gray', 'bgra'): _C.COLOR_GRAY2BGRA,
    ('rgb', 'gray'): _C.COLOR_RGB2GRAY, ('rgb', 'bgr'): _C.COLOR_RGB2BGR,
    ('rgb', 'rgba'): _C.COLOR_RGB2RGBA, ('rgb', 'bgra'): _C.COLOR_RGB2BGRA,
    ('bgr', 'gray'): _C.COLOR_BGR2GRAY, ('bgr', 'rgb'): _C.COLOR_BGR2RGB,
    ('bgr', 'rgba'): _C.COLOR_BGR2RGBA, ('bgr', 'bgra'): _C.COLOR_BGR2BGRA,
    ('rgba', 'gray'): _C.COLOR_RGBA2GRAY, ('rgba', 'rgb'): _C.COLOR_RGBA2RGB,
    ('rgba', 'bgr'): _C.COLOR_RGBA2BGR, ('rgba', 'bgra'): _C.COLOR_RGBA2BGRA,
    ('bgra', 'gray'): _C.COLOR_BGRA2GRAY, ('bgra', 'rgb'): _C.COLOR_BGRA2RGB,
    ('bgra', 'bgr'): _C.COLOR_BGRA2BGR, ('bgra', 'rgba'): _C.COLOR_BGRA2RGBA,
    ('yuv422', 'gray'): _C.COLOR_YUV2GRAY_UYVY, ('yuv422', 'rgb'): _C.COLOR_YUV2RGB_UYVY,
    ('yuv422', 'bgr'): _C.COLOR_YUV2BGR_UYVY, ('yuv422', 'rgba'): _C.COLOR_YUV2RGBA_UYVY,
    ('yuv422', 'bgra'): _C.COLOR_YUV2BGRA_UYVY,
    ('yuv422_yuy2', 'gray'): _C.COLOR_YUV2GRAY_YUY2, ('yuv422_yuy2', 'rgb'): _C.COLOR_YUV2RGB_YUY2,
    ('yuv422_yuy2', 'bgr'): _C.COLOR_YUV2BGR_YUY2, ('yuv422_yuy2', 'rgba'): _C.COLOR_YUV2RGBA_YUY2,
    ('yuv422_yuy2', 'bgra'): _C.COLOR_YUV2BGRA_YUY2,
    ('bayer_rggb', 'gray'): _C.COLOR_BayerBG2GRAY, ('bayer_rggb', 'rgb'): _C.COLOR_BayerBG2RGB,
    ('bayer_rggb', 'bgr'): _C.COLOR_BayerBG2BGR,
    ('bayer_bggr', 'gray'): _C.COLOR_BayerRG2GRAY, ('bayer_bggr', 'rgb'): _C.COLOR_BayerRG2RGB,
    ('bayer_bggr', 'bgr'): _C.COLOR_BayerRG2BGR,
    ('bayer_gbrg', 'gray'): _C.COLOR_BayerGR2GRAY, ('bayer_gbrg', 'rgb'): _C.COLOR_BayerGR2RGB,
    ('bayer_gbrg', 'bgr'): _C.COLOR_BayerGR2BGR,
    ('bayer_grbg', 'gray'): _C.COLOR_BayerGB2GRAY, ('bayer_grbg', 'rgb'): _C.COLOR_BayerGB2RGB,
    ('bayer_grbg', 'bgr'): _C.COLOR_BayerGB2BGR,
}
# the plain colour families convert to themselves (bayer and yuv do not)
_CODES.update({(f, f): SAME_FORMAT for f in ('gray', 'rgb', 'bgr', 'rgba', 'bgra', 'yuv422')})


def _has_colour_info(encoding):
    return encoding in COLOR or encoding in MONO or encoding in BAYER or encoding in YUV


def conversion_codes(src, dst):
    """The steps from `src` to `dst` (cv_bridge's getConversionCode), or EncodingError."""
    src_colour, dst_colour = _has_colour_info(src), _has_colour_info(dst)
    same_channels = num_channels(src) == num_channels(dst)
    if not src_colour:
        if dst_colour:
            raise EncodingError('[%s] is not a color format. but [%s] is. '
                                'The conversion does not make sense' % (src, dst))
        if not same_channels:
            raise EncodingError('[%s] and [%s] do not have the same number of channel'
                                % (src, dst))
        return [SAME_FORMAT]
    if not dst_colour:
        if not same_channels:
            raise EncodingError('[%s] is a color format but [%s] is not so they must have '
                                'the same OpenCV type, CV_8UC3, CV16UC1 ....' % (src, dst))
        return [SAME_FORMAT]
    key = (_family(src), _family(dst))
    if key not in _CODES:
        raise EncodingError('Unsupported conversion from [%s] to [%s]' % (src, dst))
    codes = [_CODES[key]]
    if bit_depth(src) != bit_depth(dst) and _family(src) != _family(dst):
        codes.append(SAME_FORMAT)
    return codes
