"""rclpy.parameter: the Parameter class and its Type enum (Humble behaviour).

Message classes come from labkit.interfaces and are looked up lazily, so this
module imports without the interface layer being loaded.
"""
import array
from enum import Enum

PARAMETER_SEPARATOR_STRING = '.'

__all__ = ['Parameter', 'PARAMETER_SEPARATOR_STRING', 'parameter_value_to_python']

_types = {}


def _rcl(kind_and_name):
    """rcl_interfaces class, e.g. _rcl('msg/ParameterValue') (cached)."""
    cls = _types.get(kind_and_name)
    if cls is None:
        from labkit.interfaces import get_type
        cls = _types[kind_and_name] = get_type('rcl_interfaces/' + kind_and_name)
    return cls


# ParameterValue field that holds the value, indexed by rcl_interfaces ParameterType.
_VALUE_FIELDS = (None, 'bool_value', 'integer_value', 'double_value', 'string_value',
                 'byte_array_value', 'bool_array_value', 'integer_array_value',
                 'double_array_value', 'string_array_value')


def _all(values, kind):
    return all(isinstance(v, kind) for v in values)


class Parameter:

    class Type(Enum):
        # Values are rcl_interfaces/msg/ParameterType constants.
        NOT_SET = 0
        BOOL = 1
        INTEGER = 2
        DOUBLE = 3
        STRING = 4
        BYTE_ARRAY = 5
        BOOL_ARRAY = 6
        INTEGER_ARRAY = 7
        DOUBLE_ARRAY = 8
        STRING_ARRAY = 9

        @classmethod
        def from_parameter_value(cls, parameter_value):
            """
            Get a Parameter.Type from a given variable.

            :return: A Parameter.Type corresponding to the instance type of the given value.
            :raises: TypeError if the conversion to a type was not possible.
            """
            v = parameter_value
            if v is None:
                return cls.NOT_SET
            # bool before int: bool is a subclass of int
            for kind, type_ in ((bool, cls.BOOL), (int, cls.INTEGER), (float, cls.DOUBLE),
                                (str, cls.STRING)):
                if isinstance(v, kind):
                    return type_
            if isinstance(v, (list, tuple, array.array)):
                for kind, type_ in ((bytes, cls.BYTE_ARRAY), (bool, cls.BOOL_ARRAY),
                                    (int, cls.INTEGER_ARRAY), (float, cls.DOUBLE_ARRAY),
                                    (str, cls.STRING_ARRAY)):
                    if _all(v, kind):
                        return type_
                raise TypeError(
                    f"The given value is not a list of one of the allowed types '{v}'.")
            raise TypeError(f"The given value is not one of the allowed types '{v}'.")

        def check(self, parameter_value):
            v = parameter_value
            T = Parameter.Type
            if self is T.NOT_SET:
                return v is None
            if self is T.BOOL:
                return isinstance(v, bool)
            if self is T.INTEGER:
                return isinstance(v, int)
            if self is T.DOUBLE:
                return isinstance(v, float)
            if self is T.STRING:
                return isinstance(v, str)
            if self is T.BYTE_ARRAY:
                return isinstance(v, (list, tuple)) and \
                    all(isinstance(b, bytes) and len(b) == 1 for b in v)
            if self is T.BOOL_ARRAY:
                return isinstance(v, (list, tuple)) and _all(v, bool)
            if self is T.INTEGER_ARRAY:
                return isinstance(v, (list, tuple, array.array)) and _all(v, int)
            if self is T.DOUBLE_ARRAY:
                return isinstance(v, (list, tuple, array.array)) and _all(v, float)
            if self is T.STRING_ARRAY:
                return isinstance(v, (list, tuple)) and _all(v, str)
            return False

    @classmethod
    def from_parameter_msg(cls, param_msg):
        type_ = Parameter.Type(value=param_msg.value.type)
        field = _VALUE_FIELDS[type_.value]
        value = getattr(param_msg.value, field) if field else None
        return cls(param_msg.name, type_, value)

    def __init__(self, name, type_=None, value=None):
        if type_ is None:
            # Raises TypeError when no type fits the value.
            type_ = Parameter.Type.from_parameter_value(value)
        if not isinstance(type_, Parameter.Type):
            raise TypeError("type must be an instance of '{}'".format(repr(Parameter.Type)))
        if not type_.check(value):
            raise ValueError("Type '{}' and value '{}' do not agree".format(type_, value))
        self._type_ = type_
        self._name = name
        self._value = value

    @property
    def name(self):
        return self._name

    @property
    def type_(self):
        return self._type_

    @property
    def value(self):
        return self._value

    def get_parameter_value(self):
        parameter_value = _rcl('msg/ParameterValue')(type=self.type_.value)
        field = _VALUE_FIELDS[self.type_.value]
        if field:
            setattr(parameter_value, field, self.value)
        return parameter_value

    def to_parameter_msg(self):
        return _rcl('msg/Parameter')(name=self.name, value=self.get_parameter_value())


def parameter_value_to_python(parameter_value):
    """
    Get the value for the Python builtin type from a rcl_interfaces/msg/ParameterValue object.

    Returns the value member of the message based on the ``type`` member, arrays
    as lists, ``None`` if the parameter is "NOT_SET".

    :raises RuntimeError: if the member ``type`` has an unexpected value.
    """
    t = parameter_value.type
    if not isinstance(t, int) or not 0 <= t < len(_VALUE_FIELDS):
        raise RuntimeError(f'unexpected parameter type {t}')
    field = _VALUE_FIELDS[t]
    if field is None:
        return None
    value = getattr(parameter_value, field)
    return list(value) if t >= Parameter.Type.BYTE_ARRAY.value else value


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
