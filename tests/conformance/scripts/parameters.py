"""Conformance: parameters (declare with descriptors and ranges, accepted and rejected
sets, read-only, type checks, callbacks, overrides from --ros-args -p, the parameter
services used from another node).

ARGS: --ros-args -p max_speed:=1.5 -p robot_name:=turtle1 -p turtle_node:mode:=fast -p other_node:mode:=slow

Plain rclpy: runs unchanged on ROS 2 Humble.
Humble/Jazzy differences (the expected file keeps Humble's):
- parameter exception texts: Humble passes (message, names) as two Exception args, so
  str(e) is a tuple text "('Invalid access to undeclared parameter(s)', ['nope'])";
  Jazzy formats "message: names" (also in the parameter services' reasons) and appends
  ": name" to ParameterUninitializedException's text.
- Jazzy nodes also declare the `start_type_description_service` parameter.
"""
import sys

import rclpy
from rcl_interfaces.msg import (FloatingPointRange, IntegerRange, Parameter as ParameterMsg,
                                ParameterDescriptor, ParameterType, ParameterValue,
                                SetParametersResult)
from rcl_interfaces.srv import (DescribeParameters, GetParameters, GetParameterTypes,
                                ListParameters, SetParameters)
from rclpy.executors import SingleThreadedExecutor
from rclpy.parameter import Parameter


def show_result(label, results):
    for r in results:
        print(f'{label}: successful={r.successful} reason={r.reason!r}')


