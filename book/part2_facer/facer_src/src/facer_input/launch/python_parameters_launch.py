"""启动 capture_image，并把 timer_period 参数设为 1.0 秒."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='facer_input',
            executable='capture_image',
            name='capture_image',
            output='screen',
            emulate_tty=True,
            parameters=[{'timer_period': 1.0}],
        ),
    ])
