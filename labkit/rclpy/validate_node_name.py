from labkit.graph import names
from labkit.rclpy.exceptions import InvalidNodeNameException


def validate_node_name(node_name):
    """Raise InvalidNodeNameException if the node name is invalid; else return True."""
    result = names.validate_node_name(node_name)
    if result is None:
        return True
    raise InvalidNodeNameException(node_name, *result)
