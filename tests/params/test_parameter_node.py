"""Parameters on real labkit nodes: the six services through clients, /parameter_events."""
import pytest

import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.executors import SingleThreadedExecutor
from labkit.rclpy.parameter import Parameter

ParameterDescriptor = get_type('rcl_interfaces/msg/ParameterDescriptor')
ParameterEvent = get_type('rcl_interfaces/msg/ParameterEvent')
ParameterValue = get_type('rcl_interfaces/msg/ParameterValue')
IntegerRange = get_type('rcl_interfaces/msg/IntegerRange')
srv = {name: get_type('rcl_interfaces/srv/' + name) for name in (
    'DescribeParameters', 'GetParameters', 'GetParameterTypes', 'ListParameters',
    'SetParameters', 'SetParametersAtomically')}


@pytest.fixture
def graph():
    rclpy.init()
    server = rclpy.create_node('turtle', namespace='/sim')
    client = rclpy.create_node('param_client')
    executor = SingleThreadedExecutor()
    executor.add_node(server)
    executor.add_node(client)
    yield server, client, executor
    executor.shutdown()
    server.destroy_node()
    client.destroy_node()
    rclpy.shutdown()


def _call(client_node, executor, kind, service, **fields):
    cli = client_node.create_client(srv[kind], service)
    assert cli.wait_for_service(timeout_sec=1.0)
    future = cli.call_async(srv[kind].Request(**fields))
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    assert future.done()
    client_node.destroy_client(cli)
    return future.result()


def test_services_exist_with_rcl_interfaces_types(graph):
    server, client, _ = graph
    services = dict(client.get_service_names_and_types_by_node('turtle', '/sim'))
    for suffix, kind in (('describe_parameters', 'DescribeParameters'),
                         ('get_parameter_types', 'GetParameterTypes'),
                         ('get_parameters', 'GetParameters'),
                         ('list_parameters', 'ListParameters'),
                         ('set_parameters', 'SetParameters'),
                         ('set_parameters_atomically', 'SetParametersAtomically')):
        assert services[f'/sim/turtle/{suffix}'] == [f'rcl_interfaces/srv/{kind}']


def test_use_sim_time_is_declared(graph):
    server, _, _ = graph
    assert server.get_parameter('use_sim_time').value is False


def test_get_list_describe_set_through_services(graph):
    server, client, ex = graph
    server.declare_parameter('background_r', 69, ParameterDescriptor(
        description='red', integer_range=[IntegerRange(from_value=0, to_value=255, step=1)]))
    server.declare_parameter('name', 'turtle1', ParameterDescriptor(read_only=True))

    r = _call(client, ex, 'ListParameters', '/sim/turtle/list_parameters')
    assert r.result.names == ['use_sim_time', 'background_r', 'name']

    r = _call(client, ex, 'GetParameters', '/sim/turtle/get_parameters',
              names=['background_r', 'name'])
    assert [v.integer_value for v in r.values][:1] == [69] and r.values[1].string_value == 'turtle1'
    r = _call(client, ex, 'GetParameters', '/sim/turtle/get_parameters',
              names=['background_r', 'missing'])
    assert list(r.values) == []   # one unknown name empties the answer (Humble)

    r = _call(client, ex, 'GetParameterTypes', '/sim/turtle/get_parameter_types',
              names=['background_r', 'name'])
    assert list(r.types) == [2, 4]

    r = _call(client, ex, 'DescribeParameters', '/sim/turtle/describe_parameters',
              names=['background_r'])
    assert r.descriptors[0].description == 'red'
    assert r.descriptors[0].integer_range[0].to_value == 255

    new = Parameter('background_r', value=200).to_parameter_msg()
    bad = Parameter('background_r', value=300).to_parameter_msg()
    ro = Parameter('name', value='x').to_parameter_msg()
    nope = Parameter('nope', value=1).to_parameter_msg()
    r = _call(client, ex, 'SetParameters', '/sim/turtle/set_parameters',
              parameters=[new, bad, ro, nope])
    assert [x.successful for x in r.results] == [True, False, False, False]
    assert r.results[1].reason == (
        'Parameter background_r out of range. Min: 0, Max: 255, value: 300')
    assert r.results[2].reason == 'Trying to set a read-only parameter: name.'
    assert r.results[3].reason == "('Invalid access to undeclared parameter(s)', [])"
    assert server.get_parameter('background_r').value == 200

    r = _call(client, ex, 'SetParametersAtomically', '/sim/turtle/set_parameters_atomically',
              parameters=[Parameter('background_r', value=1).to_parameter_msg(), ro])
    assert not r.result.successful
    assert server.get_parameter('background_r').value == 200


