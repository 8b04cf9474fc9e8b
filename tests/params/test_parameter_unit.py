"""Parameter logic on a stand-in node (no executor, no graph): Humble semantics and texts."""
import array
import warnings

import pytest

from labkit.interfaces import get_type
from labkit.rclpy._node_parameters import ParameterMixin
from labkit.rclpy._parameter_exceptions import (
    InvalidParameterException, InvalidParameterTypeException, InvalidParameterValueException,
    ParameterAlreadyDeclaredException, ParameterImmutableException,
    ParameterNotDeclaredException, ParameterUninitializedException)
from labkit.rclpy.parameter import Parameter, parameter_value_to_python

ParameterDescriptor = get_type('rcl_interfaces/msg/ParameterDescriptor')
ParameterValue = get_type('rcl_interfaces/msg/ParameterValue')
SetParametersResult = get_type('rcl_interfaces/msg/SetParametersResult')
IntegerRange = get_type('rcl_interfaces/msg/IntegerRange')
FloatingPointRange = get_type('rcl_interfaces/msg/FloatingPointRange')


class _Publisher:
    def __init__(self):
        self.sent = []

    def publish(self, msg):
        self.sent.append(msg)


class FakeNode(ParameterMixin):
    """Just what ParameterMixin needs from the core's Node."""

    def __init__(self, name='talker', namespace='/', overrides=None, args=None, **kwargs):
        self._name, self._ns = name, namespace
        self._args = args or {}
        self._parameter_event_publisher = _Publisher()
        self._init_parameters(overrides, **kwargs)

    def _parameter_overrides_from_args(self):
        return dict(self._args)

    def get_name(self):
        return self._name

    def get_namespace(self):
        return self._ns

    def get_clock(self):
        return None  # stamp falls back to zero

    @property
    def events(self):
        return self._parameter_event_publisher.sent


# ------------------------------------------------------------------ Parameter
def test_type_from_value_and_check():
    T = Parameter.Type
    assert T.from_parameter_value(True) is T.BOOL
    assert T.from_parameter_value(3) is T.INTEGER
    assert T.from_parameter_value(3.0) is T.DOUBLE
    assert T.from_parameter_value('x') is T.STRING
    assert T.from_parameter_value([b'a']) is T.BYTE_ARRAY
    assert T.from_parameter_value([True]) is T.BOOL_ARRAY
    assert T.from_parameter_value(array.array('q', [1])) is T.INTEGER_ARRAY
    assert T.from_parameter_value((1.0,)) is T.DOUBLE_ARRAY
    assert T.from_parameter_value(['a']) is T.STRING_ARRAY
    assert T.from_parameter_value(None) is T.NOT_SET
    with pytest.raises(TypeError, match="not a list of one of the allowed types"):
        T.from_parameter_value([1, 'a'])
    with pytest.raises(TypeError, match="The given value is not one of the allowed types"):
        T.from_parameter_value({})
    with pytest.raises(ValueError, match="Type 'Type.INTEGER' and value 'x' do not agree"):
        Parameter('p', T.INTEGER, 'x')
    assert T.INTEGER.value == get_type('rcl_interfaces/msg/ParameterType').PARAMETER_INTEGER


@pytest.mark.parametrize('value', [True, 7, 2.5, 'hi', [b'a', b'b'], [True, False], [1, 2],
                                   [1.5], ['a', 'b'], None])
def test_msg_round_trip(value):
    p = Parameter('name', value=value)
    msg = p.to_parameter_msg()
    assert msg.name == 'name' and msg.value.type == p.type_.value
    back = Parameter.from_parameter_msg(msg)
    assert back.type_ == p.type_
    assert parameter_value_to_python(msg.value) == value


def test_parameter_value_to_python_bad_type():
    v = ParameterValue()
    v.type = 42
    with pytest.raises(RuntimeError, match='unexpected parameter type 42'):
        parameter_value_to_python(v)


# ----------------------------------------------------------------- declaring
def test_declare_get_and_new_parameter_event():
    node = FakeNode('talker', '/ns')
    p = node.declare_parameter('rate', 10)
    assert (p.name, p.value, p.type_) == ('rate', 10, Parameter.Type.INTEGER)
    assert node.get_parameter('rate').value == 10
    assert node.has_parameter('rate') and not node.has_parameter('other')
    assert node.describe_parameter('rate').type == Parameter.Type.INTEGER.value
    assert node.describe_parameter('rate').name == 'rate'
    [event] = node.events
    assert event.node == '/ns/talker'
    assert [m.name for m in event.new_parameters] == ['rate']
    assert event.new_parameters[0].value.integer_value == 10
    assert not event.changed_parameters and not event.deleted_parameters


