"""
identify_image 节点：facer 机器人的处理模块.

- 话题 frame_image 的订阅者：用 OpenCV 的 Haar 级联分类器在每一帧里找人脸；
- 话题 face_image 的发布者：框出人脸的图像，供输出模块显示；
- 服务 face_result 的服务端：回答最新一帧的识别结果。

参数（检测器的三个旋钮，每一帧都重新读取，ros2 param set 之后下一帧就生效）：
- scale_factor (double, 默认 1.1, 1.01～2.0)：相邻两次搜索之间窗口放大的倍数；
- min_neighbors (int, 默认 5, 0～50)：一个框至少要有几个相邻的候选框支持才算数；
- min_size (int, 默认 30, 10～480)：人脸框的最小边长（像素）。
"""
import os

from ament_index_python.packages import get_package_share_directory, PackageNotFoundError
import cv2
from cv_bridge import CvBridge
from facer_interfaces.srv import FaceResult
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from sensor_msgs.msg import Image

NO_FACE = '未检测到人脸'
CASCADE = 'haarcascade_frontalface_default.xml'


def find_cascade():
    """人脸模型文件的路径：先找随功能包安装的，再找 opencv-data 的，最后找 pip 版 OpenCV 的."""
    folders = []
    try:
        folders.append(os.path.join(get_package_share_directory('facer_handle'), 'data'))
    except PackageNotFoundError:
        pass
    folders.append('/usr/share/opencv4/haarcascades')  # sudo apt install opencv-data
    if hasattr(cv2, 'data'):  # pip 安装的 opencv-python 自带一份；Ubuntu 的 python3-opencv 没有
        folders.append(cv2.data.haarcascades)
    for folder in folders:
        path = os.path.join(folder, CASCADE)
        if os.path.isfile(path):
            return path
    return None


class IdentifyImage(Node):

    def __init__(self):
        super().__init__('identify_image')
        self.declare_parameter('scale_factor', 1.1, ParameterDescriptor(
            description='检测窗口每次放大的倍数：越接近 1 越细致，也越慢',
            floating_point_range=[FloatingPointRange(from_value=1.01, to_value=2.0)]))
        self.declare_parameter('min_neighbors', 5, ParameterDescriptor(
            description='一个框至少要有几个相邻候选框支持：越大越不容易误报',
            integer_range=[IntegerRange(from_value=0, to_value=50, step=1)]))
        self.declare_parameter('min_size', 30, ParameterDescriptor(
            description='人脸框的最小边长（像素）：更小的脸不检测',
            integer_range=[IntegerRange(from_value=10, to_value=480, step=1)]))

        path = find_cascade()
        self.face_classifier = cv2.CascadeClassifier(path) if path else cv2.CascadeClassifier()
        # 文件读不出来时 OpenCV 并不报错，只得到一个“空”分类器，要自己检查
        if self.face_classifier.empty():
            raise RuntimeError(
                f'找不到人脸模型 {CASCADE}：把它放进功能包的 data 文件夹重新构建，'
                '或者 sudo apt install opencv-data')

        self.cv_bridge = CvBridge()
        self.result = NO_FACE
        self.subscription = self.create_subscription(
            Image, 'frame_image', self.listener_callback, 10)
        self.face_publisher = self.create_publisher(Image, 'face_image', 10)
        self.srv = self.create_service(FaceResult, 'face_result', self.face_result_callback)

    def listener_callback(self, msg):
        frame = self.cv_bridge.imgmsg_to_cv2(msg, 'bgr8')  # ROS 图像消息 -> OpenCV 图像
        gray = cv2.cvtColor(frame, cv2.COLOR_BGR2GRAY)
        size = self.get_parameter('min_size').value
        faces = self.face_classifier.detectMultiScale(
            gray,
            scaleFactor=self.get_parameter('scale_factor').value,
            minNeighbors=self.get_parameter('min_neighbors').value,
            minSize=(size, size))
        # 每一帧都重新给出结果：上一帧有人脸，不代表这一帧也有
        self.result = f'检测到 {len(faces)} 张人脸' if len(faces) else NO_FACE
        annotated = frame.copy()  # 不在收到的消息上作画
        for (x, y, w, h) in faces:
            cv2.rectangle(annotated, (int(x), int(y)), (int(x + w), int(y + h)), (0, 255, 0), 2)
        self.face_publisher.publish(
            self.cv_bridge.cv2_to_imgmsg(annotated, 'bgr8', header=msg.header))

    def face_result_callback(self, request, response):
        # 服务回调必须总是返回响应对象，不论请求是什么
        response.get_result = self.result if request.apply_result else ''
        return response


def main(args=None):
    rclpy.init(args=args)
    node = IdentifyImage()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
