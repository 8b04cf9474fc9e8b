"""rclpy.waitable: the base for custom waitables (executors ask `is_ready` each spin)."""


class NumberOfEntities:
    __slots__ = ['num_subscriptions', 'num_guard_conditions', 'num_timers', 'num_clients',
                 'num_services', 'num_events']

    def __init__(self, num_subs=0, num_gcs=0, num_timers=0, num_clients=0, num_services=0,
                 num_events=0):
        self.num_subscriptions = num_subs
        self.num_guard_conditions = num_gcs
        self.num_timers = num_timers
        self.num_clients = num_clients
        self.num_services = num_services
        self.num_events = num_events

    def __add__(self, other):
        result = self.__class__()
        for attr in result.__slots__:
            setattr(result, attr, getattr(self, attr) + getattr(other, attr))
        return result

    def __iadd__(self, other):
        for attr in self.__slots__:
            setattr(self, attr, getattr(self, attr) + getattr(other, attr))
        return self

    def __repr__(self):
        return '<{0}({1}, {2}, {3}, {4}, {5}, {6})>'.format(
            self.__class__.__name__, self.num_subscriptions, self.num_guard_conditions,
            self.num_timers, self.num_clients, self.num_services, self.num_events)


class Waitable:
    """Add something to a wait set and execute it (labkit: polled with is_ready(None))."""

    _node = None

    def __init__(self, callback_group):
        self._callback_group = callback_group
        self._callback_group.add_entity(self)
        self._executor_event = False
        self._futures = []

    def add_future(self, future):
        self._futures.append(future)

    def remove_future(self, future):
        self._futures.remove(future)

    @property
    def callback_group(self):
        return self._callback_group

    def is_ready(self, wait_set):
        raise NotImplementedError('Must be implemented by subclass')

    def _labkit_is_ready(self):
        return self.is_ready(None)

    def take_data(self):
        raise NotImplementedError('Must be implemented by subclass')

    async def execute(self, taken_data):
        raise NotImplementedError('Must be implemented by subclass')

    def get_num_entities(self):
        raise NotImplementedError('Must be implemented by subclass')

    def add_to_wait_set(self, wait_set):
        raise NotImplementedError('Must be implemented by subclass')

    def destroy(self):
        pass


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