def test_declare_twice_and_bad_names():
    node = FakeNode()
    node.declare_parameter('a', 1)
    with pytest.raises(ParameterAlreadyDeclaredException) as e:
        node.declare_parameter('a', 2)
    assert str(e.value) == "('Parameter(s) already declared', ['a'])"
    with pytest.raises(InvalidParameterException) as e:
        node.declare_parameter('', 1)
    assert str(e.value) == "('Invalid parameter name', '')"


def test_declare_parameters_namespace_and_tuple_forms():
    node = FakeNode()
    ps = node.declare_parameters('robot', [
        ('speed', 1.5),
        ('name', 'r2', ParameterDescriptor(description='robot name')),
        ('ids', Parameter.Type.INTEGER_ARRAY),
    ])
    assert [p.name for p in ps] == ['robot.speed', 'robot.name', 'robot.ids']
    assert node.describe_parameter('robot.name').description == 'robot name'
    # statically typed but uninitialized
    with pytest.raises(ParameterUninitializedException) as e:
        node.get_parameter('robot.ids')
    assert str(e.value) == "The parameter 'robot.ids' is not initialized"
    assert node.get_parameter_or('robot.ids', Parameter('x', value=3)).value == 3
    by_prefix = node.get_parameters_by_prefix('robot')
    assert sorted(by_prefix) == ['ids', 'name', 'speed']
    assert by_prefix['speed'].value == 1.5
    with pytest.raises(TypeError, match='expecting length between 1 and 3'):
        node.declare_parameters('', [()])
    with pytest.raises(ValueError, match=r'Cannot declare parameter \{x\} as statically typed'):
        node.declare_parameter('x', Parameter.Type.NOT_SET)


def test_name_only_declaration_warns_and_is_dynamic():
    node = FakeNode()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        p = node.declare_parameter('free')
    assert 'declaring a parameter only providing its name is deprecated' in str(caught[0].message)
    assert p.type_ == Parameter.Type.NOT_SET
    assert node.get_parameter('free').value is None  # dynamic: no exception
    assert node.set_parameters([Parameter('free', value='now a string')])[0].successful


# ------------------------------------------------------------------- setting
def test_set_changes_value_and_publishes_changed_event():
    node = FakeNode()
    node.declare_parameter('rate', 10)
    [result] = node.set_parameters([Parameter('rate', value=20)])
    assert result.successful and result.reason == ''
    assert node.get_parameter('rate').value == 20
    event = node.events[-1]
    assert [m.name for m in event.changed_parameters] == ['rate']
    assert not event.new_parameters


def test_static_type_is_enforced():
    node = FakeNode()
    node.declare_parameter('rate', 10)
    [result] = node.set_parameters([Parameter('rate', value='fast')])
    assert not result.successful
    assert result.reason == "Wrong parameter type, expected 'Type.INTEGER' got 'Type.STRING'"
    assert node.get_parameter('rate').value == 10
    [result] = node.set_parameters([Parameter('rate', Parameter.Type.NOT_SET)])
    assert result.reason == 'Static parameter cannot be undeclared'


def test_dynamic_typing_allows_type_change():
    node = FakeNode()
    node.declare_parameter('any', 1, ParameterDescriptor(dynamic_typing=True))
    assert node.set_parameters([Parameter('any', value='text')])[0].successful
    assert node.get_parameter('any').type_ == Parameter.Type.STRING
    # setting NOT_SET undeclares a dynamic parameter and publishes deleted_parameters
    assert node.set_parameters([Parameter('any')])[0].successful
    assert not node.has_parameter('any')
    assert [m.name for m in node.events[-1].deleted_parameters] == ['any']


def test_read_only():
    node = FakeNode()
    node.declare_parameter('model', 'burger', ParameterDescriptor(read_only=True))
    [result] = node.set_parameters([Parameter('model', value='waffle')])
    assert not result.successful
    assert result.reason == 'Trying to set a read-only parameter: model.'
    with pytest.raises(ParameterImmutableException) as e:
        node.undeclare_parameter('model')
    assert str(e.value) == "('Attempted to modify read-only parameter', 'model')"


def test_undeclared_access():
    node = FakeNode()
    with pytest.raises(ParameterNotDeclaredException) as e:
        node.get_parameter('nope')
    assert str(e.value) == "('Invalid access to undeclared parameter(s)', 'nope')"
    # Humble's generator quirk: the first undeclared name is consumed by any()
    with pytest.raises(ParameterNotDeclaredException) as e:
        node.set_parameters([Parameter('nope', value=1)])
    assert str(e.value) == "('Invalid access to undeclared parameter(s)', [])"
    with pytest.raises(ParameterNotDeclaredException):
        node.set_parameters_atomically([Parameter('a', value=1), Parameter('b', value=2)])
    with pytest.raises(ParameterNotDeclaredException):
        node.undeclare_parameter('nope')


