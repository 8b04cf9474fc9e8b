"""Parameter exceptions of rclpy.exceptions (Humble texts).

Humble passes several arguments to ``Exception.__init__`` for most of these,
so ``str(exc)`` is a tuple repr such as
``('Invalid access to undeclared parameter(s)', 'foo')``; readers see exactly
that text in tracebacks and in `ros2 param set` failures, so we keep it.
rclpy.exceptions (the core's labkit/rclpy/exceptions.py) defines them too: we use
those classes when present so there is one class per exception; the
definitions below are the stand-in for when it is not.
"""

__all__ = [
    'ParameterException', 'ParameterNotDeclaredException', 'ParameterAlreadyDeclaredException',
    'InvalidParameterException', 'InvalidParameterTypeException',
    'InvalidParameterValueException', 'ParameterImmutableException',
    'ParameterUninitializedException',
]


try:
    from labkit.rclpy.exceptions import (  # noqa: F401
        ParameterException, ParameterNotDeclaredException, ParameterAlreadyDeclaredException,
        InvalidParameterException, InvalidParameterTypeException, InvalidParameterValueException,
        ParameterImmutableException, ParameterUninitializedException)
except ImportError:  # pragma: no cover - only before the core exists
    class ParameterException(Exception):
        """Base exception for parameter-related errors."""

        def __init__(self, error_msg, parameters, *args):
            Exception.__init__(self, f'{error_msg}: {parameters}')


    class ParameterNotDeclaredException(ParameterException):
        """Raised when handling an undeclared parameter when it is not allowed."""

        def __init__(self, parameters, *args):
            Exception.__init__(self, 'Invalid access to undeclared parameter(s)', parameters, *args)


    class ParameterAlreadyDeclaredException(ParameterException):
        """Raised when declaring a parameter that had been declared before."""

        def __init__(self, parameters, *args):
            Exception.__init__(self, 'Parameter(s) already declared', parameters, *args)


    class InvalidParameterException(ParameterException):
        """Raised when a parameter to be declared has an invalid name."""

        def __init__(self, parameter, *args):
            Exception.__init__(self, 'Invalid parameter name', parameter, *args)


    class InvalidParameterTypeException(ParameterException):
        """Raised when a parameter is rejected for having an invalid type."""

        def __init__(self, desired_parameter, expected_type, *args):
            from labkit.rclpy.parameter import Parameter
            actual = Parameter.Type.from_parameter_value(desired_parameter.value).name
            Exception.__init__(
                self,
                f"Trying to set parameter '{desired_parameter.name}' to "
                f"'{desired_parameter.value}' of type '{actual}', expecting type '{expected_type}'",
                *args)
            self._actual_type = desired_parameter.type_
            self._param_name = desired_parameter.name


    class InvalidParameterValueException(ParameterException):
        """Raised when a parameter is rejected by a user callback or when applying a descriptor."""

        def __init__(self, parameter, value, reason, *args):
            Exception.__init__(
                self, f'Invalid parameter value ({value}) for parameter. Reason: {reason}',
                parameter, *args)


    class ParameterImmutableException(ParameterException):
        """Raised when a read-only parameter is modified."""

        def __init__(self, parameter, *args):
            Exception.__init__(self, 'Attempted to modify read-only parameter', parameter, *args)


    class ParameterUninitializedException(ParameterException):
        """Raised when an uninitialized parameter is accessed."""

        def __init__(self, parameter_name, *args):
            Exception.__init__(self, f"The parameter '{parameter_name}' is not initialized", *args)
