"""A clip path typed back as labkit printed it (/root/... in a sandbox) opens in a node.

ch10: `pwd` shows /root; a learner restarts capture_image with
`-p source:=/root/facer_crowd.avi`. The parameter keeps that text (as on Ubuntu) and
cv2.VideoCapture, wrapped when cv_bridge is imported under labkit, opens the sandbox file.
"""
import gc
import os
import shutil

import pytest

import labkit
from labkit.ament import files
from labkit.vision import SAMPLE_CLIP


@pytest.fixture
def sandbox(tmp_path):
    previous = os.getcwd()
    files.use_home(str(tmp_path / 'home'))
    try:
        yield tmp_path / 'home'
    finally:
        files.leave_home()
        os.chdir(previous)


def test_video_capture_opens_the_shown_path(sandbox):
    import cv2
    import labkit.vision.cv_bridge  # noqa: F401  (installs the wrapper, as a node does)
    shutil.copy(SAMPLE_CLIP, files.expand('~/facer_sample.avi'))
    cap = cv2.VideoCapture('/root/facer_sample.avi')
    assert cap.isOpened()
    ok, frame = cap.read()
    assert ok and frame is not None
    cap.release()
    assert not cv2.VideoCapture('/root/missing.avi').isOpened()
    del cap
    gc.collect()


def test_outside_a_sandbox_paths_are_not_rewritten():
    import cv2
    import labkit.vision.cv_bridge  # noqa: F401
    assert files.expand('/root/facer_sample.avi') == '/root/facer_sample.avi'
    assert cv2.VideoCapture(SAMPLE_CLIP).isOpened()
    gc.collect()


def test_capture_image_started_with_the_printed_path(virtual, sandbox):
    """The facer node itself, given source:=/root/facer_sample.avi, opens the clip: its
    parameter reads as typed and it publishes frames."""
    from labkit import process
    shutil.copy(SAMPLE_CLIP, files.expand('~/facer_sample.avi'))
    module = __import__('facer_input.capture_image', fromlist=['main'])
    camera = process.start(name='capture_image', main=module.main, echo=False,
                           args=['capture_image', '--ros-args', '-p',
                                 'source:=/root/facer_sample.avi', '-p', 'timer_period:=0.5'])
    labkit.sleep(0.2)
    r = labkit.ros2('param get /capture_image source')
    assert r.stdout == 'String value is: /root/facer_sample.avi\n'
    hz = labkit.ros2('topic echo --once /frame_image --field header.frame_id')
    assert hz.stdout.startswith('camera'), hz.stdout + hz.stderr
    assert not any('无法打开图像来源' in line for line in camera.output), camera.output
