"""A facer-like workspace on disk, written as a learner would (real package files).

facer_interfaces (ament_cmake: msg/Face.msg, srv/FaceResult.srv),
facer_input and facer_detect (ament_python, console_scripts, a launch file),
facer_bringup (ament_python, launch file + params YAML).
"""
import os
import textwrap

PACKAGE_XML = """<?xml version="1.0"?>
<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
<package format="3">
  <name>{name}</name>
  <version>0.0.0</version>
  <description>{name}</description>
  <maintainer email="learner@example.com">learner</maintainer>
  <license>Apache-2.0</license>
{deps}
  <export>
    <build_type>{build_type}</build_type>
  </export>
</package>
"""

SETUP_PY = """from setuptools import find_packages, setup
import os
from glob import glob

package_name = '{name}'

setup(
    name=package_name,
    version='0.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
        (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='learner',
    maintainer_email='learner@example.com',
    description='{name}',
    license='Apache-2.0',
    entry_points={{
        'console_scripts': [
{scripts}
        ],
    }},
)
"""

SETUP_CFG = """[develop]
script_dir=$base/lib/{name}
[install]
install_scripts=$base/lib/{name}
"""

INTERFACES_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(facer_interfaces)

find_package(ament_cmake REQUIRED)
find_package(geometry_msgs REQUIRED)
find_package(rosidl_default_generators REQUIRED)

rosidl_generate_interfaces(${PROJECT_NAME}
  "msg/Face.msg"
  "srv/FaceResult.srv"
  DEPENDENCIES geometry_msgs
)

if(BUILD_TESTING)
  find_package(ament_lint_auto REQUIRED)
  ament_lint_auto_find_test_dependencies()
endif()

ament_package()
"""

CAPTURE = '''import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class CaptureImage(Node):
    def __init__(self):
        super().__init__('capture_image')
        self.declare_parameter('camera', 'cam0')
        self.pub = self.create_publisher(String, 'image_path', 10)
        self.get_logger().info('VERSION 1 camera=%s' % self.get_parameter('camera').value)


def main(args=None):
    rclpy.init(args=args)
    node = CaptureImage()
    node.destroy_node()
    rclpy.shutdown()
'''

DETECT = '''import rclpy
from rclpy.node import Node
from facer_interfaces.srv import FaceResult


def main(args=None):
    rclpy.init(args=args)
    node = Node('detect_face')
    node.get_logger().info('fields: %s' % list(FaceResult.Response.get_fields_and_field_types()))
    node.destroy_node()
    rclpy.shutdown()
'''


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(textwrap.dedent(text) if text.startswith('\n') else text)
    return path


def deps_xml(tags):
    return ''.join(f'  <{tag}>{dep}</{tag}>\n' for tag, dep in tags)


def python_package(src, name, scripts, deps=(), modules=None):
    root = os.path.join(src, name)
    write(root, 'package.xml', PACKAGE_XML.format(
        name=name, build_type='ament_python', deps=deps_xml(list(deps) + [
            ('test_depend', 'python3-pytest')])))
    write(root, 'setup.py', SETUP_PY.format(name=name, scripts='\n'.join(
        f"            '{exe} = {target}'," for exe, target in scripts)))
    write(root, 'setup.cfg', SETUP_CFG.format(name=name))
    write(root, f'resource/{name}', '')
    write(root, f'{name}/__init__.py', '')
    for module, text in (modules or {}).items():
        write(root, f'{name}/{module}.py', text)
    return root


def interfaces_package(src, name='facer_interfaces'):
    root = os.path.join(src, name)
    write(root, 'package.xml', PACKAGE_XML.format(
        name=name, build_type='ament_cmake', deps=deps_xml([
            ('buildtool_depend', 'ament_cmake'),
            ('buildtool_depend', 'rosidl_default_generators'),
            ('depend', 'geometry_msgs'),
            ('exec_depend', 'rosidl_default_runtime'),
            ('test_depend', 'ament_lint_auto'),
            ('member_of_group', 'rosidl_interface_packages')])))
    write(root, 'CMakeLists.txt', INTERFACES_CMAKE)
    write(root, 'msg/Face.msg', 'geometry_msgs/Point center\nfloat32 radius\n')
    write(root, 'srv/FaceResult.srv', 'string image_path\n---\nFace[] faces\nint32 count\n')
    return root


BRINGUP_LAUNCH = '''from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from ament_index_python.packages import get_package_share_directory
import os


def generate_launch_description():
    params = os.path.join(get_package_share_directory('facer_bringup'), 'config', 'facer.yaml')
    return LaunchDescription([
        DeclareLaunchArgument('camera', default_value='cam0'),
        Node(package='facer_input', executable='capture_image', name='capture_image',
             parameters=[params, {'camera': LaunchConfiguration('camera')}],
             output='screen'),
        Node(package='facer_detect', executable='detect_face', output='screen'),
    ])
'''

FACER_YAML = '''capture_image:
  ros__parameters:
    camera: from_yaml
'''


def facer_workspace(ws):
    """Write the 4-package workspace under `ws`/src; returns the src folder."""
    src = os.path.join(ws, 'src')
    interfaces_package(src)
    python_package(src, 'facer_input', [('capture_image', 'facer_input.capture_image:main')],
                   deps=[('depend', 'rclpy'), ('depend', 'std_msgs')],
                   modules={'capture_image': CAPTURE})
    python_package(src, 'facer_detect', [('detect_face', 'facer_detect.detect_face:main')],
                   deps=[('depend', 'rclpy'), ('depend', 'facer_interfaces'),
                         ('exec_depend', 'python3-opencv')],
                   modules={'detect_face': DETECT})
    bringup = python_package(src, 'facer_bringup', [],
                             deps=[('exec_depend', 'facer_input'),
                                   ('exec_depend', 'facer_detect'),
                                   ('exec_depend', 'launch_ros')])
    write(bringup, 'launch/facer.launch.py', BRINGUP_LAUNCH)
    write(bringup, 'config/facer.yaml', FACER_YAML)
    return src
