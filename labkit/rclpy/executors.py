"""Executors: run the callbacks of their nodes. Work is found in O(1) from a ready-queue that
subscriptions/services/clients/guards push themselves onto; timers and tasks are polled."""
from collections import deque
import heapq
import inspect
import multiprocessing
import threading

from labkit.graph import world
from labkit.rclpy import _wait
from labkit.rclpy._entity import ENTITY_GEN
from labkit.rclpy.timer import TIMER_GEN
from labkit.rclpy.clock import Clock, ClockType
from labkit.rclpy.guard_condition import enter_context_handle
from labkit.rclpy.subscription import _NOTHING
from labkit.rclpy.task import Future, Task  # noqa: F401
from labkit.rclpy.utilities import get_default_context

__all__ = ['Executor', 'SingleThreadedExecutor', 'MultiThreadedExecutor', 'TimeoutException',
           'ShutdownException', 'ExternalShutdownException', 'ConditionReachedException',
           'await_or_execute']


async def await_or_execute(callback, *args):
    """Await a callback if it is a coroutine, else execute it."""
    if inspect.iscoroutinefunction(callback):
        return await callback(*args)
    return callback(*args)


class TimeoutException(Exception):
    """Signal that a timeout occurred."""


class ShutdownException(Exception):
    """Signal that executor was shut down."""


class ExternalShutdownException(Exception):
    """Context has been shutdown."""


class ConditionReachedException(Exception):
    """Future has been completed."""


class TimeoutObject:
    def __init__(self, timeout):
        self._timeout = timeout

    @property
    def timeout(self):
        return self._timeout

    @timeout.setter
    def timeout(self, timeout):
        self._timeout = timeout


def _timeout_ns(timeout_sec):
    if isinstance(timeout_sec, TimeoutObject):
        timeout_sec = timeout_sec.timeout
    if timeout_sec is None or timeout_sec < 0:
        return None
    return int(round(float(timeout_sec) * 1e9))


