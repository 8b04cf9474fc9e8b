"""Message <-> dict/YAML/CSV, behaving like rosidl_runtime_py (Humble).

`ros2 topic echo` prints `message_to_yaml(msg)`; `ros2 topic pub` and
`ros2 service call` fill messages with `set_message_fields`.
"""
import array
import sys
from collections import OrderedDict
from functools import partial

import numpy
import yaml

from labkit.interfaces import definition as d

__all__ = ['message_to_ordereddict', 'message_to_yaml', 'message_to_csv',
           'set_message_fields', 'get_message_slot_types']


def _type_name(value_type):
    if isinstance(value_type, d.BasicType):
        return value_type.typename
    if isinstance(value_type, d.AbstractString):
        return 'string'
    if isinstance(value_type, d.AbstractWString):
        return 'wstring'
    if isinstance(value_type, d.NamedType):
        return value_type.name
    if isinstance(value_type, d.NamespacedType):
        return '/'.join(value_type.namespaced_name())
    return 'unknown'


def _abbreviate_array_info(value, field_type):
    name = _type_name(field_type.value_type)
    if isinstance(field_type, d.Array):
        return '<array type: {0}[{1}]>'.format(name, field_type.size)
    if isinstance(field_type, d.BoundedSequence):
        return '<sequence type: {0}[{1}], length: {2}>'.format(
            name, field_type.maximum_size, len(value))
    if isinstance(field_type, d.UnboundedSequence):
        return '<sequence type: {0}, length: {1}>'.format(name, len(value))
    return 'unknown'


class _Dumper(yaml.Dumper):
    """PyYAML's default dumper plus ordered mappings (rosidl_runtime_py registers the same
    representer globally; ours stays local so other YAML users are not affected)."""


def _represent_ordereddict(dumper, data):
    items = [(dumper.represent_data(k), dumper.represent_data(v)) for k, v in data.items()]
    return yaml.nodes.MappingNode('tag:yaml.org,2002:map', items)


_Dumper.add_representer(OrderedDict, _represent_ordereddict)


def message_to_yaml(msg, *, truncate_length=None, no_arr=False, no_str=False,
                    flow_style=False):
    """YAML text of a message, as `ros2 topic echo` prints it."""
    return yaml.dump(
        message_to_ordereddict(msg, truncate_length=truncate_length, no_arr=no_arr,
                               no_str=no_str),
        Dumper=_Dumper, allow_unicode=True, width=sys.maxsize, default_flow_style=flow_style)


def message_to_csv(msg, *, truncate_length=None, no_arr=False, no_str=False):
    """Comma-separated field values (`ros2 topic echo --csv`)."""
    def to_string(val, field_type=None):
        r = ''
        if isinstance(val, (list, tuple, array.array, numpy.ndarray)):
            if no_arr is True and field_type is not None:
                r = _abbreviate_array_info(val, field_type)
            else:
                for i, v in enumerate(val):
                    if r:
                        r += ','
                    if truncate_length is not None and i >= truncate_length:
                        r += '...'
                        break
                    r += to_string(v)
        elif isinstance(val, (bool, bytes, float, int, str, numpy.number)):
            if no_str is True and isinstance(val, str):
                val = '<string length: <{0}>>'.format(len(val))
            elif isinstance(val, (bytes, str)):
                if truncate_length is not None and len(val) > truncate_length:
                    val = val[:truncate_length]
                    val += b'...' if isinstance(val, bytes) else '...'
            r = str(val)
        else:
            r = message_to_csv(val, truncate_length=truncate_length, no_arr=no_arr,
                               no_str=no_str)
        return r

    result = ''
    for field_name, field_type in zip(msg.__slots__, msg.SLOT_TYPES):
        if result:
            result += ','
        result += to_string(getattr(msg, field_name), field_type)
    return result


def message_to_ordereddict(msg, *, truncate_length=None, no_arr=False, no_str=False):
    """OrderedDict of the fields in .msg order (nested messages become OrderedDicts)."""
    out = OrderedDict()
    for field_name, field_type in zip(msg.__slots__, msg.SLOT_TYPES):
        value = getattr(msg, field_name, None)
        out[field_name[1:]] = _convert_value(
            value, field_type=field_type, truncate_length=truncate_length, no_arr=no_arr,
            no_str=no_str)
    return out


