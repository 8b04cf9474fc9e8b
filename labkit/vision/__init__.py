"""Vision tools for the book: cv_bridge, the sample camera clip, an image viewer.

`register()` makes `import cv_bridge` resolve to `labkit.vision.cv_bridge`
while the labkit import hook is active (ARCHITECTURE.md, extension points).
"""
import os

# the book's sample camera clip (book/part2_facer/media, made by make_sample_clip.py)
SAMPLE_CLIP = os.path.normpath(os.path.join(
    os.path.dirname(os.path.abspath(__file__)), '..', '..',
    'book', 'part2_facer', 'media', 'facer_sample.avi'))
# the scene for tuning the detector: two faces, a turned-away face, a false positive
CROWD_CLIP = os.path.join(os.path.dirname(SAMPLE_CLIP), 'facer_crowd.avi')


def register():
    from labkit import compat
    compat.register_alias('cv_bridge', 'labkit.vision.cv_bridge')
