"""The facer robot's three nodes (book/part2_facer/facer_src) as labkit processes, virtual time.

The clip plays one frame per timer tick. With timer_period 0.5 frame k goes out
at t = 0.5 (k + 1): frames 0-5 (a face) at 0.5..3.0 s, frames 6-11 (no face)
at 3.5..6.0 s. The Haar cascade is slow (~0.25 s a frame on 2 cores), so the
tests run the detector on as few frames as they can.
"""
import numpy as np
import pytest

import labkit
from labkit import process
from labkit.vision import SAMPLE_CLIP


def _start(package, executable, *ros_args):
    module = __import__(f'{package}.{executable}', fromlist=['main'])
    args = [executable] + (['--ros-args', *ros_args] if ros_args else [])
    return process.start(name=executable, main=module.main, args=args, echo=False)


def _camera(timer_period=0.5):
    return _start('facer_input', 'capture_image', '-p', f'source:={SAMPLE_CLIP}',
                  '-p', f'timer_period:={timer_period}')


@pytest.fixture
def tester(virtual):
    """A node in the notebook's own process, with its executor."""
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    rclpy.init(args=[])
    node = rclpy.create_node('facer_tester')
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    yield node, executor
    executor.shutdown()
    node.destroy_node()
    rclpy.try_shutdown()


def _ask_face_result(node, executor):
    from facer_interfaces.srv import FaceResult
    client = node.create_client(FaceResult, 'face_result')
    assert client.wait_for_service(timeout_sec=2.0)
    future = client.call_async(FaceResult.Request(apply_result=True))
    executor.spin_until_future_complete(future, timeout_sec=2.0)
    node.destroy_client(client)
    return future.result().get_result


def test_face_result_on_a_face_frame(tester):
    node, executor = tester
    _camera()
    _start('facer_handle', 'identify_image')
    labkit.sleep(0.6)  # frame 0 (the astronaut) went through the cascade
    assert _ask_face_result(node, executor) == '检测到 1 张人脸'


def test_no_face_on_the_no_face_frames(tester, tmp_path):
    import cv2
    node, executor = tester
    cap = cv2.VideoCapture(SAMPLE_CLIP)
    frames = [cap.read()[1] for _ in range(8)]
    cap.release()
    still = str(tmp_path / 'no_face.avi')  # a two-frame clip: frames 6 and 7 of the sample
    writer = cv2.VideoWriter(still, cv2.VideoWriter_fourcc(*'MJPG'), 2.0, (640, 480))
    for frame in frames[6:8]:
        writer.write(frame)
    writer.release()
    _start('facer_input', 'capture_image', '-p', f'source:={still}', '-p', 'timer_period:=0.5')
    _start('facer_handle', 'identify_image')
    labkit.sleep(1.1)
    assert _ask_face_result(node, executor) == '未检测到人脸'


def test_visual_interaction_prints_results_and_feedback(virtual):
    _camera()
    _start('facer_handle', 'identify_image')
    viewer = _start('facer_output', 'visual_interaction')
    labkit.sleep(1.05)
    lines = viewer.output
    assert '[visual_interaction]: 识别结果：检测到 1 张人脸' in lines[0]
    assert '[visual_interaction]: 目标请求成功' in lines[1]
    assert '[visual_interaction]: 摄像头状态：摄像头打开' in lines[2]
    assert len(lines) == 3  # the next feedback comes at 1.5 s


def test_visual_interaction_keeps_the_annotated_frame(tester):
    from facer_output.visual_interaction import VisualInteraction
    _, executor = tester
    _camera()
    _start('facer_handle', 'identify_image')
    viewer = VisualInteraction()
    executor.add_node(viewer)
    try:
        executor.spin_until_future_complete(_never(), timeout_sec=0.6)
        frame = viewer.last_frame
        assert frame is not None and frame.shape == (480, 640, 3)
        green = np.all(frame == (0, 255, 0), axis=2)
        assert green.sum() > 400  # the box drawn around the face
    finally:
        executor.remove_node(viewer)
        viewer.destroy_node()


def _never():
    from rclpy.task import Future
    return Future()


