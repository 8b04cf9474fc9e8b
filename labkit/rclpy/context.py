"""rclpy.context.Context: the lifecycle of init and shutdown (one per process by default)."""
from inspect import ismethod
import os
import threading
import weakref

from labkit.graph import arguments as _arguments
from labkit.graph import world


def default_domain_id():
    """The domain a context started now would join: ROS_DOMAIN_ID, else 0."""
    env = os.environ.get('ROS_DOMAIN_ID', '').strip()
    return int(env) if env.isdigit() else 0


class Context:
    """Encapsulates the lifecycle of init and shutdown."""

    def __init__(self):
        self._lock = threading.RLock()
        self._callbacks = []
        self._logging_initialized = False
        self.__context = None           # dict while initialised
        self._ok = False
        self._domain_id = 0
        self._arguments = None
        self._process = None

    @property
    def handle(self):
        return self.__context

    def destroy(self):
        pass

    def init(self, args=None, *, initialize_logging=True, domain_id=None):
        """Initialize ROS communications for this context."""
        from labkit import process
        from labkit.rclpy.exceptions import RCLError, UnknownROSArgsError
        with self._lock:
            if domain_id is not None and domain_id < 0:
                raise RuntimeError(
                    'Domain id ({}) should not be lower than zero.'.format(domain_id))
            if self.__context is not None:
                raise RuntimeError('Context.init() must only be called once')
            argv = list(args if args is not None else process.argv())
            try:
                parsed = _arguments.parse(argv)
            except _arguments.ArgumentError as exc:
                from labkit.rclpy.logging import get_logger
                get_logger('rcl').error('Failed to parse global arguments')
                raise RCLError(f'failed to initialize rcl: {exc}') from None
            if parsed.unparsed_ros_args:
                raise UnknownROSArgsError(repr([argv[i] for i in parsed.unparsed_ros_args]))
            if domain_id is None:
                domain_id = default_domain_id()
            self._domain_id = domain_id
            self._arguments = parsed
            self.__context = {'args': argv}
            self._ok = True
            proc = process.current()
            self._process = proc
            proc.rclpy.contexts.append(self)
            if initialize_logging and not self._logging_initialized:
                self._configure_logging(parsed)
                self._logging_initialized = True

    @staticmethod
    def _configure_logging(parsed):
        from labkit.rclpy.impl import rcutils_logger
        cfg = rcutils_logger._config()
        for name, level in parsed.log_levels.items():
            if name == '':
                cfg.default_level = level
            else:
                cfg.levels[name] = level
        cfg.stdout_logs = parsed.stdout_logs
        cfg.rosout_logs = parsed.rosout_logs

    def ok(self):
        # lock-free: executors evaluate this inside wait predicates
        return self._ok

    def _call_on_shutdown_callbacks(self):
        # called without self._lock held: callbacks wake executors (world locks)
        callbacks, self._callbacks = self._callbacks, []
        for cb in callbacks:
            callback = cb() if isinstance(cb, weakref.WeakMethod) else cb
            if callback is not None:
                callback()

    def shutdown(self):
        if self.__context is None:
            raise RuntimeError('Context must be initialized before it can be shutdown')
        with self._lock:
            if not self._ok:
                from labkit.rclpy.exceptions import RCLError
                raise RCLError('failed to shutdown: rcl_shutdown already called on the given '
                               'context')
            self._ok = False
        self._call_on_shutdown_callbacks()
        world.notify()

    def try_shutdown(self):
        if self.__context is None:
            return
        with self._lock:
            was_ok, self._ok = self._ok, False
        if was_ok:
            self._call_on_shutdown_callbacks()
        world.notify()

    def _remove_callback(self, weak_method):
        try:
            self._callbacks.remove(weak_method)
        except ValueError:
            pass

    def on_shutdown(self, callback):
        if not callable(callback):
            raise TypeError('callback should be a callable, got {}', type(callback))
        if self.__context is None:
            from labkit.rclpy.exceptions import InvalidHandle
            raise InvalidHandle('cannot use Destroyable because destruction was requested')
        with self._lock:
            run_now = not self._ok
            if not run_now:
                if ismethod(callback):
                    self._callbacks.append(weakref.WeakMethod(callback, self._remove_callback))
                else:
                    self._callbacks.append(callback)
        if run_now:
            callback()

    def get_domain_id(self):
        if self.__context is None:
            raise RuntimeError('Context must be initialized before it can have a domain id')
        return self._domain_id

    # labkit: the parsed global --ros-args of this context
    @property
    def arguments(self):
        return self._arguments


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
