"""
一次启动 facer 的三个节点，参数来自 config/facer_params.yaml.

    ros2 launch facer_input facer_bringup_launch.py               # 视频 facer_crowd.avi
    ros2 launch facer_input facer_bringup_launch.py source:=0     # 真机：0 号摄像头
    ros2 launch facer_input facer_bringup_launch.py source:=/home/me/facer_sample.avi

source 的默认值 facer_crowd.avi 是相对路径，相对于运行 ros2 launch 的那个目录；
两段示例视频在本书源码的 book/part2_facer/media/ 里，先复制到那个目录，或者给出绝对路径。
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    params_file = os.path.join(
        get_package_share_directory('facer_input'), 'config', 'facer_params.yaml')
    source = DeclareLaunchArgument(
        'source', default_value='facer_crowd.avi',
        description='图像来源：摄像头编号（如 0）或视频文件的路径')
    camera = Node(
        package='facer_input', executable='capture_image', output='screen',
        # 后面的字典覆盖参数文件里的同名参数
        parameters=[params_file, {'source': LaunchConfiguration('source')}])
    detector = Node(
        package='facer_handle', executable='identify_image', output='screen',
        parameters=[params_file])
    display = Node(
        package='facer_output', executable='visual_interaction', output='screen',
        parameters=[params_file])
    return LaunchDescription([source, camera, detector, display])
