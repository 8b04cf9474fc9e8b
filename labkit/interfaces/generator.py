"""Build message / service / action classes that behave like rosidl_generator_py's (Humble).

Classes are made from parsed specs with closures (no source compiling), so a
whole package is ready in milliseconds. Field checks raise AssertionError with
Humble's exact texts (Humble generates them under `__debug__`, which is on).
"""
import array
import math
import re
from collections import UserList, UserString
from collections.abc import Sequence, Set
from operator import attrgetter

from labkit.interfaces import definition as d


class _Numpy:
    """numpy, imported at its first use (only fixed-size numeric arrays need it: an empty
    `labkit exec` script or a String talker starts without its ~50 ms); the first use puts
    the module itself in this module's globals."""

    def __getattr__(self, name):
        import numpy as module
        globals()['numpy'] = module
        return getattr(module, name)


numpy = _Numpy()

_FLOAT_BOUNDS = {'float': 3.402823466e+38, 'double': 1.7976931348623157e+308}
_FLOAT_NAMES = {'float': 'float', 'double': 'double'}


def camel_to_snake(name):
    """rosidl's module naming: 'RotateAbsolute' -> 'rotate_absolute'."""
    name = re.sub('(.)([A-Z][a-z]+)', r'\1_\2', name)
    name = re.sub('([a-z0-9])([A-Z])', r'\1_\2', name)
    return name.lower()


class Member:
    """One field of a generated class (what a setter and `__init__` need)."""
    __slots__ = ('name', 'type', 'default', 'cls')

    def __init__(self, name, type_, default=None, cls=None):
        self.name, self.type, self.default, self.cls = name, type_, default, cls


def python_type_name(t):
    """get_python_type of rosidl_generator_py, as used in the assertion texts."""
    if isinstance(t, d.NamespacedType):
        return t.name
    if isinstance(t, d.AbstractGenericString):
        return 'str'
    if isinstance(t, d.BasicType):
        if t.typename == 'boolean':
            return 'bool'
        if t.typename == 'octet':
            return 'bytes'
        if t.typename in d.INTEGER_TYPES:
            return 'int'
        if t.typename in d.FLOATING_POINT_TYPES:
            return 'float'
        return 'str'
    raise AssertionError("unknown type '%s'" % t)


def _python_type(t, cls):
    if isinstance(t, d.NamespacedType):
        return cls
    if isinstance(t, d.AbstractGenericString):
        return str
    return {'bool': bool, 'bytes': bytes, 'int': int, 'float': float, 'str': str}[
        python_type_name(t)]


def _range_check(t):
    """(predicate on one value, assertion text suffix for sequences, text for scalars)."""
    if not isinstance(t, d.BasicType):
        return None
    tn = t.typename
    if tn in d.SIGNED_INTEGER_TYPES:
        bound = 2 ** (int(tn[3:]) - 1)
        return (lambda v: -bound <= v < bound,
                'and each integer in [%d, %d]' % (-bound, bound - 1),
                'must be an integer in [%d, %d]' % (-bound, bound - 1))
    if tn in d.UNSIGNED_INTEGER_TYPES:
        bound = 2 ** int(tn[4:])
        return (lambda v: 0 <= v < bound,
                'and each unsigned integer in [0, %d]' % (bound - 1),
                'must be an unsigned integer in [0, %d]' % (bound - 1))
    if tn in _FLOAT_BOUNDS:
        bound = _FLOAT_BOUNDS[tn]
        return (lambda v: not (v < -bound or v > bound) or math.isinf(v),
                'and each %s in [%f, %f]' % (_FLOAT_NAMES[tn], -bound, bound),
                'must be a %s in [%r, %r]' % (_FLOAT_NAMES[tn], -bound, bound))
    return None


