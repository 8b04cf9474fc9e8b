"""Futures and tasks (rclpy.task): results of asynchronous work, and coroutines run by executors."""
import inspect
import sys
import threading
import types
import warnings
import weakref

from labkit.graph import world


def _no_executor():
    return None


class Future:
    """Represent the outcome of a task in the future."""

    def __init__(self, *, executor=None):
        self._done = False
        self._cancelled = False
        self._result = None
        self._exception = None
        self._exception_fetched = False
        self._callbacks = []
        self._lock = threading.Lock()
        self._executor = _no_executor
        self._set_executor(executor)

    def __del__(self):
        if self._exception is not None and not self._exception_fetched:
            print('The following exception was never retrieved: ' + str(self._exception),
                  file=sys.stderr)

    def __await__(self):
        # Yield ourselves so the running Task knows what it waits for.
        while not self._done:
            yield self
        return self.result()

    def cancel(self):
        with self._lock:
            if not self._done:
                self._cancelled = True
        self._schedule_or_invoke_done_callbacks()

    def cancelled(self):
        return self._cancelled

    def done(self):
        return self._done

    def result(self):
        if self._exception:
            raise self.exception()
        return self._result

    def exception(self):
        self._exception_fetched = True
        return self._exception

    def set_result(self, result):
        with self._lock:
            self._result = result
            self._done = True
            self._cancelled = False
        self._schedule_or_invoke_done_callbacks()

    def set_exception(self, exception):
        with self._lock:
            self._exception = exception
            self._exception_fetched = False
            self._done = True
            self._cancelled = False
        self._schedule_or_invoke_done_callbacks()

    def _schedule_or_invoke_done_callbacks(self):
        with self._lock:
            executor = self._executor()
            callbacks = self._callbacks
            self._callbacks = []
        if executor is not None:
            for callback in callbacks:
                _schedule(executor, callback, self)
        else:
            for callback in callbacks:
                try:
                    callback(self)
                except Exception as e:
                    warnings.warn('Unhandled exception in done callback: {}'.format(e))
        world.notify()

    def _set_executor(self, executor):
        with self._lock:
            self._executor = _no_executor if executor is None else weakref.ref(executor)

    def add_done_callback(self, callback):
        invoke = False
        with self._lock:
            if self._done:
                executor = self._executor()
                if executor is not None:
                    _schedule(executor, callback, self)
                else:
                    invoke = True
            else:
                self._callbacks.append(callback)
        if invoke:
            callback(self)


def _schedule(executor, callback, future):
    """A done callback runs as a task of the executor, one turn of spin each, as in rclpy:
    a plain function as a _CallbackTask (no coroutine, no lock: the executor claims it),
    anything else as a Task."""
    add = getattr(executor, '_add_callback_task', None)
    if add is not None and not _is_coroutine_function(callback):
        add(_CallbackTask(callback, future))
    else:
        executor.create_task(callback, future)


class _CallbackTask:
    """What the executor needs of a Task, for a done callback: called once, by the
    executor that claimed it; its exception is raised out of spin as a Task's is."""
    __slots__ = ('_callback', '_future', '_done', '_claimed', '_exception')

    def __init__(self, callback, future):
        self._callback = callback
        self._future = future
        self._done = False
        self._claimed = False
        self._exception = None

    def __call__(self):
        if self._done:
            return
        self._done = True
        callback, future = self._callback, self._future
        self._callback = self._future = None
        try:
            callback(future)
        except Exception as e:
            self._exception = e

    def _ready(self):
        return not (self._done or self._claimed)

    def done(self):
        return self._done

    def executing(self):
        return False

    def exception(self):
        return self._exception


def _is_coroutine_function(handler):
    """inspect.iscoroutinefunction, fast for plain functions and bound methods (the
    executor's own done callbacks: one Task each per service call)."""
    code = getattr(handler, '__code__', None)
    if code is not None and code.__class__ is types.CodeType and \
            getattr(handler, '_is_coroutine_marker', None) is None:
        return bool(code.co_flags & inspect.CO_COROUTINE)
    return inspect.iscoroutinefunction(handler)


class Task(Future):
    """Execute a function or coroutine (made by executors)."""

    def __init__(self, handler, args=None, kwargs=None, executor=None):
        super().__init__(executor=executor)
        self._handler = handler
        self._args = args if args is not None else ()
        self._kwargs = kwargs if kwargs is not None else {}
        if _is_coroutine_function(handler):
            self._handler = handler(*self._args, **self._kwargs)
            self._args = None
            self._kwargs = None
        self._executing = False
        self._task_lock = threading.Lock()
        self._waiting_on = None      # the Future a coroutine awaits
        self._claimed = False        # handed to an executor thread, not yet run

    def __call__(self):
        self._claimed = False
        if self._done or self._executing or not self._task_lock.acquire(blocking=False):
            return
        try:
            if self._done:
                return
            self._executing = True
            if self._handler.__class__ is types.CoroutineType:
                try:
                    awaited = self._handler.send(None)
                    self._waiting_on = awaited if isinstance(awaited, Future) else None
                except StopIteration as e:
                    self._waiting_on = None
                    self.set_result(e.value)
                    self._complete_task()
                except Exception as e:
                    self._waiting_on = None
                    self.set_exception(e)
                    self._complete_task()
            else:
                try:
                    self.set_result(self._handler(*self._args, **self._kwargs))
                except Exception as e:
                    self.set_exception(e)
                self._complete_task()
            self._executing = False
        finally:
            self._task_lock.release()

    def _ready(self):
        """Could a call make progress now?"""
        if self._done or self._executing or self._claimed:
            return False
        w = self._waiting_on
        return w is None or w._done

    def _complete_task(self):
        self._handler = None
        self._args = None
        self._kwargs = None

    def executing(self):
        return self._executing


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
