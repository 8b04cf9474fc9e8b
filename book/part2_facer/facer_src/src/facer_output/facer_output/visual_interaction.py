"""
visual_interaction 节点：facer 机器人的输出模块（人机交互）.

- 服务 face_result 的客户端：每 query_period 秒询问一次识别结果并打印；
- 动作 camera_state 的客户端：启动后发送一个目标，打印反馈（摄像头状态）和结果；
- 话题 face_image 的订阅者：保存最近一帧框出人脸的图像（last_frame），
  参数 show_window 为 true 时用 cv2.imshow 显示在窗口里。

所有等待都交给执行器：节点从不阻塞，哪个服务端先启动都可以。
"""
import cv2
from cv_bridge import CvBridge
from facer_interfaces.action import CameraState
from facer_interfaces.srv import FaceResult
import rclpy
from rclpy.action import ActionClient
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from sensor_msgs.msg import Image


class VisualInteraction(Node):

    def __init__(self):
        super().__init__('visual_interaction')
        self.declare_parameter('query_period', 1.0)
        self.declare_parameter('show_window', False)
        self.cv_bridge = CvBridge()
        self.last_frame = None  # 最近一帧标注过的图像（OpenCV 格式）
        self.last_result = None
        self.goal_sent = False

        self.cli = self.create_client(FaceResult, 'face_result')
        self._action_client = ActionClient(self, CameraState, 'camera_state')
        self.create_subscription(Image, 'face_image', self.image_callback, 10)
        self.timer = self.create_timer(
            self.get_parameter('query_period').value, self.timer_callback)

    def timer_callback(self):
        if not self.goal_sent and self._action_client.server_is_ready():
            self.send_goal(True)
        if self.cli.service_is_ready():
            self.send_request(True)
        else:
            self.get_logger().info('等待服务 face_result 的服务端运行...')

    # ---- 服务 face_result ----
    def send_request(self, apply_result):
        request = FaceResult.Request()
        request.apply_result = apply_result
        future = self.cli.call_async(request)  # 不等待：结果到了再调用回调
        future.add_done_callback(self.response_callback)

    def response_callback(self, future):
        self.last_result = future.result().get_result
        self.get_logger().info(f'识别结果：{self.last_result}')

    # ---- 动作 camera_state ----
    def send_goal(self, start):
        self.goal_sent = True
        goal_msg = CameraState.Goal()
        goal_msg.start = start
        send_goal_future = self._action_client.send_goal_async(
            goal_msg, feedback_callback=self.feedback_callback)
        send_goal_future.add_done_callback(self.goal_response_callback)

    def goal_response_callback(self, future):
        goal_handle = future.result()
        if not goal_handle.accepted:
            self.get_logger().info('目标请求被拒绝')
            return
        self.get_logger().info('目标请求成功')
        goal_handle.get_result_async().add_done_callback(self.get_result_callback)

    def feedback_callback(self, feedback_msg):
        self.get_logger().info(f'摄像头状态：{feedback_msg.feedback.state}')

    def get_result_callback(self, future):
        self.get_logger().info(f'动作结果：{future.result().result.finish}')

    # ---- 话题 face_image ----
    def image_callback(self, msg):
        self.last_frame = self.cv_bridge.imgmsg_to_cv2(msg, 'bgr8')
        if self.get_parameter('show_window').value:
            cv2.imshow('facer', self.last_frame)
            cv2.waitKey(1)


def main(args=None):
    rclpy.init(args=args)
    node = VisualInteraction()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
