"""The world clock and the scheduler (see ARCHITECTURE.md, "Time and determinism").

live:    clocks are the machine's clocks, threads run concurrently, waits are real.
virtual: "now" only moves when every known thread waits; threads run one at a time,
         holding the *baton*, and give it back only inside `wait()`.
"""
import os
import _thread
import threading
import time as _time

VIRTUAL_EPOCH = 1704067200.0          # 2024-01-01T00:00:00Z
VIRTUAL_EPOCH_NS = 1704067200 * 10**9

__all__ = ["Deadlock", "mode", "set_mode", "system_ns", "steady_ns", "wait", "notify",
           "sleep", "settle", "start_thread", "VIRTUAL_EPOCH"]


class Deadlock(RuntimeError):
    """A wait without timeout that nothing can ever satisfy (virtual time)."""


_mode = None
_now = 0                       # virtual steady time, ns


def mode():
    """'live' or 'virtual'."""
    global _mode
    if _mode is None:
        value = os.environ.get("LABKIT_TIME", "live").strip().lower()
        _mode = "virtual" if value == "virtual" else "live"
    return _mode


def set_mode(new_mode):
    """Choose the time mode; only before anything has started waiting."""
    global _mode, _now
    if new_mode not in ("live", "virtual"):
        raise ValueError("time mode must be 'live' or 'virtual'")
    _mode = new_mode
    _now = 0


def system_ns():
    """System (and ROS) time in ns since the Unix epoch."""
    if mode() == "virtual":
        return VIRTUAL_EPOCH_NS + _now
    return _time.time_ns()


def steady_ns():
    """Steady time in ns."""
    if mode() == "virtual":
        return _now
    return _time.monotonic_ns()


def _to_ns(seconds):
    return int(round(seconds * 1e9))


# ---------------------------------------------------------------- live waits
_cond = threading.Condition()
_live_waiters = 0
_generation = 0                # bumped by notify(); waiters sleep only if it did not move
_started = set()               # live mode: idents of threads that reached a wait point


def notify():
    """Something changed (a message arrived, a future finished...): wake waiters."""
    global _generation
    if _live_waiters:
        with _cond:
            _generation += 1
            _cond.notify_all()


def _live_wait(predicate, timeout_ns):
    # Predicates run without holding _cond, so they may take any other lock.
    global _live_waiters
    _started.add(threading.get_ident())
    end = None if timeout_ns is None else _time.monotonic_ns() + timeout_ns
    with _cond:
        _live_waiters += 1
    try:
        while True:
            gen = _generation
            if predicate():
                return True
            if end is None:
                left = 0.5               # bounded, in case something changed silently
            else:
                left = (end - _time.monotonic_ns()) / 1e9
                if left <= 0:
                    return bool(predicate())
                left = min(left, 0.5)
            with _cond:
                if _generation == gen:
                    _cond.wait(left)
    finally:
        with _cond:
            _live_waiters -= 1


# ------------------------------------------------------------ virtual baton
NEW, RUNNING, WAITING, DONE = "new", "running", "waiting", "done"


class _Baton:
    """threading.Event's set/wait/clear on one raw lock (held = not set): handing the
    baton to a thread is one lock release, with none of Condition's Python-level
    bookkeeping (the handover between a talker's and a listener's thread is on every
    tick of virtual time). Set only by the baton's giver under world._lock, cleared only
    by its own thread; a successful wait leaves the lock held until clear()."""
    __slots__ = ("_lock", "_set")

    def __init__(self):
        self._lock = _thread.allocate_lock()
        self._lock.acquire()
        self._set = False

    def set(self):
        if not self._set:
            self._set = True
            self._lock.release()

    def wait(self, timeout):
        return self._lock.acquire(True, timeout)

    def clear(self):
        if self._set:
            self._set = False
            self._lock.acquire(False)


class _Thread:
    __slots__ = ("thread", "state", "predicate", "deadline", "settle", "event",
                 "result", "deadlock", "order")

    def __init__(self, thread, order, state):
        self.thread = thread
        self.order = order
        self.state = state
        self.predicate = None
        self.deadline = None
        self.settle = False
        self.event = _Baton()
        self.result = False
        self.deadlock = False


