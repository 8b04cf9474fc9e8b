"""rclpy.serialization: CDR bytes exactly as rclpy.serialization produces them."""
from labkit.rclpy.type_support import check_for_type_support


def serialize_message(message):
    check_for_type_support(type(message))
    from labkit.interfaces import rmw_serialize
    return rmw_serialize(message)


def deserialize_message(serialized_message, message_type):
    check_for_type_support(message_type)
    from labkit.interfaces import deserialize
    return deserialize(serialized_message, message_type)