def test_camera_state_feedback_then_result_while_frames_flow(tester):
    from facer_interfaces.action import CameraState
    from rclpy.action import ActionClient
    from sensor_msgs.msg import Image
    node, executor = tester
    _camera(timer_period=0.1)  # nobody runs the cascade here: cheap frames
    stamps = []
    node.create_subscription(Image, 'frame_image', lambda m: stamps.append(
        m.header.stamp.sec + m.header.stamp.nanosec * 1e-9), 10)
    client = ActionClient(node, CameraState, 'camera_state')
    assert client.wait_for_server(timeout_sec=2.0)
    feedback = []
    goal_future = client.send_goal_async(
        CameraState.Goal(start=True), feedback_callback=lambda f: feedback.append(
            (f.feedback.state, len(stamps))))
    executor.spin_until_future_complete(goal_future, timeout_sec=2.0)
    goal = goal_future.result()
    assert goal.accepted
    result_future = goal.get_result_async()
    executor.spin_until_future_complete(result_future, timeout_sec=10.0)
    assert result_future.result().result.finish == 'action completed'
    assert [state for state, _ in feedback] == ['摄像头打开'] * 10
    # the camera timer kept publishing while the goal was executing (5 s at 10 Hz)
    during = feedback[-1][1] - feedback[0][1]
    assert during >= 40


def test_goal_with_start_false_is_aborted(tester):
    from action_msgs.msg import GoalStatus
    from facer_interfaces.action import CameraState
    from rclpy.action import ActionClient
    node, executor = tester
    _camera()
    client = ActionClient(node, CameraState, 'camera_state')
    assert client.wait_for_server(timeout_sec=2.0)
    goal_future = client.send_goal_async(CameraState.Goal(start=False))
    executor.spin_until_future_complete(goal_future, timeout_sec=2.0)
    result_future = goal_future.result().get_result_async()
    executor.spin_until_future_complete(result_future, timeout_sec=2.0)
    assert result_future.result().status == GoalStatus.STATUS_ABORTED


def test_timer_period_change_takes_effect(tester):
    from sensor_msgs.msg import Image
    node, executor = tester
    _camera(timer_period=0.1)
    stamps = []
    node.create_subscription(Image, 'frame_image', lambda m: stamps.append(m), 10)

    def frames_in(seconds):
        before = len(stamps)
        end = node.get_clock().now().nanoseconds + int(seconds * 1e9)
        while node.get_clock().now().nanoseconds < end:
            executor.spin_once(timeout_sec=0.05)
        return len(stamps) - before

    assert frames_in(2.0) in (19, 20, 21)
    result = labkit.ros2('param set /capture_image timer_period 0.5')
    assert result.stdout.strip() == 'Set parameter successful'
    assert frames_in(2.0) in (3, 4, 5)
    refused = labkit.ros2('param set /capture_image timer_period 0.0')
    assert refused.stderr.strip() == 'Setting parameter failed: timer_period 必须大于 0'
    assert frames_in(2.0) in (3, 4, 5)


def test_parameter_description(virtual):
    _camera()
    out = labkit.ros2('param describe /capture_image timer_period').stdout
    assert 'Parameter name: timer_period' in out
    assert 'Type: double' in out
    assert 'Description: frame_image 话题的发布周期（秒）' in out


def test_no_camera_reports_camera_off(tester, tmp_path):
    from facer_interfaces.action import CameraState
    from rclpy.action import ActionClient
    from sensor_msgs.msg import Image
    node, executor = tester
    missing = str(tmp_path / 'no_such_clip.avi')
    camera = _start('facer_input', 'capture_image', '-p', f'source:={missing}')
    assert f"[capture_image]: 无法打开图像来源 '{missing}'" in camera.output[0]
    frames = []
    node.create_subscription(Image, 'frame_image', frames.append, 10)
    client = ActionClient(node, CameraState, 'camera_state')
    assert client.wait_for_server(timeout_sec=2.0)
    feedback = []
    goal_future = client.send_goal_async(CameraState.Goal(start=True),
                                         feedback_callback=lambda f: feedback.append(
                                             f.feedback.state))
    executor.spin_until_future_complete(goal_future, timeout_sec=2.0)
    result_future = goal_future.result().get_result_async()
    executor.spin_until_future_complete(result_future, timeout_sec=10.0)
    assert feedback == ['摄像头关闭'] * 10 and frames == []
    # pointing `source` at the clip at run time opens it
    result = labkit.ros2('param set /capture_image source ' + SAMPLE_CLIP)
    assert result.stdout == 'Set parameter successful\n', result.stderr
    executor.spin_until_future_complete(_never(), timeout_sec=0.55)
    assert len(frames) == 5


def test_missing_cascade_file_is_a_clear_error(virtual, monkeypatch):
    import rclpy
    import facer_handle.identify_image as identify
    # not installed here: no share/facer_handle, so the search goes on to OpenCV's own folders
    assert identify.find_cascade().endswith('haarcascade_frontalface_default.xml')
    monkeypatch.setattr(identify, 'find_cascade', lambda: None)
    rclpy.init(args=[])
    try:
        with pytest.raises(RuntimeError, match='sudo apt install opencv-data'):
            identify.IdentifyImage()
    finally:
        rclpy.try_shutdown()