def _convert_value(value, *, field_type=None, truncate_length=None, no_arr=False,
                   no_str=False):
    if isinstance(value, bytes):
        if truncate_length is not None and len(value) > truncate_length:
            value = ''.join([chr(c) for c in value[:truncate_length]]) + '...'
        else:
            value = ''.join([chr(c) for c in value])
    elif isinstance(value, str):
        if no_str is True:
            value = '<string length: <{0}>>'.format(len(value))
        elif truncate_length is not None and len(value) > truncate_length:
            value = value[:truncate_length] + '...'
    elif isinstance(value, (list, tuple, array.array, numpy.ndarray)):
        typename = tuple if isinstance(value, tuple) else list
        if no_arr is True and field_type is not None:
            value = _abbreviate_array_info(value, field_type)
        elif truncate_length is not None and len(value) > truncate_length:
            value = typename(
                [_convert_value(v, truncate_length=truncate_length, no_arr=no_arr,
                                no_str=no_str) for v in value[:truncate_length]] + ['...'])
        else:
            value = typename(
                [_convert_value(v, truncate_length=truncate_length, no_arr=no_arr,
                                no_str=no_str) for v in value])
    elif isinstance(value, dict):
        new_value = OrderedDict() if isinstance(value, OrderedDict) else {}
        for k, v in value.items():
            new_value[_convert_value(k)] = _convert_value(
                v, truncate_length=truncate_length, no_arr=no_arr, no_str=no_str)
        value = new_value
    elif isinstance(value, numpy.number):
        value = value.item()
    elif not isinstance(value, (bool, float, int)):
        value = message_to_ordereddict(value, truncate_length=truncate_length, no_arr=no_arr,
                                       no_str=no_str)
    return value


def get_message_slot_types(msg):
    return OrderedDict(zip([s[1:] for s in msg.__slots__], msg.SLOT_TYPES))


def _class_of(namespaced_type):
    from labkit.interfaces.registry import get_class
    return get_class('/'.join(namespaced_type.namespaced_name()))


def set_message_fields(msg, values, expand_header_auto=False, expand_time_now=False):
    """Fill `msg` from a dict (as parsed from the YAML a user typed).

    Returns setters for 'auto' headers / 'now' times when those expansions are on.
    Raises AttributeError for an unknown field and TypeError/ValueError/AssertionError
    for a value of the wrong type, like rosidl_runtime_py.
    """
    timestamp_fields = []

    def fill(msg, values):
        try:
            items = values.items()
        except AttributeError:
            raise TypeError("Value '%s' is expected to be a dictionary but is a %s"
                            % (values, type(values).__name__)) from None
        slot_types = get_message_slot_types(msg)
        for name, given in items:
            current = getattr(msg, name)
            kind = type(current)
            where = kind.__module__ + '.' + kind.__name__
            # 'auto' headers and 'now' stamps are filled in later, by the caller
            if where == 'std_msgs.msg._header.Header' and expand_header_auto and given == 'auto':
                timestamp_fields.append(partial(setattr, current, 'stamp'))
                continue
            if where == 'builtin_interfaces.msg._time.Time' and expand_time_now and given == 'now':
                timestamp_fields.append(partial(setattr, msg, name))
                continue
            setattr(msg, name, _nested(slot_types[name], _coerced(current, kind, given)))

    def _coerced(current, kind, given):
        if kind is array.array:
            return array.array(current.typecode, given)
        if kind is numpy.ndarray:
            return numpy.array(given, dtype=current.dtype)
        if type(given) is kind:
            return given
        try:
            return kind(given)
        except TypeError:       # a message: built field by field from a dict
            sub = kind()
            fill(sub, given)
            return sub

    def _nested(rosidl_type, value):
        """A sequence of messages given as dicts becomes a sequence of messages."""
        if isinstance(rosidl_type, d.AbstractNestedType) and \
                isinstance(rosidl_type.value_type, d.NamespacedType):
            element = _class_of(rosidl_type.value_type)
            for i, item in enumerate(value):
                built = element()
                fill(built, item)
                value[i] = built
        return value

    fill(msg, values)
    return timestamp_fields
