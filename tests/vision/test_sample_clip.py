"""The sample clip the book uses as a camera: readable by cv2.VideoCapture, faces where planned."""
import os

import cv2

from labkit.vision import SAMPLE_CLIP
from labkit.vision.make_sample_clip import count_faces, face_detector

PLAN = [1] * 6 + [0] * 6 + [1] * 6  # 3 s face, 3 s none, 3 s face at 2 fps


def test_clip_is_small_and_readable():
    assert os.path.getsize(SAMPLE_CLIP) < 1_000_000
    cap = cv2.VideoCapture(SAMPLE_CLIP)
    assert cap.isOpened()
    assert int(cap.get(cv2.CAP_PROP_FRAME_COUNT)) == len(PLAN)
    assert cap.get(cv2.CAP_PROP_FPS) == 2.0
    shapes = []
    while True:
        ok, frame = cap.read()
        if not ok:
            break
        shapes.append(frame.shape)
    cap.release()
    assert shapes == [(480, 640, 3)] * len(PLAN)


def test_faces_exactly_on_the_face_frames():
    # the frames on either side of each change (the cascade is slow: 6 frames, not 18)
    cap = cv2.VideoCapture(SAMPLE_CLIP)
    frames = [cap.read()[1] for _ in PLAN]
    cap.release()
    cascade = face_detector()
    for index in (0, 5, 6, 11, 12, 17):
        assert count_faces(cascade, frames[index]) == PLAN[index], index


def test_crowd_clip_has_two_faces_and_a_false_positive_that_min_neighbors_removes():
    from labkit.vision import CROWD_CLIP
    from labkit.vision.make_sample_clip import CROWD_FACES, CROWD_STRICT
    assert os.path.getsize(CROWD_CLIP) < 400_000
    cap = cv2.VideoCapture(CROWD_CLIP)
    frames = []
    while True:
        ok, frame = cap.read()
        if not ok:
            break
        frames.append(frame)
    cap.release()
    assert len(frames) == 8 and frames[0].shape == (480, 640, 3)
    cascade = face_detector()
    for frame in (frames[0], frames[4]):
        assert count_faces(cascade, frame) == CROWD_FACES == 3       # 2 faces + the cell patch
        assert count_faces(cascade, frame, min_neighbors=20) == CROWD_STRICT == 2
        # the false positive is in the cell picture (bottom right), the faces at the top
        grey = cv2.cvtColor(frame, cv2.COLOR_BGR2GRAY)
        boxes = cascade.detectMultiScale(grey, 1.1, 5, minSize=(30, 30))
        assert sorted((x >= 320, y >= 240) for x, y, _, _ in boxes) == [
            (False, False), (True, False), (True, True)]
