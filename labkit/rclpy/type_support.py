"""Checks that a class is a ROS 2 message or service type (rclpy.type_support)."""
from labkit.rclpy.exceptions import NoTypeSupportImportedException  # noqa: F401


def _kind(t):
    name = getattr(t, '_labkit_type', None)
    if name is None:
        return None
    return name.split('/')[1] if name.count('/') >= 2 else 'msg'


def check_for_type_support(msg_or_srv_type):
    if _kind(msg_or_srv_type) is None:
        raise AttributeError(
            f"type object '{type(msg_or_srv_type).__name__}' has no attribute '_TYPE_SUPPORT'"
            ' This might be a ROS 1 message type but it should be a ROS 2 message type.'
            ' Make sure to source your ROS 2 workspace after your ROS 1 workspace.')


def check_is_valid_msg_type(msg_type):
    check_for_type_support(msg_type)
    if (not isinstance(msg_type, type) or hasattr(msg_type, 'Request')
            or hasattr(msg_type, 'Goal')):
        raise RuntimeError(f'The message type provided is not valid ({msg_type}),'
                           ' this might be a service or action')


def check_is_valid_srv_type(srv_type):
    check_for_type_support(srv_type)
    if not (hasattr(srv_type, 'Request') and hasattr(srv_type, 'Response')):
        raise RuntimeError(f'The service type provided is not valid ({srv_type}),'
                           ' this might be a message or action')
