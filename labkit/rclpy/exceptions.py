"""rclpy.exceptions, with rclpy's texts."""


class NotInitializedException(Exception):
    def __init__(self, *args):
        Exception.__init__(self, 'rclpy.init() has not been called', *args)


class NoTypeSupportImportedException(Exception):
    def __init__(self, *args):
        Exception.__init__(self, 'no type_support imported')


class NameValidationException(Exception):
    """Raised when a topic name, node name, or namespace are invalid."""

    def __init__(self, name_type, name, error_msg, invalid_index, *args):
        msg = ("Invalid {name_type}: {error_msg}:\n  '{name}'\n   {indent}^").format(
            name_type=name_type, name=name, error_msg=error_msg, indent=' ' * invalid_index)
        Exception.__init__(self, msg)


class InvalidHandle(Exception):
    pass


class InvalidNamespaceException(NameValidationException):
    def __init__(self, name, error_msg, invalid_index, *args):
        NameValidationException.__init__(self, 'namespace', name, error_msg, invalid_index)


class InvalidNodeNameException(NameValidationException):
    def __init__(self, name, error_msg, invalid_index, *args):
        NameValidationException.__init__(self, 'node name', name, error_msg, invalid_index)


class InvalidTopicNameException(NameValidationException):
    def __init__(self, name, error_msg, invalid_index, *args):
        NameValidationException.__init__(self, 'topic name', name, error_msg, invalid_index)


class InvalidServiceNameException(NameValidationException):
    def __init__(self, name, error_msg, invalid_index, *args):
        NameValidationException.__init__(self, 'service name', name, error_msg, invalid_index)


class ParameterException(Exception):
    def __init__(self, error_msg, parameters, *args):
        Exception.__init__(self, f'{error_msg}: {parameters}')


class ParameterNotDeclaredException(ParameterException):
    def __init__(self, parameters, *args):
        Exception.__init__(self, 'Invalid access to undeclared parameter(s)', parameters, *args)


class ParameterAlreadyDeclaredException(ParameterException):
    def __init__(self, parameters, *args):
        Exception.__init__(self, 'Parameter(s) already declared', parameters, *args)


class InvalidParameterException(ParameterException):
    def __init__(self, parameter, *args):
        Exception.__init__(self, 'Invalid parameter name', parameter, *args)


class InvalidParameterTypeException(ParameterException):
    def __init__(self, desired_parameter, expected_type, *args):
        from labkit.rclpy.parameter import Parameter
        Exception.__init__(
            self,
            f"Trying to set parameter '{desired_parameter._name}' to "
            f"'{desired_parameter._value}' of type "
            f"'{Parameter.Type.from_parameter_value(desired_parameter._value).name}'"
            f", expecting type '{expected_type}'", *args)
        self._actual_type = desired_parameter.type_
        self._param_name = desired_parameter.name
        self._expected_type = expected_type     # labkit: rclcpp's text is made from these


class InvalidParameterValueException(ParameterException):
    def __init__(self, parameter, value, reason, *args):
        Exception.__init__(
            self, 'Invalid parameter value ({value}) for parameter. Reason: {reason}'.format(
                value=value, reason=reason), parameter, *args)


class ParameterImmutableException(ParameterException):
    def __init__(self, parameter, *args):
        Exception.__init__(self, 'Attempted to modify read-only parameter', parameter, *args)


class ParameterUninitializedException(ParameterException):
    def __init__(self, parameter_name, *args):
        Exception.__init__(self, f"The parameter '{parameter_name}' is not initialized", *args)


class ROSInterruptException(Exception):
    def __init__(self, *args):
        Exception.__init__(self, 'rclpy.shutdown() has been called', *args)


# What the C extension raises in real rclpy; the module name shows in tracebacks.
class RCLError(RuntimeError):
    pass


class UnknownROSArgsError(RuntimeError):
    pass


class InvalidHandleError(InvalidHandle):
    pass


for _cls in (InvalidHandle, RCLError, UnknownROSArgsError):
    _cls.__module__ = 'rclpy._rclpy_pybind11'


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
