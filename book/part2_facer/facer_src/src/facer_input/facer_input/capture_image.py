"""
capture_image 节点：facer 机器人的输入模块.

- 话题 frame_image 的发布者：按 timer_period 读取一帧图像，发布 sensor_msgs/msg/Image；
- 动作 camera_state 的服务端：执行目标时，每 0.5 秒反馈一次摄像头状态，共 10 次。

参数：
- timer_period (double, 默认 0.1 秒)：发布周期；运行中修改会重建定时器，立即生效；
- source：cv2.VideoCapture 的输入。0 是电脑的第一个摄像头；
  也可以是视频文件的路径（读到结尾后从头循环播放）。
"""
import time

import cv2
from cv_bridge import CvBridge
from facer_interfaces.action import CameraState
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
import rclpy
from rclpy.action import ActionServer
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from sensor_msgs.msg import Image

CAMERA_ON = '摄像头打开'
CAMERA_OFF = '摄像头关闭'


class CaptureImage(Node):

    def __init__(self):
        super().__init__('capture_image')
        self.declare_parameter(
            'timer_period', 0.1,
            ParameterDescriptor(description='frame_image 话题的发布周期（秒）'))
        # dynamic_typing：source 既可以是整数（摄像头编号），也可以是字符串（视频文件）
        self.declare_parameter(
            'source', 0,
            ParameterDescriptor(description='cv2.VideoCapture 的输入：摄像头编号或视频文件路径',
                                dynamic_typing=True))

        self.cv_bridge = CvBridge()
        self.cap = None
        self.open_source(self.get_parameter('source').value)

        self.publisher_ = self.create_publisher(Image, 'frame_image', 10)
        self.timer = self.create_timer(
            self.get_parameter('timer_period').value, self.timer_callback)
        # 参数被修改时调用：没有它，ros2 param set 改了数值，定时器却还按旧周期运行
        self.add_on_set_parameters_callback(self.parameters_callback)

        # 动作的执行回调要运行约 5 秒。把它放进可重入回调组，再由多线程执行器
        # 运行，它在一个线程里等待的同时，另一个线程照常执行定时器回调发布图像。
        # （单线程执行器一次只运行一个回调：执行回调不返回，定时器就停了。）
        self._action_server = ActionServer(
            self, CameraState, 'camera_state', self.execute_callback,
            callback_group=ReentrantCallbackGroup())

    def open_source(self, source):
        """打开摄像头或视频文件."""
        if self.cap is not None:
            self.cap.release()
        self.source = source
        self.cap = cv2.VideoCapture(source)
        # 在这里就给 camera_state 赋值：第一帧之前就可能有动作目标到来
        self.camera_state = CAMERA_ON if self.cap.isOpened() else CAMERA_OFF
        if not self.cap.isOpened():
            self.get_logger().warn(f'无法打开图像来源 {source!r}')

    def read_frame(self):
        """读取一帧；视频文件读到结尾就回到开头."""
        ret, frame = self.cap.read()
        if not ret and isinstance(self.source, str):
            self.cap.set(cv2.CAP_PROP_POS_FRAMES, 0)
            ret, frame = self.cap.read()
        return ret, frame

    def timer_callback(self):
        ret, frame = self.read_frame()
        if not ret:
            self.camera_state = CAMERA_OFF
            return
        self.camera_state = CAMERA_ON
        msg = self.cv_bridge.cv2_to_imgmsg(frame, 'bgr8')
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.header.frame_id = 'camera'
        self.publisher_.publish(msg)

    def parameters_callback(self, params):
        for param in params:
            if param.name == 'timer_period':
                if param.value <= 0.0:
                    return SetParametersResult(successful=False, reason='timer_period 必须大于 0')
                # 用新的周期重建定时器
                self.destroy_timer(self.timer)
                self.timer = self.create_timer(param.value, self.timer_callback)
            elif param.name == 'source':
                self.open_source(param.value)
        return SetParametersResult(successful=True)

    def execute_callback(self, goal_handle):
        result = CameraState.Result()
        if not goal_handle.request.start:
            goal_handle.abort()
            result.finish = '目标的 start 为 False，动作未执行'
            return result
        feedback_msg = CameraState.Feedback()
        for _ in range(10):
            feedback_msg.state = self.camera_state
            goal_handle.publish_feedback(feedback_msg)
            time.sleep(0.5)  # 只让这个线程等待，定时器回调在别的线程照常运行
            if not rclpy.ok():  # 等待期间节点被关闭了（Ctrl+C）：中止这个目标
                try:
                    goal_handle.abort()
                except Exception:  # 上下文已关闭，状态发不出去（RCLError）：本地仍记为中止
                    pass
                result.finish = '节点正在关闭，动作中止'
                return result
        goal_handle.succeed()
        result.finish = 'action completed'
        return result


def main(args=None):
    rclpy.init(args=args)
    node = CaptureImage()
    executor = MultiThreadedExecutor()
    executor.add_node(node)
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    # 等还在运行的回调（动作的执行回调）结束：它看到 rclpy.ok() 为 False 就中止目标，
    # 然后才能销毁节点；先销毁节点的话，执行回调里的 abort() 会因句柄已销毁而出错
    executor.shutdown()
    node.cap.release()
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