_lock = threading.RLock()
_threads = []                  # creation order
_by_ident = {}
_holder = None
_order = 0


def _record(create=True):
    """The calling thread's record; unknown threads join the world on first use."""
    global _holder, _order
    ident = threading.get_ident()
    rec = _by_ident.get(ident)
    if rec is None and create:
        with _lock:
            _order += 1
            main = threading.current_thread() is threading.main_thread()
            rec = _Thread(threading.current_thread(), 0 if main else _order,
                          RUNNING)
            _by_ident[ident] = rec
            _threads.append(rec)
            _threads.sort(key=lambda r: r.order)
            if _holder is None:
                _holder = rec
    return rec


def _runnable(rec):
    if rec.state == NEW:
        return True
    if rec.state != WAITING or rec.settle:
        return False
    try:
        return bool(rec.predicate())
    except Exception:       # let the thread itself see the error
        return True


def _pick():
    """Choose the next thread to hold the baton (called with _lock held)."""
    global _now
    while True:
        live = [r for r in _threads if r.state != DONE]
        for rec in live:
            if _runnable(rec):
                rec.result = True
                return rec
        for rec in live:
            if rec.state == WAITING and not rec.settle and rec.deadline is not None \
                    and rec.deadline <= _now:
                rec.result = False
                return rec
        for rec in live:
            if rec.state == WAITING and rec.settle:
                rec.result = False
                return rec
        deadlines = [r.deadline for r in live if r.state == WAITING and r.deadline is not None]
        if deadlines:
            _now = max(_now, min(deadlines))
            continue
        for rec in live:
            if rec.state == WAITING:
                rec.deadlock = True
                return rec
        return None


def _hand_over():
    """Give the baton to whoever runs next (caller must no longer be RUNNING)."""
    global _holder
    with _lock:
        nxt = _pick()
        _holder = nxt
        if nxt is not None:
            if nxt.state == WAITING:
                nxt.state = RUNNING
            elif nxt.state == NEW:
                nxt.state = RUNNING
            nxt.event.set()


def _block(rec):
    """Sleep until this thread holds the baton again (an interrupt is re-raised after)."""
    try:
        _block_inner(rec)
    except KeyboardInterrupt:
        # A signal hit this thread while another held the baton: become runnable at once,
        # wait for our turn (so only one thread ever runs), then let the interrupt through.
        with _lock:
            if _holder is not rec:
                rec.predicate = lambda: True
                rec.deadline = None
                rec.settle = False
        _block_inner(rec)
        rec.deadlock = False
        raise


def _block_inner(rec):
    while not rec.event.wait(0.2):
        # Rescue: the holder may have died without handing over (a foreign thread).
        with _lock:
            h = _holder
            if h is not None and h is not rec and not h.thread.is_alive():
                h.state = DONE
                _forget(h)
                _hand_over()
    rec.event.clear()


def _forget(rec):
    _by_ident.pop(rec.thread.ident, None)
    if rec in _threads:
        _threads.remove(rec)


def _virtual_wait(predicate, timeout_ns, settle=False):
    rec = _record()
    if predicate() and not settle:
        return True
    now0 = _now
    with _lock:
        rec.predicate = predicate
        rec.deadline = None if timeout_ns is None else now0 + timeout_ns
        rec.settle = settle
        rec.deadlock = False
        holding = _holder is rec or _holder is None
        rec.state = WAITING
        rec.event.clear()
        if holding:
            _hand_over()
    _block(rec)
    rec.predicate = None
    rec.settle = False
    if rec.deadlock:
        rec.deadlock = False
        raise Deadlock("every thread waits and nothing can wake them (virtual time): this "
                       "call would block forever on a real ROS 2 system too (is the node "
                       "that should answer spinning?)")
    return rec.result or bool(predicate())


