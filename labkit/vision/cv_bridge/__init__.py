"""`import cv_bridge` under labkit: CvBridge, CvBridgeError, getCvType (as vision_opencv's)."""
from labkit.vision.cv_bridge.core import CvBridge, CvBridgeError
from labkit.vision.cv_bridge.encodings import cv_type as getCvType

__all__ = ['CvBridge', 'CvBridgeError', 'getCvType']

from labkit.vision import open_typed_back_paths as _typed_back  # noqa: E402
_typed_back()       # a clip's /root/... path, typed back from labkit's output, opens
