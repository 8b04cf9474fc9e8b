"""turtlesim, a pose_to_tf for each turtle, and a chaser heading for `target`."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def frame_of(turtle):
    return Node(package='turtle_tf2_demo', executable='pose_to_tf',
                name=f'{turtle}_tf', parameters=[{'turtle': turtle}])


def generate_launch_description():
    target = DeclareLaunchArgument('target', default_value='turtle1',
                                   description='The frame turtle2 drives to.')
    return LaunchDescription([
        target,
        Node(package='turtlesim', executable='turtlesim_node', name='sim'),
        frame_of('turtle1'),
        frame_of('turtle2'),
        Node(package='turtle_tf2_demo', executable='chaser', name='chaser',
             parameters=[{'target': LaunchConfiguration('target')}]),
    ])
