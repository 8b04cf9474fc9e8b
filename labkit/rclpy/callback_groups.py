"""Callback groups: which callbacks an executor may run at the same time."""
import threading
import weakref


class CallbackGroup:
    """The base class for a callback group."""

    def __init__(self):
        super().__init__()
        self.entities = set()

    def add_entity(self, entity):
        self.entities.add(weakref.ref(entity))

    def has_entity(self, entity):
        return weakref.ref(entity) in self.entities

    def can_execute(self, entity):
        raise NotImplementedError()

    def beginning_execution(self, entity):
        raise NotImplementedError()

    def ending_execution(self, entity):
        raise NotImplementedError()


class ReentrantCallbackGroup(CallbackGroup):
    """Allow callbacks to be executed in parallel without restriction."""

    def can_execute(self, entity):
        return True

    def beginning_execution(self, entity):
        return True

    def ending_execution(self, entity):
        pass


class MutuallyExclusiveCallbackGroup(CallbackGroup):
    """Allow only one callback to be executing at a time."""

    def __init__(self):
        super().__init__()
        self._active_entity = None
        self._busy = threading.Lock()    # held while one of its callbacks runs

    def can_execute(self, entity):
        return not self._busy.locked()

    def beginning_execution(self, entity):
        if self._busy.acquire(False):
            self._active_entity = entity
            return True
        return False

    def ending_execution(self, entity):
        self._active_entity = None
        try:
            self._busy.release()
        except RuntimeError:
            pass


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
