"""Conformance: generated message classes (repr, equality, defaults, field type
assertions, constants, nested and array fields, services' Request/Response).

Plain rclpy: runs unchanged on ROS 2 Humble (field checks on, as under Humble's
`__debug__`; the Jazzy reference runs with ROS_PYTHON_CHECK_FIELDS=1 for the same).
Humble/Jazzy (the expected file keeps Humble's): Jazzy adds '_check_fields' to __slots__;
Humble's rcl_interfaces/Log declares its level constants as `byte` (Log.INFO == b'\x14'),
Jazzy's as uint8 (20).
"""
import array
import copy

import numpy
from action_msgs.msg import GoalStatus
from builtin_interfaces.msg import Duration, Time
from geometry_msgs.msg import Point, Pose, PoseWithCovariance, Twist, Vector3
from rcl_interfaces.msg import Log
from sensor_msgs.msg import Image, JointState
from std_msgs.msg import (Bool, Byte, Char, ColorRGBA, Float32, Float64, Header, Int8, Int32,
                          Int64, MultiArrayDimension, String, UInt8, UInt8MultiArray, UInt64)
from std_srvs.srv import SetBool, Trigger


def attempt(label, fn):
    try:
        value = fn()
        print(f'{label}: ok {value!r}')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print(f'{label}: {type(e).__name__}: {e}')


def assign(msg, field, value):
    setattr(msg, field, value)
    return getattr(msg, field)


def main():
    # repr of defaults and of filled messages
    for cls in (String, Bool, Byte, Char, Int8, Int32, UInt64, Float32, Float64, Header,
                ColorRGBA, Vector3, Twist, Time, Duration, GoalStatus, MultiArrayDimension):
        print(repr(cls()))
    print(String(data='hello world'))
    print(Twist(linear=Vector3(x=2.0), angular=Vector3(z=1.8)))
    print(Header(stamp=Time(sec=12, nanosec=500), frame_id='base_link'))
    print(JointState(name=['a', 'b'], position=[0.5, -1.0]))
    print(UInt8MultiArray(data=[1, 2, 255]))
    print(Image(height=1, width=2, encoding='rgb8', step=6, data=bytes(range(6))))
    print(str(String(data="it's")))

    # module, class name, slots, fields and types
    print(String.__module__, String.__name__, String.__qualname__)
    print(Twist.__module__, JointState.__module__, GoalStatus.__module__)
    print('slots:', String.__slots__, Header.__slots__)
    print('fields:', String.get_fields_and_field_types())
    print('fields:', Header.get_fields_and_field_types())
    print('fields:', JointState.get_fields_and_field_types())
    print('fields:', Image.get_fields_and_field_types())
    print('fields:', PoseWithCovariance.get_fields_and_field_types())
    print('fields:', UInt8MultiArray.get_fields_and_field_types())
    print('fields:', GoalStatus.get_fields_and_field_types())
    print('byte constants:', repr(Log.INFO), repr(Log.ERROR))
    print('constants:', GoalStatus.STATUS_SUCCEEDED, GoalStatus.STATUS_ABORTED,
          sorted(k for k in dir(GoalStatus) if k.startswith('STATUS_')))

    # equality and copies
    a = Twist(linear=Vector3(x=1.0))
    b = Twist(linear=Vector3(x=1.0))
    print('equal:', a == b, 'identical:', a is b, 'not equal:', a != Twist())
    print('different class:', String(data='1') == Int32(data=1))
    c = copy.deepcopy(a)
    c.linear.x = 3.0
    print('deepcopy independent:', a.linear.x, c.linear.x)
    print('__hash__ is None:', String.__hash__ is None)

    # storage types of array fields
    js = JointState(position=[1.0, 2.0])
    print('float64[] storage:', type(js.position).__name__, js.position.typecode)
    img = Image(data=[1, 2, 3])
    print('uint8[] storage:', type(img.data).__name__, img.data.typecode, list(img.data))
    img.data = b'\x04\x05'
    print('uint8[] from bytes:', type(img.data).__name__, list(img.data))
    pwc = PoseWithCovariance()
    print('float64[36] storage:', type(pwc.covariance).__name__, pwc.covariance.dtype,
          pwc.covariance.shape)
    print('string[] storage:', type(JointState(name=['x']).name).__name__)
    print('char/byte:', repr(Char(data=65).data), repr(Byte(data=b'\x01').data))

    # field type assertions (Humble __debug__ checks)
    attempt('String(data=1)', lambda: String(data=1))
    attempt('String(text="x")', lambda: String(text='x'))
    attempt('Int32(data=2**31)', lambda: Int32(data=2 ** 31))
    attempt('Int32(data=1.5)', lambda: Int32(data=1.5))
    attempt('Int8(data=-129)', lambda: Int8(data=-129))
    attempt('UInt8(data=-1)', lambda: UInt8(data=-1))
    attempt('Int64(data=2**63)', lambda: Int64(data=2 ** 63))
    attempt('Float64(data=1)', lambda: Float64(data=1))
    attempt('Float64(data="1")', lambda: Float64(data='1'))
    attempt('Float32(data=1e39)', lambda: Float32(data=1e39))
    attempt('Float64(data=inf)', lambda: Float64(data=float('inf')).data)
    attempt('Bool(data=1)', lambda: Bool(data=1))
    attempt('Twist(linear=Point())', lambda: Twist(linear=Point()))
    attempt('twist.linear.x = "fast"', lambda: assign(Twist().linear, 'x', 'fast'))
    attempt('JointState(name="abc")', lambda: JointState(name='abc'))
    attempt('JointState(name=[1])', lambda: JointState(name=[1]))
    attempt('JointState(position=[1, 2]).position',
            lambda: list(JointState(position=[1, 2]).position))
    attempt('js.position = [1, 2]', lambda: assign(JointState(), 'position', [1, 2]))
    attempt('js.position = [1.0, 2.0]',
            lambda: list(assign(JointState(), 'position', [1.0, 2.0])))
    attempt('js.position = array i',
            lambda: assign(JointState(), 'position', array.array('i', [1])))
    attempt('Image(data=[256])', lambda: Image(data=[256]))
    attempt('img.data = [256]', lambda: assign(Image(), 'data', [256]))
    attempt('img.data = "abc"', lambda: assign(Image(), 'data', 'abc'))
    attempt('pwc.covariance = [0.0] * 3',
            lambda: assign(PoseWithCovariance(), 'covariance', [0.0] * 3))
    attempt('pwc.covariance = ndarray float32',
            lambda: assign(PoseWithCovariance(), 'covariance', numpy.zeros(36, numpy.float32)))
    attempt('pwc.covariance = ndarray 3',
            lambda: assign(PoseWithCovariance(), 'covariance', numpy.zeros(3)))
    attempt('pwc.covariance = [1.0] * 36',
            lambda: type(assign(PoseWithCovariance(), 'covariance', [1.0] * 36)).__name__)
    attempt('Header(stamp=5)', lambda: Header(stamp=5))
    attempt('String().foo = 1', lambda: assign(String(), 'foo', 1))
    attempt('Pose().position.w', lambda: Pose().position.w)

    # services
    print(SetBool.Request(data=True), SetBool.Response(success=True, message='ok'))
    print(Trigger.Request(), Trigger.Response())
    print(SetBool.Request.__module__, SetBool.Request.__name__, SetBool.__name__)
    print('print done')


if __name__ == '__main__':
    main()
