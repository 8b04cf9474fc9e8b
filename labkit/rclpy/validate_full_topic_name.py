from labkit.graph import names
from labkit.rclpy.exceptions import InvalidServiceNameException, InvalidTopicNameException


def validate_full_topic_name(name, *, is_service=False):
    """Raise if `name` is not a valid fully-qualified topic (or service) name; else True."""
    result = names.validate_full_topic_name(name)
    if result is None:
        return True
    if is_service:
        raise InvalidServiceNameException(name, *result)
    raise InvalidTopicNameException(name, *result)
