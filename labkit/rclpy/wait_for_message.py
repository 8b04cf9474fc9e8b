"""rclpy.wait_for_message: block (a world wait point) until one message arrives."""
from labkit.rclpy import _wait
from labkit.rclpy.utilities import timeout_sec_to_nsec


def wait_for_message(msg_type, node, topic, *, qos_profile=1, time_to_wait=-1):
    """(True, msg) once a message arrives; (False, None) on timeout or shutdown."""
    context = node.context
    got = []
    sub = node.create_subscription(msg_type, topic, lambda _: None, qos_profile=qos_profile)
    try:
        timeout = timeout_sec_to_nsec(time_to_wait)
        _wait.wait(lambda: bool(sub._queue) or not context.ok(),
                   None if timeout < 0 else timeout)
        if sub._queue and context.ok():
            got.append(sub._queue.popleft())
    finally:
        node.destroy_subscription(sub)
    if got:
        return True, got[0]
    return False, None