class Executor:
    """The base class for an executor."""

    def __init__(self, *, context=None):
        super().__init__()
        self._context = get_default_context() if context is None else context
        with enter_context_handle(self._context):     # rclpy makes its guard condition here
            pass
        self._nodes = {}                 # insertion-ordered set
        self._nodes_lock = threading.RLock()
        self._tasks = []                 # (Task, entity, node)
        self._tasks_lock = threading.Lock()
        self._ready = deque()
        self._blocked = []               # ready but their callback group was busy
        self._is_shutdown = False
        self._shutdown_lock = threading.Lock()
        self._wake_gen = 0
        self._timer_cache = ()
        self._timer_gen = None
        self._heaps = {}
        self._timer_entry = {}
        self._heap_gen = None
        self._has_waitables = False
        # rclpy.spin_once(node) adds then removes its node; the removal is deferred until
        # anything else uses this executor, which is the same to observe and much cheaper.
        self._transient = None
        self._running = 0                # callbacks in progress (for shutdown)
        self._clock = Clock(clock_type=ClockType.STEADY_TIME)
        self._context.on_shutdown(self.wake)

    @property
    def context(self):
        return self._context

    def create_task(self, callback, *args, **kwargs):
        task = Task(callback, args, kwargs, executor=self)
        with self._tasks_lock:
            self._tasks.append((task, None, None))
        self.wake()
        return task

    def _add_callback_task(self, task):
        """A future's done callback (labkit.rclpy.task._schedule), run as create_task's are."""
        with self._tasks_lock:
            self._tasks.append((task, None, None))
        self.wake()

    def shutdown(self, timeout_sec=None):
        self._finalize_transient()
        with self._shutdown_lock:
            if not self._is_shutdown:
                self._is_shutdown = True
                self.wake()
        if self._running and not _wait.wait(lambda: not self._running, _timeout_ns(timeout_sec)):
            return False
        with self._nodes_lock:
            for node in list(self._nodes):
                if node._executor_obj is self:
                    node._executor_obj = None
            self._nodes = {}
        return True

    def _finalize_transient(self):
        node = self._transient
        if node is not None:
            self._transient = None
            self.remove_node(node)

    def add_node(self, node):
        if self._transient is not None:
            self._finalize_transient()
        with self._nodes_lock:
            if node in self._nodes:
                return False
            self._nodes[node] = None
            node.executor = self
            node._executor_obj = self
            if node._unclaimed:
                for entity in node._unclaimed:
                    self._ready.append(entity)
                node._unclaimed.clear()
            self._timer_gen = None
            self.wake()
            return True

    def remove_node(self, node):
        if self._transient is not None and self._transient is not node:
            self._finalize_transient()
        self._transient = None
        with self._nodes_lock:
            if self._nodes.pop(node, 0) is None:
                if node._executor_obj is self:
                    node._executor_obj = None
                # queued work of that node waits on the node until it joins an executor
                for queue_name in ('_ready', '_blocked'):
                    queue = getattr(self, queue_name)
                    if any(e._node is node for e in queue):
                        keep = [e for e in queue if e._node is not node]
                        node._unclaimed.extend(e for e in queue if e._node is node)
                        setattr(self, queue_name, deque(keep) if queue_name == '_ready'
                                else keep)
                self._timer_gen = None
                self.wake()

    def wake(self):
        self._wake_gen += 1
        world.notify()

    def get_nodes(self):
        self._finalize_transient()
        with self._nodes_lock:
            return list(self._nodes)

    # ------------------------------------------------------------ spinning
    def spin(self):
        self._finalize_transient()
        while self._context.ok() and not self._is_shutdown:
            self.spin_once()

    def spin_until_future_complete(self, future, timeout_sec=None):
        self._finalize_transient()
        future.add_done_callback(lambda x: self.wake())
        if timeout_sec is None or timeout_sec < 0:
            while self._context.ok() and not future.done() and not self._is_shutdown:
                self.spin_once_until_future_complete(future, timeout_sec)
        else:
            end = world.steady_ns() + _timeout_ns(timeout_sec)
            timeout_left = TimeoutObject(timeout_sec)
            while self._context.ok() and not future.done() and not self._is_shutdown:
                self.spin_once_until_future_complete(future, timeout_left)
                now = world.steady_ns()
                if now >= end:
                    return
                timeout_left.timeout = (end - now) / 1e9

    def spin_once(self, timeout_sec=None):
        raise NotImplementedError()

    def spin_once_until_future_complete(self, future, timeout_sec=None):
        raise NotImplementedError()

    # ------------------------------------------------------------ finding work
    def _timers(self):
        if self._timer_gen != ENTITY_GEN[0]:
            self._refresh()
        return self._timer_cache

    def _refresh(self):
        nodes = list(self._nodes)
        self._timer_cache = tuple(t for node in nodes for t in node._timers)
        self._has_waitables = any(node._Node__waitables for node in nodes)
        self._timer_gen = ENTITY_GEN[0]
        self._build_heaps()

    # Due timers are found through heaps instead of asking every timer's clock on every spin.
    # Per time source (steady time, system time, or one clock that follows /clock) a heap
    # of deadlines holds the timers not yet due, [deadline, order, timer]; those found due
    # move to a heap by order (node order, then creation order), so the first due timer in
    # that order fires, exactly as when every timer was scanned in that order. A timer's
    # current entry is self._timer_entry[timer]; other entries are stale and dropped.
    # Deadlines move only through _call() (the executor files the timer again), reset() or
    # a new period, and /clock switching on or off: the last two bump TIMER_GEN, and the
    # heaps are rebuilt.
    def _build_heaps(self):
        heaps = {}
        entries = {}
        for order, tmr in enumerate(self._timer_cache):
            if tmr._canceled:
                continue
            entry = [tmr._next_call, order, tmr]
            entries[tmr] = entry
            heaps.setdefault(_source(tmr._clock), ([], []))[0].append(entry)
        for pending, _ in heaps.values():
            heapq.heapify(pending)
        self._heaps = heaps
        self._timer_entry = entries
        self._heap_gen = TIMER_GEN[0]

    def _timer_heaps(self):
        if self._timer_gen != ENTITY_GEN[0]:
            self._refresh()
        elif self._heap_gen != TIMER_GEN[0]:
            self._build_heaps()
        return self._heaps

    def _first_due(self, source, pending, ready):
        """(order, entry) of the first due timer of one source whose callback group can
        run it, or None; the due ones move from `pending` to `ready` on the way."""
        entries = self._timer_entry
        now = None
        while pending:
            entry = pending[0]
            tmr = entry[2]
            if entries.get(tmr) is not entry or tmr._canceled:
                heapq.heappop(pending)
                continue
            if now is None:
                now = tmr._clock._now_ns()
            if entry[0] > now:
                break
            heapq.heappop(pending)
            heapq.heappush(ready, (entry[1], entry))
        aside = None
        found = None
        while ready:
            item = ready[0]
            entry = item[1]
            tmr = entry[2]
            if entries.get(tmr) is not entry or tmr._canceled:
                heapq.heappop(ready)
                continue
            if now is None:
                now = tmr._clock._now_ns()
            if entry[0] > now:            # its clock went back (/clock): not due any more
                heapq.heappop(ready)
                heapq.heappush(pending, entry)
                continue
            if tmr.callback_group.can_execute(tmr):
                found = item
                break
            if aside is None:
                aside = []
            aside.append(heapq.heappop(ready))
        if aside:
            for item in aside:
                heapq.heappush(ready, item)
        return found

    def _ready_task(self):
        tasks = self._tasks
        if not tasks:
            return None
        with self._tasks_lock:
            tasks = self._tasks
            for t in tasks:
                if t[0]._done:           # drop finished tasks (the list is short)
                    tasks = self._tasks = [t for t in tasks if not t[0]._done]
                    break
            for task, entity, node in reversed(tasks):
                if task._ready() and (node is None or node in self._nodes):
                    return task
        return None

    def _due_timer(self):
        best = None
        for source, (pending, ready) in self._timer_heaps().items():
            if pending or ready:
                item = self._first_due(source, pending, ready)
                if item is not None and (best is None or item[0] < best[0]):
                    best = item
        return None if best is None else best[1][2]

    def _call_timer(self, tmr):
        """rcl_timer_call, and the timer filed again under its next deadline."""
        tmr._call()
        entry = self._timer_entry.get(tmr)
        if entry is not None:
            heaps = self._heaps.get(_source(tmr._clock))
            if heaps is not None:
                new = [tmr._next_call, entry[1], tmr]
                self._timer_entry[tmr] = new          # the old entry is stale now
                heapq.heappush(heaps[0], new)

    def _waitable_work(self):
        for node in list(self._nodes):
            for wt in node.waitables:
                if wt._labkit_is_ready() and wt.callback_group.can_execute(wt):
                    return wt
        return None

    def _next_work(self):
        """Select one unit of work and claim it (callback group, data taken), or None.
        Returns (kind, entity, taken data)."""
        if self._tasks:
            task = self._ready_task()
            if task is not None:
                task._claimed = True
                return ('task', task, None)
        if self._timer_gen != ENTITY_GEN[0]:
            self._refresh()
        if self._timer_cache:
            tmr = self._due_timer()
            if tmr is not None and tmr.callback_group.beginning_execution(tmr):
                self._call_timer(tmr)
                return ('timer', tmr, None)
        ready = self._ready
        while ready:
            entity = ready.popleft()
            entity._queued = False
            if entity._destroyed:
                continue
            if entity._node._executor_obj is not self:
                entity._signal()          # it belongs elsewhere (or nowhere) now
                continue
            group = entity.callback_group
            if not group.beginning_execution(entity):
                entity._queued = True
                self._blocked.append(entity)
                continue
            arg = entity._take()
            if arg is _NOTHING:
                group.ending_execution(entity)
                continue
            return (entity._kind, entity, arg)
        if self._has_waitables:
            wt = self._waitable_work()
            if wt is not None and wt.callback_group.beginning_execution(wt):
                return ('waitable', wt, wt.take_data())
        return None

    def _has_work(self):
        if self._ready:
            return True
        if self._tasks:
            for task, _, _ in self._tasks:
                if task._ready():
                    return True
        if self._timer_cache or self._timer_gen != ENTITY_GEN[0]:
            if self._due_timer() is not None:
                return True
        for node in self._nodes:
            if node._Node__waitables:
                for wt in node.waitables:
                    if wt._labkit_is_ready():
                        return True
        return False

    def _next_timer_wait_ns(self):
        best = None
        exact = True
        for source, (pending, ready) in self._timer_heaps().items():
            if source.__class__ is not str:
                continue                  # follows /clock: nothing to wait for
            if self._first_due(source, pending, ready) is not None:
                return 0
            entries = self._timer_entry
            while pending:
                entry = pending[0]
                tmr = entry[2]
                if entries.get(tmr) is not entry or tmr._canceled:
                    heapq.heappop(pending)
                    continue
                if not tmr.callback_group.can_execute(tmr):
                    exact = False         # a busy group's timer comes first: scan them all
                    break
                w = tmr._wait_ns()
                if w is not None and (best is None or w < best):
                    best = w
                break
            if not exact:
                break
        if exact:
            return best
        best = None
        for tmr in self._timers():
            if not tmr.callback_group.can_execute(tmr):
                continue                  # its group's release wakes us
            w = tmr._wait_ns()
            if w is not None and (best is None or w < best):
                best = w
        return best

    def _wait_for_work(self, timeout_sec, condition):
        """Wait until work is claimed (returned), or None on timeout/condition/shutdown."""
        timeout = _timeout_ns(timeout_sec)
        end = None if timeout is None else world.steady_ns() + timeout
        context = self._context
        while True:
            if self._is_shutdown:
                raise ShutdownException()
            if not context.ok():
                raise ExternalShutdownException()
            if condition is not None and condition():
                raise ConditionReachedException()
            wait_ns = self._next_timer_wait_ns()
            if end is not None:
                left = end - world.steady_ns()
                if left <= 0:
                    raise TimeoutException()
                wait_ns = left if wait_ns is None else min(wait_ns, left)
            gen = self._wake_gen

            def ready():
                return (self._wake_gen != gen or self._has_work() or self._is_shutdown or
                        not context.ok() or (condition is not None and condition()))

            _wait.wait(ready, wait_ns)
            work = self._next_work()
            if work is not None:
                return work

    def _get_work(self, timeout_sec, condition=None, work=None):
        if work is None:
            work = self._next_work()
        if work is not None:
            return work
        if _timeout_ns(timeout_sec) == 0:
            if self._is_shutdown:
                raise ShutdownException()
            if not self._context.ok():
                raise ExternalShutdownException()
            raise TimeoutException()
        return self._wait_for_work(timeout_sec, condition)

    # ------------------------------------------------------------ running work
    def _release(self, entity):
        entity.callback_group.ending_execution(entity)
        if self._blocked:
            self._release_blocked()

    def _release_blocked(self):
        blocked, self._blocked = self._blocked, []
        for e in blocked:
            e._queued = False
            e._signal()
        self.wake()

    def _execute(self, work):
        """Run one claimed unit of work; coroutine callbacks become tasks. Returns the Task
        whose exception must be raised, if any."""
        kind, entity, arg = work
        if kind == 'task':
            entity()
            return entity
        if kind == 'waitable':
            return self._run_coroutine(entity, self._waitable_coro(entity, arg))
        if kind == 'client':
            try:
                entity._complete(self, arg)
            finally:
                self._release(entity)
            return None
        if kind == 'timer':
            callback, args = entity.callback, ()
        else:
            callback, args = entity._callback_and_args(arg)
        if callback is not None and _is_coroutine_function(entity, callback):
            return self._run_coroutine(entity, self._callback_coro(entity, callback, args, work))
        try:
            # a Rate's timer has no callback; a subscription or service without one fails
            # here, as in rclpy ("'NoneType' object is not callable")
            if callback is not None or kind != 'timer':
                result = callback(*args)
                if kind == 'service':
                    entity.send_response(result, arg[1])
        finally:
            self._release(entity)
        return None

    def _run_coroutine(self, entity, coro):
        task = Task(coro, executor=self)
        task()
        if not task.done():
            with self._tasks_lock:
                self._tasks.append((task, entity, entity._node if entity else None))
        return task

    async def _callback_coro(self, entity, callback, args, work):
        try:
            result = await callback(*args)
            if work[0] == 'service':
                entity.send_response(result, work[2][1])
            return result
        finally:
            self._release(entity)
            self.wake()

    async def _waitable_coro(self, waitable, data):
        try:
            for future in getattr(waitable, '_futures', ()):
                future._set_executor(self)
            await waitable.execute(data)
        finally:
            self._release(waitable)
            self.wake()


