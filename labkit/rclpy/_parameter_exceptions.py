"""The parameter exceptions, as the parameter modules import them.

They live in rclpy.exceptions (labkit/rclpy/exceptions.py), one class per
exception, with Humble's texts: Humble passes several arguments to
``Exception.__init__`` for most of these, so ``str(exc)`` is a tuple repr such
as ``('Invalid access to undeclared parameter(s)', 'foo')``.
"""
from labkit.rclpy.exceptions import (  # noqa: F401
    InvalidParameterException, InvalidParameterTypeException, InvalidParameterValueException,
    ParameterAlreadyDeclaredException, ParameterException, ParameterImmutableException,
    ParameterNotDeclaredException, ParameterUninitializedException)

__all__ = [
    'ParameterException', 'ParameterNotDeclaredException', 'ParameterAlreadyDeclaredException',
    'InvalidParameterException', 'InvalidParameterTypeException',
    'InvalidParameterValueException', 'ParameterImmutableException',
    'ParameterUninitializedException',
]
