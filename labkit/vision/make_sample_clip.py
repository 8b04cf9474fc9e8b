"""Regenerate the facer sample clip: book/part2_facer/media/facer_sample.avi.

A camera for readers without one: 18 frames of 640x480 MJPG at 2 fps,
3 s with a face, 3 s without, 3 s with a face. Every picture is public domain
and ships with scikit-image (only needed here, never at run time):
astronaut() is NASA's portrait of Eileen Collins (one face); coffee(),
rocket() and chelsea() have none. Each frame is checked with the same Haar
cascade the facer robot uses.

    python -m labkit.vision.make_sample_clip [output.avi]
"""
import os
import sys

import cv2
import numpy as np

WIDTH, HEIGHT, FPS = 640, 480, 2.0
DEFAULT_OUTPUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..',
                              'book', 'part2_facer', 'media', 'facer_sample.avi')


def face_detector():
    return cv2.CascadeClassifier(cv2.data.haarcascades + 'haarcascade_frontalface_default.xml')


def count_faces(cascade, bgr):
    """The facer robot's test: grey image, detectMultiScale(1.1, 5, minSize=(30, 30))."""
    grey = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY)
    return len(cascade.detectMultiScale(grey, scaleFactor=1.1, minNeighbors=5, minSize=(30, 30)))


def _frame(rgb, shift):
    """A 640x480 BGR frame of a picture, slid `shift` pixels sideways so frames differ."""
    bgr = cv2.cvtColor(np.ascontiguousarray(rgb), cv2.COLOR_RGB2BGR)
    frame = cv2.resize(bgr, (WIDTH + 16, HEIGHT), interpolation=cv2.INTER_AREA)
    return np.ascontiguousarray(frame[:, shift:shift + WIDTH])


def planned_frames():
    """(frame, has_face) pairs of the clip, in order."""
    from skimage import data
    face, others = data.astronaut(), [data.coffee(), data.rocket(), data.chelsea()]
    frames = [(_frame(face, 2 * i), True) for i in range(6)]
    frames += [(_frame(others[i // 2], 4 * (i % 2)), False) for i in range(6)]
    frames += [(_frame(face, 10 - 2 * i), True) for i in range(6)]
    return frames


def write_clip(path=DEFAULT_OUTPUT):
    path = os.path.abspath(path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    writer = cv2.VideoWriter(path, cv2.VideoWriter_fourcc(*'MJPG'), FPS, (WIDTH, HEIGHT))
    writer.set(cv2.VIDEOWRITER_PROP_QUALITY, 80)
    for frame, _ in planned_frames():
        writer.write(frame)
    writer.release()
    return path


def check_clip(path=DEFAULT_OUTPUT):
    """Read the clip back: returns the face count of every frame (what the robot will see)."""
    cap = cv2.VideoCapture(path)
    cascade, counts = face_detector(), []
    while True:
        ok, frame = cap.read()
        if not ok:
            break
        assert frame.shape == (HEIGHT, WIDTH, 3), frame.shape
        counts.append(count_faces(cascade, frame))
    cap.release()
    return counts


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    path = write_clip(argv[0] if argv else DEFAULT_OUTPUT)
    counts = check_clip(path)
    expected = [1 if has_face else 0 for _, has_face in planned_frames()]
    print('%s: %d bytes, %d frames, faces per frame %s'
          % (path, os.path.getsize(path), len(counts), counts))
    if counts != expected:
        print('face counts differ from the plan %s' % expected, file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