def _make_setter(m):
    """The property setter of member `m`, with Humble's checks and storage rules."""
    name, t, slot = m.name, m.type, '_' + m.name
    store = object.__setattr__

    if isinstance(t, d.AbstractNestedType):
        vt = t.value_type
        special = isinstance(vt, d.BasicType) and vt.typename in d.ARRAY_TYPECODES
        pytype = _python_type(vt, m.cls)
        rng = _range_check(vt)
        suffixes = ['a set or sequence']
        str_bound = vt.maximum_size if (isinstance(vt, d.AbstractGenericString)
                                        and vt.has_maximum_size()) else None
        if str_bound is not None:
            suffixes.append('and each string value not longer than %d' % str_bound)
        if isinstance(t, d.BoundedSequence):
            suffixes.insert(1, 'with length <= %d' % t.maximum_size)
        elif isinstance(t, d.Array):
            suffixes.insert(1, 'with length %d' % t.size)
        suffixes.append("and each value of type '%s'" % python_type_name(vt))
        if rng:
            suffixes.append(rng[1])
        message = "The '%s' field must be %s" % (name, ' '.join(suffixes))
        in_range = rng[0] if rng else None
        is_array = isinstance(t, d.Array)
        size = t.size if is_array else None
        max_size = t.maximum_size if isinstance(t, d.BoundedSequence) else None
        if special:
            tc = d.ARRAY_TYPECODES[vt.typename]
            # only a fixed-size array is a numpy.ndarray (a sequence is an array.array)
            dtype = numpy.dtype(d.NUMPY_DTYPES[vt.typename]) if is_array else None

        def check(value):
            if not ((isinstance(value, (Sequence, Set, UserList))) and
                    not isinstance(value, (str, UserString))):
                return False
            if str_bound is not None and not all(len(v) <= str_bound for v in value):
                return False
            if size is not None and len(value) != size:
                return False
            if max_size is not None and len(value) > max_size:
                return False
            if not all(isinstance(v, pytype) for v in value):
                return False
            if in_range is not None and not all(in_range(v) for v in value):
                return False
            return True

        if special and is_array:
            dtype_text = "The '%s' numpy.ndarray() must have the dtype of 'numpy.%s'" % (
                name, dtype.name)
            size_text = "The '%s' numpy.ndarray() must have a size of %d" % (name, size)

            def setter(self, value):
                if isinstance(value, numpy.ndarray):
                    assert value.dtype == dtype, dtype_text
                    assert value.size == size, size_text
                    store(self, slot, value)
                    return
                assert check(value), message
                store(self, slot, numpy.array(value, dtype=dtype))
        elif special:
            tc_text = "The '%s' array.array() must have the type code of '%s'" % (name, tc)
            bound_text = ("The '%s' array.array() must have a size <= %s" % (name, max_size))

            bytes_ok = tc == 'B'

            def setter(self, value):
                if isinstance(value, array.array):
                    assert value.typecode == tc, tc_text
                    if max_size is not None:
                        assert len(value) <= max_size, bound_text
                    store(self, slot, value)
                    return
                if bytes_ok and isinstance(value, (bytes, bytearray)) and (
                        max_size is None or len(value) <= max_size):
                    # every byte is an int in [0, 255]: the check would pass, skip its cost
                    store(self, slot, array.array(tc, value))
                    return
                assert check(value), message
                store(self, slot, array.array(tc, value))
        else:
            def setter(self, value):
                assert check(value), message
                store(self, slot, value)
        return setter

    if isinstance(t, d.AbstractGenericString) and t.has_maximum_size():
        bound = t.maximum_size
        message = ("The '%s' field must be string value not longer than %d" % (name, bound))

        def setter(self, value):
            assert isinstance(value, (str, UserString)) and len(value) <= bound, message
            store(self, slot, value)
        return setter
    if isinstance(t, d.NamespacedType):
        cls = m.cls
        message = "The '%s' field must be a sub message of type '%s'" % (name, t.name)

        def setter(self, value):
            assert isinstance(value, cls), message
            store(self, slot, value)
        return setter
    if isinstance(t, d.BasicType) and t.typename == 'octet':
        message = ("The '%s' field must be of type 'bytes' or 'ByteString' with length 1" % name)

        def setter(self, value):
            assert isinstance(value, (bytes, bytearray)) and len(value) == 1, message
            store(self, slot, value)
        return setter
    pytype = _python_type(t, None)
    message = "The '%s' field must be of type '%s'" % (name, python_type_name(t))
    rng = _range_check(t)
    if rng is None:
        def setter(self, value):
            assert isinstance(value, pytype), message
            store(self, slot, value)
        return setter
    in_range, range_text = rng[0], "The '%s' field %s" % (name, rng[2])

    def setter(self, value):
        assert isinstance(value, pytype), message
        assert in_range(value), range_text
        store(self, slot, value)
    return setter