def wait(predicate, timeout_s=None, *, timeout_ns=None):
    """Wait until predicate() is true or the timeout passes; return predicate's truth.

    The one wait point of labkit: executors, Rate.sleep, futures, clients and
    labkit.sleep all wait here.
    """
    if timeout_ns is None and timeout_s is not None:
        timeout_ns = max(0, _to_ns(timeout_s))
    if mode() == "virtual":
        return _virtual_wait(predicate, timeout_ns)
    return _live_wait(predicate, timeout_ns)


def sleep(seconds):
    """Let the world run for `seconds` (real seconds in live mode)."""
    if mode() == "virtual":
        _virtual_wait(lambda: False, max(0, _to_ns(seconds)))
    else:
        _started.add(threading.get_ident())
        if seconds > 0:
            _time.sleep(seconds)


def settle():
    """Run every runnable thread until quiescent, without advancing time."""
    if mode() == "virtual":
        _virtual_wait(lambda: False, None, settle=True)


def adopt(thread):
    """Make a not-yet-started thread a world thread (virtual time): it first runs when the
    scheduler gives it the baton. Returns (enter, started): call enter() first thing in
    the new thread, started() right after thread.start()."""
    global _order
    _record()                  # the creator is known too
    ready = threading.Event()
    with _lock:
        _order += 1
        rec = _Thread(thread, _order, NEW)
        _threads.append(rec)
    thread._labkit_world = True

    def enter():
        ready.wait()
        _block(rec)

    def started():
        _by_ident[thread.ident] = rec
        ready.set()
    return enter, started


def start_thread(target, name=None, args=(), kwargs=None, daemon=True):
    """Start a thread the world knows (it takes part in the baton in virtual time)."""
    kwargs = kwargs or {}
    if mode() != "virtual":
        t = threading.Thread(target=target, args=args, kwargs=kwargs, name=name, daemon=daemon)
        t.start()
        return t
    box = {}

    def run():
        box["enter"]()
        try:
            target(*args, **kwargs)
        finally:
            thread_exit()

    t = threading.Thread(target=run, name=name, daemon=daemon)
    box["enter"], started = adopt(t)
    t.start()
    started()
    return t


def finished(thread):
    """Has a world thread finished its target (it may still be unwinding)?"""
    if mode() == "virtual" and thread.ident is not None:
        rec = _by_ident.get(thread.ident)
        return rec is None or rec.state == DONE
    return not thread.is_alive()


def is_member(thread=None):
    """Virtual time: does this thread take part in the baton (a world thread)?"""
    thread = thread or threading.current_thread()
    return thread.ident in _by_ident


def thread_waiting(thread):
    """Virtual time: is this world thread parked at a wait point?"""
    rec = _by_ident.get(thread.ident)
    return rec is not None and rec.state == WAITING


def wait_started(thread, timeout_s):
    """Live time: wait (really) until a thread reached its first wait point or ended."""
    end = _time.monotonic() + timeout_s
    while thread.is_alive() and thread.ident not in _started and _time.monotonic() < end:
        _time.sleep(0.001)


def join(thread, timeout_s=None):
    """Join a thread; a world thread is waited for at a wait point (so it can run)."""
    if mode() == "virtual" and threading.current_thread() is not thread and \
            thread.ident is not None and _by_ident.get(thread.ident) is not None:
        try:
            wait(lambda: finished(thread), timeout_s)
        except Deadlock:
            pass
        if not finished(thread):
            return False
        timeout_s = 1.0           # it is only unwinding now
    threading.Thread.join(thread, timeout_s)
    return not thread.is_alive()


def restart_clock():
    """Virtual time back to the epoch (labkit.reset(); only once nothing else runs)."""
    global _now
    if mode() != "virtual":
        return
    others = [r for r in _threads if r.state not in (DONE,) and r.thread is not
              threading.current_thread() and r.thread.is_alive()]
    waiting_with_deadline = [r for r in others if r.deadline is not None]
    if not waiting_with_deadline:
        _now = 0


def thread_exit():
    """The calling thread ends: leave the world (hand the baton on if holding it)."""
    _started.discard(threading.get_ident())
    rec = _by_ident.get(threading.get_ident())
    if rec is None:
        return
    with _lock:
        rec.state = DONE
        _forget(rec)
        if _holder is rec:
            _hand_over()
