import pytest

from labkit.interfaces import definition as d
from labkit.interfaces import parser as p


def field_types(text, pkg='pkg', name='Msg'):
    return {f.name: f.type for f in p.parse_message_string(pkg, name, text).fields}


def test_primitive_types_map_to_idl_names():
    text = '\n'.join('%s f_%d' % (t, i) for i, t in enumerate(
        ['bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16', 'uint16',
         'int32', 'uint32', 'int64', 'uint64']))
    names = [t.typename for t in field_types(text).values()]
    assert names == ['boolean', 'octet', 'uint8', 'float', 'double', 'int8', 'uint8', 'int16',
                     'uint16', 'int32', 'uint32', 'int64', 'uint64']


def test_arrays_sequences_and_strings():
    t = field_types('float64[3] a\nint32[] b\nuint8[<=4] c\nstring<=10 s\nwstring w\n'
                    'string<=5[<=2] bs\nstring[2] sa')
    assert t['a'] == d.Array(d.BasicType('double'), 3)
    assert t['b'] == d.UnboundedSequence(d.BasicType('int32'))
    assert t['c'] == d.BoundedSequence(d.BasicType('uint8'), 4)
    assert t['s'] == d.BoundedString(10)
    assert t['w'] == d.UnboundedWString()
    assert t['bs'] == d.BoundedSequence(d.BoundedString(5), 2)
    assert d.idl_type_string(t['bs']) == 'sequence<string<5>, 2>'
    assert d.idl_type_string(t['a']) == 'double[3]'


def test_nested_type_spellings():
    t = field_types('Point p\ngeometry_msgs/Point q\ngeometry_msgs/msg/Point r\nHeader h\n'
                    'Point[] ps', pkg='geometry_msgs')
    point = d.NamespacedType(['geometry_msgs', 'msg'], 'Point')
    assert t['p'] == t['q'] == t['r'] == point
    assert t['h'] == d.NamespacedType(['std_msgs', 'msg'], 'Header')
    assert t['ps'] == d.UnboundedSequence(point)


def test_constants_and_defaults():
    spec = p.parse_message_string('pkg', 'Msg', '\n'.join([
        'int32 FOO=1', 'string S="x y"', 'byte B=7', 'bool OK=true',
        'int32 x 5', 'float64[] v [1.0, 2.0]', "string s 'hi'", 'string[] names ["a,b", \'c\']',
        'float32 f -1.5', 'bool[2] flags [true, 0]', 'int64 h 0x10',
    ]))
    consts = {c.name: c.value for c in spec.constants}
    assert consts == {'FOO': 1, 'S': 'x y', 'B': b'\x07', 'OK': True}
    defaults = {f.name: f.default for f in spec.fields}
    assert defaults == {'x': 5, 'v': [1.0, 2.0], 's': 'hi', 'names': ['a,b', 'c'], 'f': -1.5,
                        'flags': [True, False], 'h': 16}


def test_comments_are_kept_per_element():
    spec = p.parse_message_string('pkg', 'Msg', '# file comment\n# more\n\n'
                                  '# about x\nint32 x  # [m] trailing\n  # indented\nint32 y')
    assert spec.comments == ['file comment', 'more']
    x = spec.fields[0]
    assert x.unit == 'm'
    # rosidl's unit pattern starts with \s*, which eats the newline before '[m]' when the
    # comment has several lines, so the text keeps '[m]': same here
    assert x.comments == ['about x', '[m] trailing', 'indented']
    y = p.parse_message_string('pkg', 'Msg', 'float64 y  # speed [m/s]').fields[0]
    assert (y.unit, y.comments) == ('m/s', ['speed'])


