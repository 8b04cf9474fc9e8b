"""Light type descriptors, named like `rosidl_parser.definition`'s.

Generated classes list them in `SLOT_TYPES`, so code written against rosidl
(`isinstance(t, AbstractNestedType)`, `t.value_type.typename`, ...) works.
Type names are the IDL ones rosidl uses ('double', 'boolean', 'octet', ...).
"""

# IDL name of each .msg primitive (rosidl_adapter's mapping: char is uint8)
MSG_TO_IDL = {
    'bool': 'boolean', 'byte': 'octet', 'char': 'uint8',
    'int8': 'int8', 'uint8': 'uint8', 'int16': 'int16', 'uint16': 'uint16',
    'int32': 'int32', 'uint32': 'uint32', 'int64': 'int64', 'uint64': 'uint64',
    'float32': 'float', 'float64': 'double',
}

INTEGER_TYPES = ('int8', 'uint8', 'int16', 'uint16', 'int32', 'uint32', 'int64', 'uint64')
SIGNED_INTEGER_TYPES = ('int8', 'int16', 'int32', 'int64')
UNSIGNED_INTEGER_TYPES = ('uint8', 'uint16', 'uint32', 'uint64')
FLOATING_POINT_TYPES = ('float', 'double', 'long double')
CHARACTER_TYPES = ('char', 'wchar')
BOOLEAN_TYPE = 'boolean'
OCTET_TYPE = 'octet'
BASIC_TYPES = (*INTEGER_TYPES, *FLOATING_POINT_TYPES, *CHARACTER_TYPES, BOOLEAN_TYPE, OCTET_TYPE)
EMPTY_STRUCTURE_REQUIRED_MEMBER_NAME = 'structure_needs_at_least_one_member'

# typecodes / dtypes used for numeric sequences and arrays (as rosidl_generator_py)
ARRAY_TYPECODES = {
    'float': 'f', 'double': 'd', 'int8': 'b', 'uint8': 'B', 'int16': 'h', 'uint16': 'H',
    'int32': 'i', 'uint32': 'I', 'int64': 'q', 'uint64': 'Q',
}
SPECIAL_NESTED_BASIC_TYPES = ARRAY_TYPECODES
NUMPY_DTYPES = {
    'float': 'float32', 'double': 'float64', 'int8': 'int8', 'uint8': 'uint8',
    'int16': 'int16', 'uint16': 'uint16', 'int32': 'int32', 'uint32': 'uint32',
    'int64': 'int64', 'uint64': 'uint64',
}


class AbstractType:
    __slots__ = ()

    def __eq__(self, other):
        return type(self) is type(other) and all(
            getattr(self, s) == getattr(other, s) for s in _all_slots(type(self)))

    def __hash__(self):
        values = (_freeze(getattr(self, s)) for s in _all_slots(type(self)))
        return hash((type(self).__name__, *values))

    def __repr__(self):
        args = ', '.join(repr(getattr(self, s)) for s in _all_slots(type(self)))
        return '%s(%s)' % (type(self).__name__, args)


def _all_slots(cls):
    out = []
    for c in reversed(cls.__mro__):
        out.extend(getattr(c, '__slots__', ()))
    return out


def _freeze(v):
    return tuple(v) if isinstance(v, list) else v


class AbstractNestableType(AbstractType):
    __slots__ = ()


class BasicType(AbstractNestableType):
    __slots__ = ('typename',)

    def __init__(self, typename):
        assert typename in BASIC_TYPES, typename
        self.typename = typename


class NamedType(AbstractNestableType):
    __slots__ = ('name',)

    def __init__(self, name):
        self.name = name


class NamespacedType(AbstractNestableType):
    __slots__ = ('namespaces', 'name')

    def __init__(self, namespaces, name):
        self.namespaces = list(namespaces)
        self.name = name

    def namespaced_name(self):
        return (*self.namespaces, self.name)


class AbstractGenericString(AbstractNestableType):
    __slots__ = ()

    def has_maximum_size(self):
        return False


class AbstractString(AbstractGenericString):
    __slots__ = ()


class AbstractWString(AbstractGenericString):
    __slots__ = ()


class UnboundedString(AbstractString):
    __slots__ = ()


class BoundedString(AbstractString):
    __slots__ = ('maximum_size',)

    def __init__(self, maximum_size):
        self.maximum_size = maximum_size

    def has_maximum_size(self):
        return True


class UnboundedWString(AbstractWString):
    __slots__ = ()


class BoundedWString(AbstractWString):
    __slots__ = ('maximum_size',)

    def __init__(self, maximum_size):
        self.maximum_size = maximum_size

    def has_maximum_size(self):
        return True


class AbstractNestedType(AbstractType):
    __slots__ = ('value_type',)

    def __init__(self, value_type):
        self.value_type = value_type

    def has_maximum_size(self):
        return False


class Array(AbstractNestedType):
    __slots__ = ('size',)

    def __init__(self, value_type, size):
        super().__init__(value_type)
        self.size = size

    def has_maximum_size(self):
        return True


class AbstractSequence(AbstractNestedType):
    __slots__ = ()


class BoundedSequence(AbstractSequence):
    __slots__ = ('maximum_size',)

    def __init__(self, value_type, maximum_size):
        super().__init__(value_type)
        self.maximum_size = maximum_size

    def has_maximum_size(self):
        return True


class UnboundedSequence(AbstractSequence):
    __slots__ = ()


def idl_type_string(t):
    """The type as `_fields_and_field_types` spells it ('sequence<double, 3>', 'double[9]', ...)."""
    base = t.value_type if isinstance(t, AbstractNestedType) else t
    if isinstance(base, BasicType):
        s = base.typename
    elif isinstance(base, AbstractGenericString):
        s = ('w' if isinstance(base, AbstractWString) else '') + 'string'
        if base.has_maximum_size():
            s += '<%d>' % base.maximum_size
    else:
        s = '%s/%s' % (base.namespaces[0], base.name)
    if isinstance(t, BoundedSequence):
        return 'sequence<%s, %d>' % (s, t.maximum_size)
    if isinstance(t, UnboundedSequence):
        return 'sequence<%s>' % s
    if isinstance(t, Array):
        return '%s[%d]' % (s, t.size)
    return s