def attempt(label, fn):
    try:
        value = fn()
        print(f'{label}: ok {value!r}')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print(f'{label}: {type(e).__name__}: {e}')


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('turtle_node')

    # overrides from --ros-args -p (global and node-specific)
    print('max_speed:', node.declare_parameter('max_speed', 1.0).value)
    print('robot_name:', node.declare_parameter('robot_name', 'robot').value)
    print('mode:', node.declare_parameter('mode', 'normal').value)
    print('ignore_override:', node.declare_parameter('ignore_me', 7, ignore_override=True).value)
    print('use_sim_time:', node.get_parameter('use_sim_time').value)

    # descriptors and ranges
    speed_desc = ParameterDescriptor(
        description='turning speed in rad/s',
        floating_point_range=[FloatingPointRange(from_value=0.0, to_value=2.0, step=0.5)])
    node.declare_parameter('turn_speed', 1.0, speed_desc)
    show_result('turn_speed=1.5', node.set_parameters([Parameter('turn_speed', value=1.5)]))
    show_result('turn_speed=1.2', node.set_parameters([Parameter('turn_speed', value=1.2)]))
    show_result('turn_speed=3.0', node.set_parameters([Parameter('turn_speed', value=3.0)]))
    show_result('turn_speed=2.0', node.set_parameters([Parameter('turn_speed', value=2.0)]))
    show_result('turn_speed=fast', node.set_parameters([Parameter('turn_speed', value='fast')]))
    print('turn_speed now:', node.get_parameter('turn_speed').value)

    count_desc = ParameterDescriptor(
        integer_range=[IntegerRange(from_value=0, to_value=10, step=2)])
    node.declare_parameter('count', 4, count_desc)
    show_result('count=3', node.set_parameters([Parameter('count', value=3)]))
    show_result('count=12', node.set_parameters([Parameter('count', value=12)]))
    show_result('count=8', node.set_parameters([Parameter('count', value=8)]))
    attempt('declare out of range',
            lambda: node.declare_parameter('bad_count', 11, count_desc).value)

    node.declare_parameter('robot_id', 42, ParameterDescriptor(read_only=True))
    show_result('robot_id=7', node.set_parameters([Parameter('robot_id', value=7)]))
    print('robot_id now:', node.get_parameter('robot_id').value)

    # dynamic typing allows any type
    node.declare_parameter('anything', 1, ParameterDescriptor(dynamic_typing=True))
    show_result('anything=text', node.set_parameters([Parameter('anything', value='text')]))
    print('anything now:', repr(node.get_parameter('anything').value))

    # types of values
    node.declare_parameter('waypoints', [1.0, 2.5])
    node.declare_parameter('names', ['a', 'b'])
    node.declare_parameter('flags', [True, False])
    for name in ('max_speed', 'robot_name', 'count', 'waypoints', 'names', 'flags'):
        p = node.get_parameter(name)
        print(f'type of {name}:', p.type_, p.type_.value, repr(p.value))

    # declared with a type but no value
    node.declare_parameter('later', Parameter.Type.INTEGER)
    attempt('get uninitialized', lambda: node.get_parameter('later').value)
    print('has later:', node.has_parameter('later'))

    # errors
    attempt('get undeclared', lambda: node.get_parameter('nope'))
    attempt('set undeclared', lambda: node.set_parameters([Parameter('nope', value=1)]))
    attempt('declare twice', lambda: node.declare_parameter('count', 2))
    attempt('declare bad type', lambda: node.declare_parameter('weird', {'a': 1}))
    attempt('get_parameter_or', lambda: node.get_parameter_or(
        'nope', Parameter('nope', value=5)).value)
    attempt('undeclare read-only', lambda: node.undeclare_parameter('robot_id'))

    # a set-parameters callback that rejects negative numbers
    def no_negatives(params):
        for p in params:
            if isinstance(p.value, (int, float)) and not isinstance(p.value, bool) \
                    and p.value < 0:
                return SetParametersResult(successful=False, reason=f'{p.name} must be >= 0')
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(no_negatives)
    show_result('max_speed=-1.0', node.set_parameters([Parameter('max_speed', value=-1.0)]))
    show_result('atomic', [node.set_parameters_atomically([
        Parameter('max_speed', value=0.5), Parameter('count', value=-2)])])
    print('max_speed after atomic:', node.get_parameter('max_speed').value)
    attempt('declare negative', lambda: node.declare_parameter('offset', -3))

    # prefixes
    node.declare_parameters('pid', [('kp', 1.0), ('ki', 0.1), ('kd', 0.0)])
    print('by prefix:', {k: v.value for k, v in
                         sorted(node.get_parameters_by_prefix('pid').items())})

    # the same parameters through the parameter services, from another node
    client_node = rclpy.create_node('param_client')
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(client_node)

    def call(srv_type, name, request):
        client = client_node.create_client(srv_type, name)
        client.wait_for_service(timeout_sec=5.0)
        future = client.call_async(request)
        executor.spin_until_future_complete(future, timeout_sec=5.0)
        return future.result()

    listed = call(ListParameters, '/turtle_node/list_parameters', ListParameters.Request())
    print('list names:', sorted(listed.result.names))
    print('list prefixes:', sorted(listed.result.prefixes))
    listed = call(ListParameters, '/turtle_node/list_parameters',
                  ListParameters.Request(prefixes=['pid'], depth=0))
    print('list pid:', sorted(listed.result.names), sorted(listed.result.prefixes))
    described = call(DescribeParameters, '/turtle_node/describe_parameters',
                     DescribeParameters.Request(names=['turn_speed', 'robot_id']))
    for d in described.descriptors:
        print('describe:', d)
    described = call(DescribeParameters, '/turtle_node/describe_parameters',
                     DescribeParameters.Request(names=['turn_speed', 'nope']))
    print('describe with undeclared:', list(described.descriptors))
    for names in (['max_speed', 'robot_name', 'waypoints', 'later'], ['max_speed', 'nope']):
        types = call(GetParameterTypes, '/turtle_node/get_parameter_types',
                     GetParameterTypes.Request(names=names))
        print('types:', names, list(types.types))
    for names in (['count', 'robot_name', 'flags'], ['count', 'nope'], ['count', 'later']):
        got = call(GetParameters, '/turtle_node/get_parameters',
                   GetParameters.Request(names=names))
        print('get values:', names, len(got.values))
        for v in got.values:
            print('  value:', v)
    request = SetParameters.Request(parameters=[
        ParameterMsg(name='count', value=ParameterValue(type=ParameterType.PARAMETER_INTEGER,
                                                        integer_value=6)),
        ParameterMsg(name='robot_id', value=ParameterValue(type=ParameterType.PARAMETER_INTEGER,
                                                           integer_value=1)),
        ParameterMsg(name='nope', value=ParameterValue(type=ParameterType.PARAMETER_BOOL,
                                                       bool_value=True)),
    ])
    for r in call(SetParameters, '/turtle_node/set_parameters', request).results:
        print('remote set:', r)
    print('count now:', node.get_parameter('count').value)

    executor.shutdown()
    client_node.destroy_node()
    node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main(sys.argv)
