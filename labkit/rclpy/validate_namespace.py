from labkit.graph import names
from labkit.rclpy.exceptions import InvalidNamespaceException


def validate_namespace(namespace):
    """Raise InvalidNamespaceException if the (absolute) namespace is invalid; else return True."""
    result = names.validate_namespace(namespace)
    if result is None:
        return True
    raise InvalidNamespaceException(namespace, *result)
