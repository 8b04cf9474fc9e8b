"""Record what real rclpy does, as a fixture for tests/interfaces (run by hand, not by pytest).

Run with a real rclpy (Jazzy wheels; Humble behaves the same for what is recorded):
    LD_LIBRARY_PATH=<venv>/lib <venv>/bin/python make_rclpy_reference.py OUT.json
Recorded: CDR bytes of test_msgs fixtures and common messages, their repr(), class
metadata, and assertion texts for bad assignments.
"""
import json
import os
import sys

os.environ.setdefault('ROS_PYTHON_CHECK_FIELDS', '1')  # Jazzy checks fields only when asked

from rclpy.serialization import serialize_message  # noqa: E402
from test_msgs import message_fixtures  # noqa: E402


def type_name(msg):
    mod = type(msg).__module__.split('.')
    return '%s/%s/%s' % (mod[0], mod[1], type(msg).__name__)


def sample_messages():
    msgs = []
    for name in dir(message_fixtures):
        if name.startswith('get_msg_'):
            msgs += getattr(message_fixtures, name)()
    from geometry_msgs.msg import Twist, Pose, PoseStamped, TransformStamped
    from sensor_msgs.msg import Image, JointState, LaserScan
    from std_msgs.msg import String, Header, Float64MultiArray, MultiArrayDimension
    from rcl_interfaces.msg import Log, ParameterEvent, Parameter, ParameterValue
    from nav_msgs.msg import Odometry
    t = Twist()
    t.linear.x, t.angular.z = 2.0, 1.8
    msgs.append(t)
    p = Pose()
    p.position.x, p.position.y, p.orientation.w = 1.5, -2.25, 1.0
    msgs.append(p)
    ps = PoseStamped()
    ps.header.frame_id, ps.header.stamp.sec, ps.header.stamp.nanosec = 'map', 12, 345
    msgs.append(ps)
    ts = TransformStamped()
    ts.header.frame_id, ts.child_frame_id = 'world', 'turtle1'
    ts.transform.translation.x = 5.5
    ts.transform.rotation.w = 1.0
    msgs.append(ts)
    img = Image(height=2, width=3, encoding='bgr8', step=9, data=list(range(18)))
    img.header.frame_id = 'camera'
    msgs.append(img)
    msgs.append(JointState(name=['a', 'bb'], position=[0.5, -1.0], velocity=[], effort=[1.0]))
    msgs.append(LaserScan(angle_min=-1.5, ranges=[1.0, 2.5, float('inf')], intensities=[]))
    msgs += [String(data=''), String(data='hello'), String(data='你好 ROS 2'), Header()]
    msgs.append(Float64MultiArray(data=[1.0, 2.0, 3.0]))
    msgs[-1].layout.dim = [MultiArrayDimension(label='x', size=3, stride=3)]
    msgs.append(Log(level=20, name='talker', msg='Publishing: "Hello World: 1"', file='a.py',
                    function='cb', line=42))
    ev = ParameterEvent(node='/turtlesim')
    ev.changed_parameters = [Parameter(name='background_r', value=ParameterValue(
        type=2, integer_value=150))]
    msgs.append(ev)
    od = Odometry(child_frame_id='base_link')
    od.pose.covariance[0] = 0.1
    od.twist.covariance[35] = 0.2
    msgs.append(od)
    return msgs


BAD_ASSIGNMENTS = [
    # (type, field, python expression of the value)
    ('geometry_msgs/msg/Vector3', 'x', '1'),
    ('geometry_msgs/msg/Vector3', 'x', "'a'"),
    ('geometry_msgs/msg/Vector3', 'x', '1e309 * 0 + 2e308'),
    ('std_msgs/msg/String', 'data', '5'),
    ('std_msgs/msg/Int8', 'data', '200'),
    ('std_msgs/msg/UInt8', 'data', '-1'),
    ('std_msgs/msg/Int32', 'data', '2.0'),
    ('std_msgs/msg/UInt64', 'data', '2 ** 64'),
    ('std_msgs/msg/Float32', 'data', '1e39'),
    ('std_msgs/msg/Float32', 'data', '1'),
    ('std_msgs/msg/Bool', 'data', '1'),
    ('std_msgs/msg/Byte', 'data', "b'ab'"),
    ('std_msgs/msg/Char', 'data', "'a'"),
    ('std_msgs/msg/Header', 'stamp', '1.0'),
    ('geometry_msgs/msg/Twist', 'linear', 'None'),
    ('sensor_msgs/msg/Image', 'data', "'abc'"),
    ('sensor_msgs/msg/Image', 'data', '[256]'),
    ('sensor_msgs/msg/JointState', 'name', '[1]'),
    ('sensor_msgs/msg/JointState', 'position', '[1]'),
    ('sensor_msgs/msg/JointState', 'position', "array.array('f', [1.0])"),
    ('nav_msgs/msg/Odometry', 'pose', '1'),
    ('geometry_msgs/msg/PoseWithCovariance', 'covariance', '[0.0] * 35'),
    ('geometry_msgs/msg/PoseWithCovariance', 'covariance', 'numpy.zeros(36, dtype=numpy.float32)'),
    ('geometry_msgs/msg/PoseWithCovariance', 'covariance', 'numpy.zeros(35)'),
    ('test_msgs/msg/BoundedSequences', 'int32_values', '[1, 2, 3, 4]'),
    ('test_msgs/msg/BoundedSequences', 'int32_values', "array.array('i', [1, 2, 3, 4])"),
    ('test_msgs/msg/BoundedSequences', 'string_values', "['a'] * 4"),
    ('test_msgs/msg/BoundedSequences', 'float32_values', '[1e39]'),
    ('test_msgs/msg/BoundedSequences', 'float64_values', "[1]"),
    ('test_msgs/msg/BoundedSequences', 'uint8_values', '[300]'),
    ('test_msgs/msg/BoundedSequences', 'int8_values', '[300]'),
    ('test_msgs/msg/BoundedSequences', 'bool_values', '[1]'),
    ('test_msgs/msg/BoundedSequences', 'byte_values', '[1]'),
    ('test_msgs/msg/BoundedSequences', 'basic_types_values', '[1]'),
    ('test_msgs/msg/Arrays', 'bool_values', '[True]'),
    ('test_msgs/msg/Arrays', 'string_values', "['a', 'b']"),
    ('test_msgs/msg/Arrays', 'byte_values', "[b'a']"),
    ('test_msgs/msg/Arrays', 'basic_types_values', '[]'),
    ('test_msgs/msg/Strings', 'bounded_string_value', "'x' * 23"),
    ('test_msgs/msg/Strings', 'bounded_string_value', '1'),
    ('test_msgs/msg/BasicTypes', 'char_value', "'a'"),
    ('test_msgs/msg/BasicTypes', 'byte_value', '1'),
    ('test_msgs/msg/UnboundedSequences', 'string_values', "'abc'"),
    ('test_msgs/msg/UnboundedSequences', 'int64_values', '[2 ** 63]'),
    ('test_msgs/msg/UnboundedSequences', 'uint64_values', '[-1]'),
    ('test_msgs/msg/WStrings', 'wstring_value', '1'),
    ('test_msgs/msg/WStrings', 'array_of_wstrings', "['a']"),
]


