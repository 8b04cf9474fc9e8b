"""Look at a facer model: robot_state_publisher, the joint sliders and RViz.

    ros2 launch facer_description display.launch.py model:=urdf/06-pan-joint.urdf

`model` is a path inside this package's share folder, or an absolute path. It goes
through xacro first, so .urdf and .urdf.xacro files both work.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('facer_description')
    gui = LaunchConfiguration('gui')

    arguments = [
        DeclareLaunchArgument(
            'model', default_value='urdf/01-one-shape.urdf',
            description='URDF or xacro file, relative to the facer_description share folder'),
        DeclareLaunchArgument(
            'gui', default_value='true', choices=['true', 'false'],
            description='Slider window (joint_state_publisher_gui) or none'),
        DeclareLaunchArgument(
            'rvizconfig', default_value=PathJoinSubstitution([share, 'rviz', 'facer.rviz']),
            description='RViz configuration file'),
    ]

    # xacro prints the URDF text; ParameterValue keeps it a plain string (not YAML)
    urdf_text = Command(['xacro ', PathJoinSubstitution([share, LaunchConfiguration('model')])])

    nodes = [
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': ParameterValue(urdf_text, value_type=str)}]),
        Node(package='joint_state_publisher_gui', executable='joint_state_publisher_gui',
             condition=IfCondition(gui)),
        Node(package='joint_state_publisher', executable='joint_state_publisher',
             condition=UnlessCondition(gui)),
        Node(package='rviz2', executable='rviz2', name='rviz2', output='screen',
             arguments=['-d', LaunchConfiguration('rvizconfig')]),
    ]
    return LaunchDescription(arguments + nodes)
