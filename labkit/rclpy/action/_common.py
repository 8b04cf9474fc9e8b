"""Helpers shared by the action server and client (not rclpy API)."""
import inspect
import random
import uuid

_types = {}


def msg_type(name):
    """Interface class by full name, e.g. 'action_msgs/msg/GoalStatus' (cached)."""
    cls = _types.get(name)
    if cls is None:
        from labkit.interfaces import get_type
        cls = _types[name] = get_type(name)
    return cls


def action_names(action_name):
    """The hidden service and topic names rcl_action derives from an action name."""
    prefix = f'{action_name}/_action/'
    return {k: prefix + k for k in ('send_goal', 'cancel_goal', 'get_result',
                                    'feedback', 'status')}


def call_maybe_coroutine(callback, *args):
    """Call a plain or ``async def`` callback that is not expected to suspend.

    Goal and cancel callbacks may be coroutines in rclpy; they nearly never
    await anything, so we drive them to completion right here.
    """
    result = callback(*args)
    if inspect.iscoroutine(result):
        try:
            result.send(None)
        except StopIteration as done:
            return done.value
        result.close()
        raise RuntimeError('labkit: this action callback awaited something that did not '
                           'complete at once; use a plain function')
    return result


# Goal ids: random like uuid4 in live mode; a seeded stream in virtual mode so
# that notebooks print the same goal ids on every run.
_virtual_rng = random.Random(20240101)


def new_goal_uuid_bytes():
    from labkit.graph import world
    if world.mode() == 'virtual':
        raw = _virtual_rng.getrandbits(128).to_bytes(16, 'big')
        return uuid.UUID(bytes=raw, version=4).bytes
    return uuid.uuid4().bytes


def reset_virtual_uuids(seed=20240101):
    """Restart the virtual goal-id stream (labkit.reset may call this)."""
    _virtual_rng.seed(seed)


def debug(logger, make_text):
    """Log at DEBUG, building the text only if DEBUG is on (uuids print slowly)."""
    from labkit.rclpy.logging import LoggingSeverity
    if logger.is_enabled_for(LoggingSeverity.DEBUG):
        logger.debug(make_text())