def test_allow_undeclared_parameters():
    node = FakeNode(allow_undeclared_parameters=True)
    assert node.get_parameter('x').type_ == Parameter.Type.NOT_SET
    assert node.get_parameter_type('x') == Parameter.Type.NOT_SET
    assert node.set_parameters([Parameter('x', value=1.0)])[0].successful
    assert node.get_parameter('x').value == 1.0
    assert node.describe_parameter('x').dynamic_typing is True
    assert [m.name for m in node.events[-1].new_parameters] == ['x']


def test_integer_range_and_step():
    node = FakeNode()
    desc = ParameterDescriptor(integer_range=[IntegerRange(from_value=0, to_value=10, step=2)])
    node.declare_parameter('even', 4, desc)
    assert node.set_parameters([Parameter('even', value=10)])[0].successful  # edge
    [r] = node.set_parameters([Parameter('even', value=11)])
    assert r.reason == 'Parameter even out of range. Min: 0, Max: 10, value: 11'
    [r] = node.set_parameters([Parameter('even', value=3)])
    assert r.reason == ('The parameter value for even is not a valid step. '
                        'Min: 0, max: 10, value: 3, step: 2')
    with pytest.raises(InvalidParameterValueException) as e:
        node.declare_parameter('bad', 12, ParameterDescriptor(
            integer_range=[IntegerRange(from_value=0, to_value=10, step=1)]))
    assert str(e.value) == ("('Invalid parameter value (12) for parameter. Reason: "
                            "Parameter bad out of range. Min: 0, Max: 10, value: 12', 'bad')")
    assert not node.has_parameter('bad')


def test_floating_point_range():
    node = FakeNode()
    desc = ParameterDescriptor(floating_point_range=[
        FloatingPointRange(from_value=0.0, to_value=1.0, step=0.25)])
    node.declare_parameter('gain', 0.5, desc)
    assert node.set_parameters([Parameter('gain', value=0.75)])[0].successful
    [r] = node.set_parameters([Parameter('gain', value=1.5)])
    assert r.reason == 'Parameter gain out of range Min: 0.0, Max: 1.0, value: 1.5'
    [r] = node.set_parameters([Parameter('gain', value=0.3)])
    assert r.reason.startswith('The parameter value for gain is not close enough to a valid step')


def test_declare_with_wrong_override_type_raises_type_exception():
    node = FakeNode(args={'rate': 'fast'})
    with pytest.raises(InvalidParameterTypeException) as e:
        node.declare_parameter('rate', Parameter.Type.INTEGER)
    assert str(e.value) == ("Trying to set parameter 'rate' to 'fast' of type 'STRING', "
                            "expecting type 'INTEGER'")


def test_callbacks_can_reject_and_are_called_newest_first():
    node = FakeNode()
    node.declare_parameter('speed', 1.0)
    calls = []

    def limit(params):
        calls.append('limit')
        ok = all(p.value <= 5.0 for p in params)
        return SetParametersResult(successful=ok, reason='' if ok else 'too fast')

    def log(params):
        calls.append('log')
        return SetParametersResult(successful=True)

    node.add_on_set_parameters_callback(limit)
    node.add_on_set_parameters_callback(log)
    [r] = node.set_parameters([Parameter('speed', value=9.0)])
    assert (r.successful, r.reason) == (False, 'too fast')
    assert calls == ['log', 'limit']
    assert node.get_parameter('speed').value == 1.0
    node.remove_on_set_parameters_callback(limit)
    assert node.set_parameters([Parameter('speed', value=9.0)])[0].successful
    with pytest.raises(ValueError):
        node.remove_on_set_parameters_callback(limit)


def test_set_parameters_atomically_all_or_nothing():
    node = FakeNode()
    node.declare_parameters('', [('a', 1), ('b', 2)])
    n_events = len(node.events)
    r = node.set_parameters_atomically([Parameter('a', value=5), Parameter('b', value='x')])
    assert not r.successful
    assert node.get_parameter('a').value == 1 and len(node.events) == n_events
    r = node.set_parameters_atomically([Parameter('a', value=5), Parameter('b', value=6)])
    assert r.successful
    assert [m.name for m in node.events[-1].changed_parameters] == ['a', 'b']


