from labkit.rclpy._entity import Handle, ReadyEntity


class GuardCondition(ReadyEntity):
    _kind = 'guard'

    def __init__(self, callback, callback_group, context=None):
        from labkit.rclpy.utilities import get_default_context
        self._context = get_default_context() if context is None else context
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
