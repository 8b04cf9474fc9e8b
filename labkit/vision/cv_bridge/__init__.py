"""`import cv_bridge` under labkit: CvBridge, CvBridgeError, getCvType (as vision_opencv's)."""
from labkit.vision.cv_bridge.core import CvBridge, CvBridgeError
from labkit.vision.cv_bridge.encodings import cv_type as getCvType

__all__ = ['CvBridge', 'CvBridgeError', 'getCvType']