def load(name):
    import importlib
    pkg, kind, t = name.split('/')
    mod = importlib.import_module('%s.%s' % (pkg, kind))
    if not hasattr(mod, t):  # derived classes live in the file's own module
        stem = t.split('_')[0]
        for sub in dir(mod):
            if sub.startswith('_') and hasattr(getattr(mod, sub), t):
                return getattr(getattr(mod, sub), t)
        raise LookupError(t + stem)
    return getattr(mod, t)


def main(out):
    import array  # noqa: F401 (used by BAD_ASSIGNMENTS expressions)
    import numpy  # noqa: F401
    samples = []
    for msg in sample_messages():
        if len(serialize_message(msg)) > 20000:   # keep the fixture small
            continue
        samples.append({'type': type_name(msg), 'cdr': serialize_message(msg).hex(),
                        'repr': repr(msg)})
    errors = []
    for tname, field, expr in BAD_ASSIGNMENTS:
        msg = load(tname)()
        try:
            setattr(msg, field, eval(expr))
            text = None
        except AssertionError as e:
            text = str(e)
        errors.append({'type': tname, 'field': field, 'expr': expr, 'error': text})
    classes = {}
    for tname in ['std_msgs/msg/String', 'geometry_msgs/msg/Twist', 'sensor_msgs/msg/Image',
                  'test_msgs/msg/Arrays', 'test_msgs/msg/BoundedSequences',
                  'test_msgs/msg/Strings', 'test_msgs/msg/Defaults', 'test_msgs/msg/Empty',
                  'test_msgs/msg/WStrings', 'test_msgs/srv/Arrays_Request',
                  'test_msgs/action/Fibonacci_Goal', 'action_msgs/msg/GoalStatus',
                  'rcl_interfaces/msg/ParameterDescriptor']:
        cls = load(tname)
        classes[tname] = {
            'module': cls.__module__, 'name': cls.__name__,
            'slots': [s for s in cls.__slots__ if s != '_check_fields'],
            'fields': cls.get_fields_and_field_types(),
            'constants': {k: repr(v) for k, v in vars(cls).items()
                          if k.isupper() and not k.endswith('__DEFAULT') and k != 'SLOT_TYPES'},
            'repr_default': repr(cls()),
        }
    from test_msgs.action import Fibonacci
    from test_msgs.srv import Arrays
    derived = {}
    for attr in ('Goal', 'Result', 'Feedback'):
        c = getattr(Fibonacci, attr)
        derived['Fibonacci.' + attr] = [c.__module__, c.__name__, repr(c())]
    for attr in ('SendGoalService', 'GetResultService', 'FeedbackMessage',
                 'CancelGoalService', 'GoalStatusMessage'):
        c = getattr(Fibonacci.Impl, attr)
        derived['Fibonacci.Impl.' + attr] = [c.__module__, c.__name__]
    for attr in ('Request', 'Response'):
        c = getattr(Fibonacci.Impl.SendGoalService, attr)
        derived['Fibonacci.Impl.SendGoalService.' + attr] = [c.__module__, c.__name__, repr(c())]
        c = getattr(Arrays, attr)
        derived['Arrays.' + attr] = [c.__module__, c.__name__]
    derived['Fibonacci.Impl.FeedbackMessage()'] = repr(Fibonacci.Impl.FeedbackMessage())
    with open(out, 'w') as f:
        json.dump({'samples': samples, 'errors': errors, 'classes': classes,
                   'derived': derived}, f, indent=1, ensure_ascii=False)


if __name__ == '__main__':
    main(sys.argv[1])