@pytest.mark.parametrize('line, exc, text', [
    ('int32 X', NameError, "'X' is an invalid field name. It should have the pattern "
     "'^(?!.*__)(?!.*_$)[a-z][a-z0-9_]*$'"),
    ('int32 bad__name', NameError, "'bad__name' is an invalid field name"),
    ('int32 foo=1', NameError, "'foo' is an invalid constant name. It should have the pattern "
     "'^[A-Z]([A-Z0-9_]?[A-Z0-9]+)*$'"),
    ('int8 x 200', p.InvalidValue, "value '200' can not be converted to type 'int8': "
     'must be a valid integer value >= -128 and <= 127'),
    ('bool b maybe', p.InvalidValue, "value 'maybe' can not be converted to type 'bool': "
     "must be either 'true' / '1' or 'false' / '0'"),
    ('float64 f one', p.InvalidValue, "value 'one' can not be converted to type 'float64': "
     "must be a floating point number using '.' as the separator"),
    ('int32[2] a [1]', p.InvalidValue, "value '[1]' can not be converted to type 'int32[2]': "
     'array must have exactly 2 elements, not 1'),
    ('int32[<=1] a [1, 2]', p.InvalidValue, 'array must have not more than 1 elements, not 2'),
    ('int32[] a 1', p.InvalidValue, "array value must start with '[' and end with ']'"),
    ('string<=2 s abc', p.InvalidValue, "value 'abc' can not be converted to type 'string<=2': "
     'string must not exceed the maximum length of 2 characters'),
    ('Foo_bar x', p.InvalidResourceName, "'Foo_bar' is an invalid message name"),
    ('a/b/c/D x', p.InvalidResourceName, 'a/b/c/D'),
    ('Bad-pkg/Type x', p.InvalidResourceName, "'Bad-pkg' is an invalid package name"),
    ('string<=0 s', TypeError, "the upper bound of the string type 'string<=0' must be a valid "
     'integer value > 0'),
    ('int32', p.InvalidFieldDefinition, 'int32'),
    ('Point P=1', TypeError, "the constant type 'Point' must be a primitive type"),
    ('int32 x\nint32 x', ValueError, 'the fields iterable contains duplicate names: x'),
])
def test_errors_have_rosidl_texts(line, exc, text):
    with pytest.raises(exc) as info:
        p.parse_message_string('pkg', 'Msg', line)
    assert text in str(info.value)


def test_service_and_action_split():
    srv = p.parse_service_string('pkg', 'Add', 'int64 a\n---\nint64 sum')
    assert srv.request.msg_name == 'Add_Request' and srv.response.fields[0].name == 'sum'
    act = p.parse_action_string('pkg', 'Fib', 'int32 order\n---\nint32[] seq\n---\nint32[] part')
    assert [act.goal.msg_name, act.result.msg_name, act.feedback.msg_name] == \
        ['Fib_Goal', 'Fib_Result', 'Fib_Feedback']
    with pytest.raises(p.InvalidServiceSpecification,
                       match="Could not find separator '---' between request and response"):
        p.parse_service_string('pkg', 'Add', 'int64 a')
    with pytest.raises(p.InvalidActionSpecification,
                       match="Number of '---' separators nonconformant with action definition"):
        p.parse_action_string('pkg', 'Fib', 'int32 a\n---\n')


def test_every_bundled_file_parses_like_rosidl_adapter():
    """Digests recorded with the real rosidl_adapter (tools/make_parser_reference.py)."""
    import json
    import os
    import sys

    from ifc_paths import DATA, TEST_SHARE
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), 'tools'))
    try:
        import make_parser_reference as ref
    finally:
        sys.path.pop(0)
    from labkit.interfaces.registry import BUNDLED_SHARE
    with open(os.path.join(DATA, 'rosidl_adapter_reference.json')) as f:
        expected = json.load(f)
    ours = ref.parse_all(BUNDLED_SHARE, p, ref.dump_labkit)
    ours.update(ref.parse_all(TEST_SHARE, p, ref.dump_labkit))
    assert len(ours) > 230
    assert {k: v for k, v in ours.items() if expected.get(k) != v} == {}
    assert set(ours) == set(expected)