def _default_factory(m):
    """A zero-argument function giving a fresh default value for member `m`."""
    t = m.type
    if m.default is not None:
        return _declared_default(t, m.default)
    if isinstance(t, d.Array):
        vt, n = t.value_type, t.size
        if isinstance(vt, d.BasicType) and vt.typename == 'octet':
            return lambda: [bytes([0]) for _ in range(n)]
        if isinstance(vt, d.BasicType) and vt.typename in d.ARRAY_TYPECODES:
            dtype = d.NUMPY_DTYPES[vt.typename]
            return lambda: numpy.zeros(n, dtype=dtype)
        make = _python_type(vt, m.cls)
        return lambda: [make() for _ in range(n)]
    if isinstance(t, d.AbstractSequence):
        vt = t.value_type
        if isinstance(vt, d.BasicType) and vt.typename in d.ARRAY_TYPECODES:
            tc = d.ARRAY_TYPECODES[vt.typename]
            return lambda: array.array(tc)
        return list
    if isinstance(t, d.BasicType) and t.typename == 'octet':
        return lambda: b'\x00'
    if isinstance(t, d.NamespacedType):
        return m.cls
    value = _python_type(t, None)()
    return lambda: value


def _declared_default(t, value):
    """Default from the .msg file (`int32 x 5`), typed as the generated code types it."""
    if not isinstance(t, d.AbstractNestedType):
        if isinstance(t, d.BasicType) and t.typename == 'octet':
            value = bytes([value])
        elif isinstance(t, d.BasicType) and t.typename in d.FLOATING_POINT_TYPES:
            value = float(value)
        return lambda: value
    vt = t.value_type
    values = list(value)
    if isinstance(vt, d.BasicType) and vt.typename in d.FLOATING_POINT_TYPES:
        values = [float(v) for v in values]
    if isinstance(vt, d.BasicType) and vt.typename == 'octet':
        values = [bytes([v]) for v in values]
    if isinstance(vt, d.BasicType) and vt.typename in d.ARRAY_TYPECODES:
        if isinstance(t, d.Array):
            dtype = d.NUMPY_DTYPES[vt.typename]
            return lambda: numpy.array(values, dtype=dtype)
        tc = d.ARRAY_TYPECODES[vt.typename]
        return lambda: array.array(tc, values)
    return lambda: list(values)


def _init_plan(members):
    """(name, default factory, numpy dtype and size for fixed numeric arrays) per member."""
    plan = []
    for m in members:
        t = m.type
        fixed = None
        if (m.default is None and isinstance(t, d.Array) and isinstance(t.value_type, d.BasicType)
                and t.value_type.typename in d.ARRAY_TYPECODES):
            fixed = (numpy.dtype(d.NUMPY_DTYPES[t.value_type.typename]), t.size)
        seq_tc = None
        if (m.default is None and isinstance(t, d.AbstractSequence)
                and isinstance(t.value_type, d.BasicType)
                and t.value_type.typename in d.ARRAY_TYPECODES):
            seq_tc = d.ARRAY_TYPECODES[t.value_type.typename]
        plan.append((m.name, _default_factory(m), fixed, seq_tc))
    return tuple(plan)


class MessageMeta(type):
    """Base of the per-class metaclasses (rclpy looks for `_TYPE_SUPPORT` on it)."""
    _CREATE_ROS_MESSAGE = None
    _CONVERT_FROM_PY = None
    _CONVERT_TO_PY = None
    _DESTROY_ROS_MESSAGE = None
    _TYPE_SUPPORT = 'labkit'

    @classmethod
    def __import_type_support__(cls):
        pass


class InterfaceMeta(type):
    """Base of service and action metaclasses."""
    _TYPE_SUPPORT = 'labkit'

    @classmethod
    def __import_type_support__(cls):
        pass


def _message_init(self, **kwargs):
    slots = self.__slots__
    if kwargs:
        bad = [k for k in kwargs if '_' + k not in slots]
        assert not bad, 'Invalid arguments passed to constructor: %s' % ', '.join(sorted(bad))
        for name, make, fixed, seq_tc in self._labkit_init:
            if name in kwargs:
                value = kwargs[name]
                if fixed is not None:
                    value = numpy.array(value, dtype=fixed[0])
                    assert value.shape == (fixed[1], )
                elif seq_tc is not None:
                    value = array.array(seq_tc, value)
                setattr(self, name, value)
            else:
                setattr(self, name, make())
    else:
        for name, make, _, _ in self._labkit_init:
            setattr(self, name, make())


def _is_array_sequence(t):
    return (isinstance(t, d.AbstractSequence) and isinstance(t.value_type, d.BasicType)
            and t.value_type.typename in d.ARRAY_TYPECODES)


def _message_repr(self):
    typename = self.__class__.__module__.split('.')
    typename.pop()
    typename.append(self.__class__.__name__)
    args = []
    for s, t in zip(self.__slots__, self.SLOT_TYPES):
        field = getattr(self, s)
        fieldstr = repr(field)
        # numeric sequences are array.array: show them as plain lists, like rclpy
        if _is_array_sequence(t):
            if len(field) == 0:
                fieldstr = '[]'
            else:
                assert fieldstr.startswith('array(')
                fieldstr = fieldstr[len("array('X', "):-1]
        args.append(s[1:] + '=' + fieldstr)
    return '%s(%s)' % ('.'.join(typename), ', '.join(args))


