"""Regenerate the facer sample clips in book/part2_facer/media.

facer_sample.avi, a camera for readers without one: 18 frames of 640x480 MJPG
at 2 fps, 3 s with a face, 3 s without, 3 s with a face. Every picture is
public domain and ships with scikit-image (only needed here, never at run
time): astronaut() is NASA's portrait of Eileen Collins (one face); coffee(),
rocket() and chelsea() have none.

facer_crowd.avi, the scene for tuning the detector (chapter 15): four pictures
in one 640x480 frame, 8 frames at 2 fps, sliding a little: Eileen Collins
(astronaut(), NASA, public domain), Grace Hopper (the U.S. Navy portrait,
public domain, that matplotlib ships as sample_data/grace_hopper.jpg), the
cameraman of camera() (CC0) whose face is turned away behind his camera, and a
patch of cell() (CC0) that the frontal-face cascade takes for a face at the
default minNeighbors=5 (a hard negative: about 10 neighbours, where the two
real faces have 30 or more).

Each frame is checked with the same Haar cascade the facer robot uses.

    python -m labkit.vision.make_sample_clip [output_dir]
"""
import os
import sys

import cv2
import numpy as np

WIDTH, HEIGHT, FPS = 640, 480, 2.0
MEDIA = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..',
                     'book', 'part2_facer', 'media')
DEFAULT_OUTPUT = os.path.join(MEDIA, 'facer_sample.avi')
CROWD_OUTPUT = os.path.join(MEDIA, 'facer_crowd.avi')
# facer_crowd.avi: boxes per frame at the defaults, and with minNeighbors raised to 20
CROWD_FACES, CROWD_STRICT = 3, 2


def face_detector():
    return cv2.CascadeClassifier(cv2.data.haarcascades + 'haarcascade_frontalface_default.xml')


def count_faces(cascade, bgr, min_neighbors=5):
    """The facer robot's test: grey image, detectMultiScale(1.1, 5, minSize=(30, 30))."""
    grey = cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY)
    return len(cascade.detectMultiScale(grey, scaleFactor=1.1, minNeighbors=min_neighbors,
                                        minSize=(30, 30)))


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


def crowd_frames():
    """The frames of facer_crowd.avi: four pictures in the quarters of the frame."""
    import matplotlib
    from skimage import data
    hopper = cv2.imread(os.path.join(os.path.dirname(matplotlib.__file__), 'mpl-data',
                                     'sample_data', 'grace_hopper.jpg'))
    hopper = cv2.resize(hopper, None, fx=0.35, fy=0.35, interpolation=cv2.INTER_AREA)
    collins = cv2.cvtColor(data.astronaut(), cv2.COLOR_RGB2BGR)
    cameraman = cv2.cvtColor(data.camera(), cv2.COLOR_GRAY2BGR)
    cells = cv2.cvtColor(data.cell(), cv2.COLOR_GRAY2BGR)
    frames = []
    for shift in (0, 2, 4, 6, 8, 6, 4, 2):
        frame = np.full((HEIGHT, WIDTH, 3), 96, np.uint8)
        frame[0:240, 0:320] = collins[0:240, 90 - shift:410 - shift]
        h, w = hopper.shape[:2]
        frame[15:15 + h, 390 + shift:390 + shift + w] = hopper
        frame[240:480, 0:320] = cameraman[40:280, 150 + shift:470 + shift]
        frame[240:480, 320:640] = cells[250:490, 230 - shift:550 - shift]
        frames.append(frame)
    return frames


def write_clip(path=DEFAULT_OUTPUT, frames=None):
    path = os.path.abspath(path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    writer = cv2.VideoWriter(path, cv2.VideoWriter_fourcc(*'MJPG'), FPS, (WIDTH, HEIGHT))
    writer.set(cv2.VIDEOWRITER_PROP_QUALITY, 80)
    if frames is None:
        frames = [frame for frame, _ in planned_frames()]
    for frame in frames:
        writer.write(frame)
    writer.release()
    return path


def check_clip(path=DEFAULT_OUTPUT, min_neighbors=5):
    """Read the clip back: returns the face count of every frame (what the robot will see)."""
    cap = cv2.VideoCapture(path)
    cascade, counts = face_detector(), []
    while True:
        ok, frame = cap.read()
        if not ok:
            break
        assert frame.shape == (HEIGHT, WIDTH, 3), frame.shape
        counts.append(count_faces(cascade, frame, min_neighbors))
    cap.release()
    return counts


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    folder = argv[0] if argv else MEDIA
    path = write_clip(os.path.join(folder, 'facer_sample.avi'))
    crowd = crowd_frames()
    crowd_path = write_clip(os.path.join(folder, 'facer_crowd.avi'), crowd)
    status = 0
    for path, counts, expected in (
            (path, check_clip(path), [1 if face else 0 for _, face in planned_frames()]),
            (crowd_path, check_clip(crowd_path), [CROWD_FACES] * len(crowd)),
            (crowd_path, check_clip(crowd_path, 20), [CROWD_STRICT] * len(crowd))):
        print('%s: %d bytes, %d frames, faces per frame %s'
              % (os.path.basename(path), os.path.getsize(path), len(counts), counts))
        if counts != expected:
            print('face counts differ from the plan %s' % expected, file=sys.stderr)
            status = 1
    return status


if __name__ == '__main__':
    sys.exit(main())