def test_overrides_from_args_and_constructor():
    node = FakeNode(args={'rate': 30, 'name': 'from_args'},
                    overrides=[Parameter('name', value='explicit')])
    assert node.declare_parameter('rate', 10).value == 30
    assert node.declare_parameter('name', 'default').value == 'explicit'
    assert node.declare_parameter('other', 1, ignore_override=False).value == 1
    ignored = FakeNode(args={'rate': 30})
    assert ignored.declare_parameter('rate', 10, ignore_override=True).value == 10


def test_automatically_declare_parameters_from_overrides():
    node = FakeNode(args={'a': 1, 'b.c': 'x'},
                    automatically_declare_parameters_from_overrides=True)
    assert node.get_parameter('a').value == 1
    assert node.get_parameter('b.c').value == 'x'
    assert node.describe_parameter('a').type == Parameter.Type.INTEGER.value


def test_set_descriptor():
    node = FakeNode()
    node.declare_parameter('n', 5)
    value = node.set_descriptor('n', ParameterDescriptor(
        type=Parameter.Type.INTEGER.value,
        integer_range=[IntegerRange(from_value=0, to_value=3, step=1)]),
        alternative_value=ParameterValue(type=2, integer_value=2))
    assert value.integer_value == 2 and node.get_parameter('n').value == 2
    with pytest.raises(InvalidParameterValueException):
        node.set_descriptor('n', ParameterDescriptor(
            type=Parameter.Type.INTEGER.value,
            integer_range=[IntegerRange(from_value=10, to_value=20, step=1)]))


def test_list_parameters_depth_and_prefixes():
    node = FakeNode()
    node.declare_parameters('', [('a', 1), ('b.c', 2), ('b.d.e', 3), ('ab', 4)])
    r = node.list_parameters([], 0)
    assert r.names == ['a', 'ab', 'b.c', 'b.d.e'] and r.prefixes == ['b', 'b.d']
    r = node.list_parameters([], 1)
    assert r.names == ['a', 'ab'] and r.prefixes == []
    r = node.list_parameters([], 2)
    assert r.names == ['a', 'ab', 'b.c'] and r.prefixes == ['b']
    r = node.list_parameters(['b'], 0)
    assert r.names == ['b.c', 'b.d.e'] and r.prefixes == ['b', 'b.d']
    r = node.list_parameters(['a'], 0)
    assert r.names == ['a', 'ab']


# ------------------------------------------------ nodes that are C++ in real ROS
class CppNode(FakeNode):
    _labkit_parameter_dialect = 'rclcpp'


def test_rclcpp_dialect_reasons():
    node = CppNode()
    node.declare_parameter('background_r', 69, ParameterDescriptor(
        integer_range=[IntegerRange(from_value=0, to_value=255, step=1)]))
    node.declare_parameter('qos_overrides./parameter_events.publisher.depth', 1000,
                           ParameterDescriptor(read_only=True))
    node.declare_parameter('gain', 0.5, ParameterDescriptor(floating_point_range=[
        FloatingPointRange(from_value=0.0, to_value=1.0, step=0.25)]))
    reasons = [r.reason for r in node.set_parameters([
        Parameter('background_r', value=300),
        Parameter('background_r', value='red'),
        Parameter('background_r'),
        Parameter('qos_overrides./parameter_events.publisher.depth', value=5),
        Parameter('gain', value=0.3),
        Parameter('gain', value=0.75),
    ])]
    assert reasons == [
        "Parameter {background_r} doesn't comply with integer range.",
        'Wrong parameter type, parameter {background_r} is of type {integer}, '
        'setting it to {string} is not allowed.',
        'Wrong parameter type, parameter {background_r} is of type {integer}, '
        'setting it to {not set} is not allowed.',
        "parameter 'qos_overrides./parameter_events.publisher.depth' cannot be set "
        'because it is read-only',
        "Parameter {gain} doesn't comply with floating point range.",
        '',
    ]


def test_rclcpp_dialect_list_is_sorted_and_prefix_exact():
    node = CppNode()
    node.declare_parameters('', [('b.c', 2), ('a', 1), ('ab', 4), ('b.d.e', 3)])
    r = node.list_parameters([], 0)
    assert r.names == ['a', 'ab', 'b.c', 'b.d.e'] and r.prefixes == ['b', 'b.d']
    assert node.list_parameters([], 1).names == ['a', 'ab']
    assert node.list_parameters(['a'], 0).names == ['a']
    # depth counts the dots after the prefix, its own separator included
    assert node.list_parameters(['b'], 1).names == []
    r = node.list_parameters(['b'], 2)
    assert r.names == ['b.c'] and r.prefixes == ['b']