def _source(clock):
    """What a clock's now comes from: 'steady', 'system', or the clock itself while it
    follows /clock (ROS time active)."""
    if clock._clock_type == ClockType.STEADY_TIME:
        return 'steady'
    if clock._ros_time_is_active:
        return clock
    return 'system'


def _is_coroutine_function(entity, callback):
    # cached per entity: inspect is slow for the hot path
    cached = entity.__dict__.get('_labkit_cb')
    if cached is not None and cached[0] is callback:
        return cached[1]
    flag = inspect.iscoroutinefunction(callback)
    entity.__dict__['_labkit_cb'] = (callback, flag)
    return flag


class SingleThreadedExecutor(Executor):
    """Runs callbacks in the thread that calls :meth:`Executor.spin`."""

    def __init__(self, *, context=None):
        super().__init__(context=context)

    def _spin_once_impl(self, timeout_sec=None, condition=None):
        if self._transient is not None:
            self._finalize_transient()
        try:
            work = self._get_work(timeout_sec, condition)
        except (ShutdownException, TimeoutException, ConditionReachedException):
            return
        handler = self._execute(work)
        if handler is not None and handler.done() and handler.exception() is not None:
            raise handler.exception()

    def spin_once(self, timeout_sec=None):
        if self._transient is not None:
            self._finalize_transient()
        work = self._next_work()
        if work is not None and work[0] == 'sub':
            # hot path: a plain (not async) subscription callback
            entity = work[1]
            callback = entity.callback
            if entity.__dict__.get('_labkit_cb') == (callback, False):
                try:
                    callback(work[2])
                finally:
                    entity.callback_group.ending_execution(entity)
                    if self._blocked:
                        self._release_blocked()
                return
        if work is None:
            try:
                work = self._get_work(timeout_sec, None)
            except (ShutdownException, TimeoutException, ConditionReachedException):
                return
        handler = self._execute(work)
        if handler is not None and handler.done() and handler.exception() is not None:
            raise handler.exception()

    def spin_once_until_future_complete(self, future, timeout_sec=None):
        self._spin_once_impl(timeout_sec, future.done)

    def spin_until_future_complete(self, future, timeout_sec=None):
        """Executor.spin_until_future_complete, one unit of work per turn as there; work
        that is ready now runs without the wait machinery (a service call is four turns:
        the request, the response and the two done-callback tasks of the call before)."""
        self._finalize_transient()
        future.add_done_callback(lambda x: self.wake())
        timed = timeout_sec is not None and timeout_sec >= 0
        steady_ns = world.steady_ns
        end = steady_ns() + _timeout_ns(timeout_sec) if timed else None
        context = self._context
        while context.ok() and not future._done and not self._is_shutdown:
            if self._transient is not None:
                self._finalize_transient()
            work = self._next_work()
            if work is None:
                left = None
                if timed:
                    left = TimeoutObject((end - steady_ns()) / 1e9)
                try:
                    work = self._get_work(left, future.done)
                except (ShutdownException, TimeoutException, ConditionReachedException):
                    work = None
            if work is not None:
                handler = self._execute(work)
                if handler is not None and handler._done and handler.exception() is not None:
                    raise handler.exception()
            if timed and steady_ns() >= end:
                return


