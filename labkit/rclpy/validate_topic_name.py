from labkit.graph import names
from labkit.rclpy.exceptions import InvalidServiceNameException, InvalidTopicNameException

TOPIC_SEPARATOR_STRING = '/'


def validate_topic_name(name, *, is_service=False):
    """Raise if `name` is not a valid (possibly relative) topic or service name; else True."""
    result = names.validate_topic_name(name)
    if result is None:
        return True
    if is_service:
        raise InvalidServiceNameException(name, *result)
    raise InvalidTopicNameException(name, *result)
