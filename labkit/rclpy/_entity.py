"""What every waitable entity (subscription, service, client, guard condition) shares:
how it tells its node's executor it has work (an O(1) ready-queue push)."""
from labkit.graph import world


# Executors cache their timer/waitable lists; any change to those bumps this generation.
ENTITY_GEN = [0]


def bump():
    ENTITY_GEN[0] += 1


class Handle:
    """Stands in for rclpy's C handle: a context manager that fails once destroyed."""

    __slots__ = ("_owner", "pointer")

    def __init__(self, owner):
        self._owner = owner
        self.pointer = id(owner)

    def __enter__(self):
        if self._owner._destroyed:
            from labkit.rclpy.exceptions import InvalidHandle
            raise InvalidHandle('cannot use Destroyable because destruction was requested')
        return self

    def __exit__(self, *exc):
        return False

    def destroy_when_not_in_use(self):
        self._owner._destroyed = True


class ReadyEntity:
    _queued = False
    _destroyed = False
    _node = None

    def _signal(self):
        """This entity has work: queue it on its node's executor (once)."""
        if self._queued or self._destroyed:
            return
        self._queued = True
        node = self._node
        ex = node._executor_obj if node is not None else None
        if ex is not None:
            ex._ready.append(self)
            if world._live_waiters:
                world.notify()
        elif node is not None:
            node._unclaimed.append(self)

    def _has_work(self):
        raise NotImplementedError
