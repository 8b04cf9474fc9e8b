from labkit.rclpy.exceptions import InvalidParameterException


def validate_parameter_name(name):
    """Raise InvalidParameterException for an empty name (rcl has no further rule)."""
    if not name:
        raise InvalidParameterException(name)
    return True
