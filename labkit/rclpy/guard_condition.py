import contextlib

from labkit.rclpy._entity import Handle, ReadyEntity


def enter_context_handle(context):
    """rclpy's `with context.handle:` before making a C object: a context that was never
    initialised (e.g. the new default context after rclpy.shutdown()) has no handle, and
    Python itself refuses `with None`."""
    handle = context.handle
    return contextlib.nullcontext() if handle is not None else handle


class GuardCondition(ReadyEntity):
    _kind = 'guard'

    def __init__(self, callback, callback_group, context=None):
        from labkit.rclpy.utilities import get_default_context
        self._context = get_default_context() if context is None else context
        with enter_context_handle(self._context):
            pass
        self.callback = callback
        self.callback_group = callback_group
        self._executor_event = False
        self._executor_triggered = False
        self._triggered = False
        self._handle = Handle(self)

    def trigger(self):
        with self._handle:
            self._triggered = True
            self._signal()

    def _has_work(self):
        return self._triggered

    def _take(self):
        from labkit.rclpy.subscription import _NOTHING
        if not self._triggered:
            return _NOTHING
        self._triggered = False
        return None

    def _callback_and_args(self, _):
        return self.callback, ()

    @property
    def handle(self):
        return self._handle

    def destroy(self):
        if self._node is not None:
            self._node.destroy_guard_condition(self)
        self._destroyed = True

    def _destroy(self):
        self._destroyed = True


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