def test_parameter_events(graph):
    server, client, ex = graph
    events = []
    client.create_subscription(ParameterEvent, '/parameter_events', events.append, 10)
    server.declare_parameter('speed', 1.0)
    server.set_parameters([Parameter('speed', value=2.0)])
    server.declare_parameter('tmp', 'x', ParameterDescriptor(dynamic_typing=True))
    server.set_parameters([Parameter('tmp')])  # NOT_SET deletes it
    for _ in range(10):
        ex.spin_once(timeout_sec=0.1)
    mine = [e for e in events if e.node == '/sim/turtle']
    assert [[p.name for p in e.new_parameters] for e in mine] == [['speed'], [], ['tmp'], []]
    assert [p.value.double_value for p in mine[1].changed_parameters] == [2.0]
    assert [p.name for p in mine[3].deleted_parameters] == ['tmp']
    stamp = mine[0].stamp
    assert stamp.sec > 0  # from the node clock


def test_ros_args_overrides_and_explicit_overrides():
    rclpy.init(args=['prog', '--ros-args', '-p', 'rate:=30', '-p', 'name:=cli'])
    try:
        node = rclpy.create_node('n', parameter_overrides=[Parameter('name', value='code')])
        assert node.declare_parameter('rate', 10).value == 30
        assert node.declare_parameter('name', 'default').value == 'code'
        auto = rclpy.create_node('auto', automatically_declare_parameters_from_overrides=True)
        assert auto.get_parameter('rate').value == 30
        node.destroy_node()
        auto.destroy_node()
    finally:
        rclpy.shutdown()


def test_cpp_node_answers_with_rclcpp_texts(graph):
    """`ros2 param load /turtlesim` in the seed shows rclcpp's read-only text."""
    _, client, ex = graph
    from labkit.rclpy.node import Node

    class CppNode(Node):
        _labkit_parameter_dialect = 'rclcpp'

    node = CppNode('turtlesim')
    ex.add_node(node)
    node.declare_parameter('qos_overrides./parameter_events.publisher.depth', 1000,
                           ParameterDescriptor(read_only=True))
    node.declare_parameter('background_g', 86)
    r = _call(client, ex, 'SetParameters', '/turtlesim/set_parameters', parameters=[
        Parameter('background_g', value=150).to_parameter_msg(),
        Parameter('qos_overrides./parameter_events.publisher.depth', value=1000).to_parameter_msg(),
        Parameter('nope', value=1).to_parameter_msg()])
    assert [(x.successful, x.reason) for x in r.results] == [
        (True, ''),
        (False, "parameter 'qos_overrides./parameter_events.publisher.depth' cannot be set "
                'because it is read-only'),
        (False, "parameter 'nope' cannot be set because it was not declared")]
    r = _call(client, ex, 'SetParametersAtomically', '/turtlesim/set_parameters_atomically',
              parameters=[Parameter('nope', value=1).to_parameter_msg()])
    assert r.result.reason == 'One or more parameters were not declared before setting'
    r = _call(client, ex, 'ListParameters', '/turtlesim/list_parameters')
    assert r.result.names == ['background_g', 'qos_overrides./parameter_events.publisher.depth',
                              'use_sim_time']
    node.destroy_node()
