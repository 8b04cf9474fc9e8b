"""The import hook: rclpy / interface packages / rosidl_runtime_py resolve to labkit."""
import os
import subprocess
import sys
import textwrap

import pytest

from labkit import compat


@pytest.fixture
def hook():
    assert compat.activate(quiet=True)
    yield
    compat.deactivate()


def test_interface_packages_resolve_to_labkit_classes(hook):
    import labkit.interfaces as ifc
    from std_msgs.msg import String
    from turtlesim.action import RotateAbsolute
    from turtlesim.srv import Spawn
    assert String is ifc.get_type('std_msgs/msg/String')
    assert Spawn is ifc.get_type('turtlesim/srv/Spawn')
    assert RotateAbsolute is ifc.get_type('turtlesim/action/RotateAbsolute')
    assert repr(String(data='hi')) == "std_msgs.msg.String(data='hi')"


def test_unknown_names_still_fail(hook):
    with pytest.raises(ImportError):
        import labkit_no_such_pkg  # noqa: F401
    with pytest.raises(ImportError):
        import std_msgs.nothing  # noqa: F401
    with pytest.raises(ImportError):
        from turtlesim.msg import NoSuchMessage  # noqa: F401


def test_rclpy_alias_is_the_same_module_object(hook):
    import rclpy.qos
    import labkit.rclpy.qos
    assert rclpy.qos is labkit.rclpy.qos
    assert rclpy.qos.__name__ == 'labkit.rclpy.qos'  # the module keeps its own identity


def test_rosidl_runtime_py_stand_ins(hook):
    from rosidl_runtime_py import message_to_yaml
    from rosidl_runtime_py.set_message import set_message_fields
    from rosidl_runtime_py.utilities import get_message, get_service
    twist_cls = get_message('geometry_msgs/Twist')
    twist = twist_cls()
    set_message_fields(twist, {'linear': {'x': 2.0}})
    assert message_to_yaml(twist).startswith('linear:\n  x: 2.0\n')
    assert get_service('turtlesim/srv/Spawn').Request
    with pytest.raises(ValueError,
                       match="Expected the full name of a message, got 'turtlesim/srv/Spawn'"):
        get_message('turtlesim/srv/Spawn')


def test_deactivate_removes_the_hook():
    compat.activate(quiet=True)
    import std_msgs.msg  # noqa: F401
    compat.deactivate()
    assert 'std_msgs.msg' not in sys.modules
    assert not compat.is_active()
    with pytest.raises(ImportError):
        import std_msgs  # noqa: F401


def test_share_path_packages_are_importable(tmp_path, hook):
    import labkit.interfaces as ifc
    from labkit.interfaces import registry
    msg_dir = tmp_path / 'clitest_interfaces' / 'msg'
    msg_dir.mkdir(parents=True)
    (msg_dir / 'Face.msg').write_text('int32 x\nint32 y\n')
    ifc.add_share_path(str(tmp_path))
    try:
        from clitest_interfaces.msg import Face
        assert Face(x=1).x == 1
    finally:
        registry.remove_share_path(str(tmp_path))


def test_a_sourced_ros_is_never_shadowed(tmp_path):
    fake = tmp_path / 'opt' / 'lib' / 'python3' / 'site-packages'
    (fake / 'rclpy').mkdir(parents=True)
    (fake / 'rclpy' / '__init__.py').write_text('REAL = True\n')
    code = textwrap.dedent('''
        from labkit import compat
        print(compat.activate())
        import rclpy
        print(getattr(rclpy, 'REAL', False))
    ''')
    env = dict(os.environ, AMENT_PREFIX_PATH=str(tmp_path / 'opt'), PYTHONPATH=str(fake))
    done = subprocess.run([sys.executable, '-c', code], env=env, capture_output=True, text=True)
    assert done.stdout.split() == ['False', 'True']
    assert 'sourced ROS 2' in done.stderr and len(done.stderr.strip().splitlines()) == 1


def test_rclpy_serialization_through_the_hook(hook):
    from geometry_msgs.msg import Twist
    from rclpy.serialization import deserialize_message, serialize_message
    data = serialize_message(Twist())
    assert len(data) == 52 and deserialize_message(data, Twist) == Twist()
