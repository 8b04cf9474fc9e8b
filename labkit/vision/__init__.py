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


def open_typed_back_paths():
    """cv2.VideoCapture(path) opens a path as labkit printed it (/root/... in a sandbox).

    A node reading a clip gets the path from a parameter (`-p source:=/root/x.avi`): the
    parameter keeps what was typed, as on Ubuntu, and the capture opens the file the
    sandbox stands for. Installed when `cv_bridge` is imported under labkit (every image
    node does). A wrapper function, not a subclass: subclasses of cv2's classes crash in
    the garbage collector. Outside a sandbox nothing is rewritten."""
    import cv2
    if getattr(cv2.VideoCapture, '_labkit_paths', False):
        return
    from labkit.ament import files
    original = cv2.VideoCapture

    def VideoCapture(*args, **kwargs):
        if args and isinstance(args[0], str):
            args = (files.expand(args[0]),) + args[1:]
        return original(*args, **kwargs)

    VideoCapture._labkit_paths = True
    VideoCapture.__doc__ = original.__doc__
    cv2.VideoCapture = VideoCapture
