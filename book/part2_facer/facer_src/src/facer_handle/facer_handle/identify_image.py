"""identify_image 节点：facer 机器人的处理模块。

- 话题 frame_image 的订阅者：用 OpenCV 的 Haar 级联分类器在每一帧里找人脸；
- 话题 face_image 的发布者：框出人脸的图像，供输出模块显示；
- 服务 face_result 的服务端：回答最新一帧的识别结果。
"""
import cv2
import rclpy
from cv_bridge import CvBridge
from rclpy.node import Node
from sensor_msgs.msg import Image

from facer_interfaces.srv import FaceResult

NO_FACE = '未检测到人脸'


class IdentifyImage(Node):

    def __init__(self):
        super().__init__('identify_image')
        self.cv_bridge = CvBridge()
        # OpenCV 自带训练好的模型文件，cv2.data.haarcascades 是它们所在的文件夹
        self.face_classifier = cv2.CascadeClassifier(
            cv2.data.haarcascades + 'haarcascade_frontalface_default.xml')
        self.result = NO_FACE
        self.subscription = self.create_subscription(
            Image, 'frame_image', self.listener_callback, 10)
        self.face_publisher = self.create_publisher(Image, 'face_image', 10)
        self.srv = self.create_service(FaceResult, 'face_result', self.face_result_callback)

    def listener_callback(self, msg):
        frame = self.cv_bridge.imgmsg_to_cv2(msg, 'bgr8')  # ROS 图像消息 -> OpenCV 图像
        gray = cv2.cvtColor(frame, cv2.COLOR_BGR2GRAY)
        faces = self.face_classifier.detectMultiScale(
            gray, scaleFactor=1.1, minNeighbors=5, minSize=(30, 30))
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
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