def _message_eq(self, other):
    if not isinstance(other, self.__class__):
        return False
    for slot, is_ndarray in self._labkit_eq:
        a, b = getattr(self, slot), getattr(other, slot)
        if is_ndarray:
            # Humble compares fixed numeric arrays with all(a != b)
            if all(a != b):
                return False
        elif a != b:
            return False
    return True


def _get_fields_and_field_types(cls):
    return dict(cls._fields_and_field_types)


def _message_copy(self):
    """copy.copy: a new message sharing the field values (as Python's default would)."""
    new = self.__class__.__new__(self.__class__)
    for s in self.__slots__:
        object.__setattr__(new, s, getattr(self, s))
    return new


def _message_deepcopy(self, memo=None):
    from labkit.interfaces.fastcopy import copy_message
    return copy_message(self)


def make_message_class(type_name, module_name, class_name, members, constants=()):
    """A message class: `type_name` like 'std_msgs/msg/String', members resolved already."""
    constant_names = [c.name for c in constants]
    doc = "Message class '%s'." % class_name
    if constant_names:
        doc = "\n    Message class '%s'.\n\n    Constants:\n%s\n    " % (
            class_name, ''.join('      %s\n' % n for n in constant_names))
    meta_ns = {'__module__': module_name,
               '__doc__': "Metaclass of message '%s'." % class_name}
    for m in members:
        if m.default is not None:
            make = _declared_default(m.type, m.default)
            meta_ns[m.name.upper() + '__DEFAULT'] = property(lambda cls, make=make: make())
    meta = type('Metaclass_' + class_name, (MessageMeta,), meta_ns)
    ns = {
        '__module__': module_name,
        '__qualname__': class_name,
        '__doc__': doc,
        '__slots__': ['_' + m.name for m in members],
        '_fields_and_field_types': {m.name: d.idl_type_string(m.type) for m in members},
        'SLOT_TYPES': tuple(m.type for m in members),
        '_labkit_type': type_name,
        '_labkit_members': tuple(members),
        '_labkit_init': _init_plan(members),
        '_labkit_eq': tuple(('_' + m.name, isinstance(m.type, d.Array)
                             and isinstance(m.type.value_type, d.BasicType)
                             and m.type.value_type.typename in d.ARRAY_TYPECODES)
                            for m in members),
        '__init__': _message_init,
        '__repr__': _message_repr,
        '__eq__': _message_eq,
        '__copy__': _message_copy,
        '__deepcopy__': _message_deepcopy,
        'get_fields_and_field_types': classmethod(_get_fields_and_field_types),
    }
    for c in constants:
        ns[c.name] = c.value
    for m in members:
        if m.default is not None:
            ns[m.name.upper() + '__DEFAULT'] = _declared_default(m.type, m.default)()
        ns[m.name] = property(attrgetter('_' + m.name), _make_setter(m),
                              doc="Message field '%s'." % m.name)
    return meta(class_name, (), ns)


def make_service_class(type_name, module_name, class_name, request, response):
    meta = type('Metaclass_' + class_name, (InterfaceMeta,), {
        '__module__': module_name, '__doc__': "Metaclass of service '%s'." % class_name})

    def __init__(self):
        raise NotImplementedError('Service classes can not be instantiated')
    return meta(class_name, (), {
        '__module__': module_name, '__qualname__': class_name,
        'Request': request, 'Response': response, '_labkit_type': type_name,
        '__init__': __init__})


def make_action_class(type_name, module_name, class_name, goal, result, feedback,
                      send_goal, get_result, feedback_message, cancel_goal, goal_status_array):
    meta = type('Metaclass_' + class_name, (InterfaceMeta,), {
        '__module__': module_name, '__doc__': "Metaclass of action '%s'." % class_name})
    impl = type('Impl', (), {
        '__module__': module_name, '__qualname__': class_name + '.Impl',
        'SendGoalService': send_goal, 'GetResultService': get_result,
        'FeedbackMessage': feedback_message, 'CancelGoalService': cancel_goal,
        'GoalStatusMessage': goal_status_array})

    def __init__(self):
        raise NotImplementedError('Action classes can not be instantiated')
    return meta(class_name, (), {
        '__module__': module_name, '__qualname__': class_name,
        'Goal': goal, 'Result': result, 'Feedback': feedback, 'Impl': impl,
        '_labkit_type': type_name, '__init__': __init__})
