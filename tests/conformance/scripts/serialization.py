"""Conformance: CDR bytes of rclpy.serialization.serialize_message, and round trips.

Plain rclpy: runs unchanged on ROS 2 Humble (same XCDR1 little-endian encoding).
Reference note: Fast CDR leaves alignment padding bytes uninitialised (random values);
the expected file has them as 00 (record.py re-encodes each line with rosbags to find them).
The length is rmw_fastrtps's estimate (see record.py): fixed-size types are rounded up to
4 bytes, and JointState with an empty float64[] gets 8 trailing bytes, in Humble and Jazzy.
Humble/Jazzy: Log(level=Log.INFO) fails on Humble, whose
Log.INFO is a byte constant (b'\x14'), so the level is given as 20.
"""
from builtin_interfaces.msg import Time
from geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion, Twist, Vector3
from rcl_interfaces.msg import Log
from rclpy.serialization import deserialize_message, serialize_message
from sensor_msgs.msg import Image, JointState, LaserScan
from std_msgs.msg import (Bool, Byte, Char, Empty, Float32, Float64, Header, Int8, Int16, Int64,
                          Int32MultiArray, MultiArrayDimension, MultiArrayLayout, String, UInt8,
                          UInt16, UInt64)
from std_srvs.srv import SetBool


def type_name(msg):
    package, kind = type(msg).__module__.split('.')[:2]
    return f'{package}/{kind}/{type(msg).__name__}'


def show(label, msg):
    data = serialize_message(msg)
    print(f'{label} [{type_name(msg)}]: {len(data)} {data.hex()}')
    back = deserialize_message(data, type(msg))
    if back != msg:
        print(f'{label}: ROUND TRIP MISMATCH {back!r}')


def main():
    show('Empty', Empty())
    show('Bool', Bool(data=True))
    show('Byte', Byte(data=b'\xab'))
    show('Char', Char(data=200))
    show('Int8', Int8(data=-2))
    show('UInt8', UInt8(data=254))
    show('Int16', Int16(data=-300))
    show('UInt16', UInt16(data=65000))
    show('Int64', Int64(data=-(2 ** 40)))
    show('UInt64', UInt64(data=2 ** 64 - 1))
    show('Float32', Float32(data=1.5))
    show('Float64', Float64(data=-0.1))
    show('String empty', String())
    show('String', String(data='hello'))
    show('String utf8', String(data='你好'))
    show('Time', Time(sec=1704067200, nanosec=123456789))
    show('Header', Header(stamp=Time(sec=1, nanosec=2), frame_id='map'))
    show('Vector3', Vector3(x=1.0, y=-2.0, z=0.5))
    show('Twist', Twist(linear=Vector3(x=2.0), angular=Vector3(z=1.8)))
    show('PoseStamped', PoseStamped(header=Header(frame_id='odom'),
                                    pose=Pose(position=Point(x=1.0),
                                              orientation=Quaternion(w=1.0))))
    show('JointState', JointState(name=['j1', 'j22'], position=[0.1, 0.2], velocity=[],
                                  effort=[1.0]))
    show('Image', Image(header=Header(frame_id='cam'), height=2, width=2, encoding='mono8',
                        step=2, data=bytes([1, 2, 3, 4])))
    show('LaserScan', LaserScan(angle_min=-1.0, angle_max=1.0, ranges=[1.0, 2.0, float('inf')],
                                intensities=[]))
    show('Int32MultiArray', Int32MultiArray(
        layout=MultiArrayLayout(dim=[MultiArrayDimension(label='x', size=3, stride=3)]),
        data=[-1, 0, 1]))
    show('Log', Log(stamp=Time(sec=5), level=20, name='talker', msg='Publishing: "hi"',
                    file='talker.py', function='cb', line=42))
    show('SetBool.Request', SetBool.Request(data=True))
    show('SetBool.Response', SetBool.Response(success=True, message='ok'))

    data = serialize_message(String(data='round trip'))
    print('deserialize:', deserialize_message(data, String))
    print('type of serialized:', type(data).__name__)
    try:
        serialize_message('not a message')
    except Exception as e:  # noqa: B902 - the class name is what we check
        print('serialize non-message:', type(e).__name__)
    print('done')


if __name__ == '__main__':
    main()