class MultiThreadedExecutor(Executor):
    """Runs callbacks in a pool of (world) threads."""

    def __init__(self, num_threads=None, *, context=None):
        super().__init__(context=context)
        if num_threads is None:
            try:
                num_threads = multiprocessing.cpu_count()
            except NotImplementedError:
                num_threads = 1
        self._num_threads = max(1, num_threads)
        self._queue = deque()
        self._workers = []
        self._errors = []
        self._pool_stop = False

    def _start_workers(self):
        self._workers = [t for t in self._workers if t.is_alive()]
        while len(self._workers) < self._num_threads:
            name = f'ThreadPoolExecutor-{id(self) % 1000}_{len(self._workers)}'
            self._workers.append(world.start_thread(self._worker, name=name))

    def _worker(self):
        context = self._context
        while True:
            world.wait(lambda: self._queue or self._pool_stop or not context.ok()
                       or self._is_shutdown)
            if not self._queue:
                if self._pool_stop or not context.ok() or self._is_shutdown:
                    return
                continue
            work = self._queue.popleft()
            try:
                handler = self._execute(work)
                if handler is not None and handler.done() and handler.exception() is not None:
                    self._errors.append(handler.exception())
            except BaseException as exc:   # re-raised by the spinning thread
                self._errors.append(exc)
            finally:
                self._running -= 1
                self.wake()

    def _spin_once_impl(self, timeout_sec=None, condition=None):
        try:
            work = self._get_work(timeout_sec, condition)
        except (ExternalShutdownException, ShutdownException, TimeoutException,
                ConditionReachedException):
            work = None
        if work is not None:
            self._running += 1
            self._queue.append(work)
            self._start_workers()
            world.notify()
        if self._errors:
            raise self._errors.pop(0)

    def spin_once(self, timeout_sec=None):
        self._spin_once_impl(timeout_sec)

    def spin_once_until_future_complete(self, future, timeout_sec=None):
        self._spin_once_impl(timeout_sec, future.done)

    def shutdown(self, timeout_sec=None):
        ok = super().shutdown(timeout_sec)
        self._pool_stop = True
        world.notify()
        return ok


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
