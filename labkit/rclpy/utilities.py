"""rclpy.utilities: the default context of the calling process, ok/shutdown helpers."""
import threading

from labkit import process as _process
from labkit.graph import arguments as _arguments
from labkit.rclpy.constants import S_TO_NS  # noqa: F401
from labkit.rclpy.context import Context

g_context_lock = threading.Lock()


def _state():
    return _process.current().rclpy


def get_default_context(*, shutting_down=False):
    """Return the default context of the calling process."""
    with g_context_lock:
        state = _state()
        if state.default_context is None:
            state.default_context = Context()
        if shutting_down:
            old = state.default_context
            state.default_context = None
            return old
        return state.default_context


def remove_ros_args(args=None):
    from labkit.rclpy.exceptions import RCLError
    try:
        return _arguments.remove_ros_args(args if args is not None else _process.argv())
    except _arguments.ArgumentError as exc:
        raise RCLError(f'Failed to parse ROS arguments: {exc}') from None


def ok(*, context=None):
    if context is None:
        context = get_default_context()
    return context.ok()


def shutdown(*, context=None):
    if context is None:
        with g_context_lock:
            state = _state()
            if state.default_context is None and getattr(state, 'reset_by_labkit', False):
                # labkit.reset() already shut the default context down: the notebook's own
                # `rclpy.shutdown()` in a later cell has nothing left to do
                state.reset_by_labkit = False
                return None
        context = get_default_context(shutting_down=True)
    return context.shutdown()


def forget_after_reset():
    """labkit.reset() shut the calling process's default context down (see shutdown())."""
    _state().reset_by_labkit = True


def try_shutdown(*, context=None):
    if context is None:
        with g_context_lock:
            state = _state()
            if state.default_context is None:
                state.default_context = Context()
            state.default_context.try_shutdown()
            if not state.default_context.ok():
                state.default_context = None
    else:
        return context.try_shutdown()


def get_rmw_implementation_identifier():
    return 'rmw_fastrtps_cpp'


def get_available_rmw_implementations():
    return {'rmw_fastrtps_cpp'}


def timeout_sec_to_nsec(timeout_sec):
    """None or negative -> -1 (forever), else integer nanoseconds."""
    if timeout_sec is None or timeout_sec < 0:
        return -1
    return int(float(timeout_sec) * S_TO_NS)
