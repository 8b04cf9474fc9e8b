"""chase.launch.py aimed at carrot1, plus the carrot: `orbit:=true` makes it circle."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PythonExpression
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    orbit = LaunchConfiguration('orbit')
    chase = PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('turtle_tf2_demo'), 'launch', 'chase.launch.py']))
    return LaunchDescription([
        DeclareLaunchArgument('orbit', default_value='false',
                              description='true: carrot1 circles turtle1 (radius 2 m).'),
        IncludeLaunchDescription(chase, launch_arguments={'target': 'carrot1'}.items()),
        Node(package='turtle_tf2_demo', executable='carrot', name='carrot',
             parameters=[{'radius': PythonExpression(
                 ["2.0 if '", orbit, "'.lower() == 'true' else 0.0"])}]),
    ])
