""""Processes" (ARCHITECTURE.md, layer 3): each `ros2 run`/launched executable runs in
its own thread(s) with its own default Context, global executor and logging state,
as if it were its own OS process. The notebook/script itself is process `main`.
"""
import io
import itertools
import linecache
import os
import sys
import threading
import time
import traceback

from labkit.graph import world

__all__ = ["Process", "current", "start", "processes", "reset_all", "main_process"]

_pids = itertools.count(4001)         # fake pids, deterministic
_lock = threading.RLock()
_echo_lock = threading.RLock()        # one writer's lines at a time reach the notebook
MAX_OUTPUT_LINES = 20000              # Process.output keeps the newest this many lines


class RclpyState:
    """rclpy's per-process globals."""

    def __init__(self):
        self.default_context = None
        self.global_executor = None
        self.logging = None             # rcutils-like config, made by labkit.rclpy on demand
        self.contexts = []              # every Context initialised in this process
        self.nodes = []                 # every Node created in this process


class Process:
    def __init__(self, name, argv=None, pid=None):
        self.name = name
        self.argv = list(argv or [])
        self.pid = pid if pid is not None else next(_pids)
        self.output = []                # lines printed (stdout and stderr)
        self.rclpy = RclpyState()
        self.thread = None
        self.returncode = None
        self.echo = True                # echo output to the notebook/console
        self.sink = None                # optional callable(stream_name, text)
        self.view = None                # optional live output area: .write(stream_name, text)
        self.windows = []               # live views it opened (canvas, keypad): shown again
        self.parent = None              # the process that started it
        self._partial = {"stdout": "", "stderr": ""}
        self._echo_partial = {"stdout": "", "stderr": ""}   # a line not yet ended
        self._sigint = False            # a stop request, delivered like SIGINT
        self.cpp = False                # a C++ program in real ROS (rclcpp handles SIGINT)
        self.closing = False            # labkit.reset(): its terminal is closed, shows nothing
        self.exit_hooks = []            # callable(returncode), run in it as it ends (ros2 run)
        self.aborted = None             # abort(): the status it dies with (-6, SIGABRT)

    def __repr__(self):
        state = "running" if self.running else f"exited {self.returncode}"
        return f"<Process {self.name} pid={self.pid} {state}>"

    @property
    def running(self):
        return self.thread is not None and self.returncode is None

    # -- output --------------------------------------------------------------
    def _write(self, stream_name, text):
        if self.aborted is not None:
            return                      # it is dead: nothing it would still print shows
        buf = self._partial[stream_name] + text
        *lines, rest = buf.split("\n")
        self.output.extend(lines)
        if len(self.output) > 2 * MAX_OUTPUT_LINES:   # a flood must not grow without bound
            del self.output[:len(self.output) - MAX_OUTPUT_LINES]
        self._partial[stream_name] = rest
        if self.sink is not None:
            self.sink(stream_name, text)
        elif self.echo:
            self.echo_text(stream_name, text)

    def echo_text(self, stream_name, text, flush=True):
        """Show `text` as this process's output, whole lines at a time: like a terminal's
        line discipline, so two writers' lines never interleave mid-line (the rest waits
        for its newline, the cell's end or the process's end)."""
        with _echo_lock:
            buf = self._echo_partial[stream_name] + text
            cut = buf.rfind("\n") + 1
            self._echo_partial[stream_name] = buf[cut:]
            if cut:
                self._echo(stream_name, buf[:cut], flush)

    def _echo(self, stream_name, text, flush=True):
        with _echo_lock:
            if self.view is not None:
                self.view.write(stream_name, text)
                return
            target = _original[stream_name]
            if target is not None:
                try:
                    if flush:
                        flush_other(stream_name)
                    target.write(text)
                    if flush:
                        target.flush()
                except Exception:
                    pass

    def flush_echo(self):
        """Show a line the process started but has not ended yet (at a cell's end, at exit)."""
        with _echo_lock:
            for key in ("stdout", "stderr"):
                text, self._echo_partial[key] = self._echo_partial[key], ""
                if text:
                    self._echo(key, text)

    def _flush_partial(self):
        for key in ("stdout", "stderr"):
            if self._partial[key]:
                self.output.append(self._partial[key])
                self._partial[key] = ""
        self.flush_echo()

    # -- lifecycle -----------------------------------------------------------
    def stop(self, timeout_s=2.0):
        """Shut its contexts (so spin returns), join its threads, destroy its nodes."""
        if self is MAIN:
            _clear_rclpy_state(self)
            return
        # like SIGINT on a real rclpy process: KeyboardInterrupt in its main thread (at its
        # next wait point) and every context shut down
        if self.running:
            self._sigint = True
            if self.cpp and not self.closing:
                self._rclcpp_signal_line()
        for ctx in list(self.rclpy.contexts):
            try:
                ctx.try_shutdown()
            except Exception:
                pass
        world.notify()
        if self.thread is not None and self.thread is not threading.current_thread():
            world.join(self.thread, timeout_s)
        for thread in threading.enumerate():     # the other threads it started
            if getattr(thread, "_labkit_process", None) is self and \
                    thread is not threading.current_thread() and thread is not self.thread:
                world.join(thread, timeout_s)
        _clear_rclpy_state(self)
        if self.returncode is None:
            self.returncode = -2 if (self.thread and self.thread.is_alive()) else 0
        with _lock:
            if self in _processes:
                _processes.remove(self)
        self._flush_partial()

    def _rclcpp_signal_line(self):
        """rclcpp's signal handler logs the signal it got (Humble: rclcpp/signal_handler.cpp),
        in the process's own output, with its logging settings."""
        thread = threading.current_thread()
        saved = getattr(thread, "_labkit_process", None)
        thread._labkit_process = self
        try:
            from labkit.rclpy.impl import rcutils_logger
            from labkit.rclpy.impl.logging_severity import LoggingSeverity
            if rcutils_logger._config().effective_level("rclcpp") <= LoggingSeverity.INFO:
                rcutils_logger.emit(LoggingSeverity.INFO, "rclcpp", "signal_handler(signum=2)")
        except Exception:
            pass
        finally:
            if saved is None:
                del thread._labkit_process
            else:
                thread._labkit_process = saved

    def wait(self, timeout_s=None):
        """Wait (a world wait point) until the process ends; returns its returncode."""
        if self.thread is not None:
            world.wait(lambda: not self.running, timeout_s)
        return self.returncode


class Aborted(BaseException):
    """The process called std::abort() (an uncaught C++ exception): it ends at once."""


def abort_current(text, code=-6):
    """What an uncaught C++ exception does to a real process: libstdc++'s terminate lines
    (`text`) on stderr, then SIGABRT: the process ends with `code` (a shell shows 134),
    nothing else it would print shows, no destructor runs. Called from any of its threads;
    the caller then ends (raise Aborted, or return from its thread)."""
    proc = current()
    sys.stderr.write(text)
    if proc is MAIN:
        raise Aborted(text.rstrip("\n"))
    proc.aborted = code
    proc._sigint = True                 # its main thread leaves its wait point now
    world.notify()


def _clear_rclpy_state(proc):
    state = proc.rclpy
    for node in list(state.nodes):
        try:
            node.destroy_node()
        except Exception:
            pass
    state.nodes.clear()
    for ctx in list(state.contexts):
        try:
            ctx.try_shutdown()
        except Exception:
            pass
    state.contexts.clear()
    if proc is MAIN:
        from labkit.rclpy.signals import uninstall_signal_handlers
        uninstall_signal_handlers()     # what rclpy.init installed (reset: a fresh start)
    state.default_context = None
    state.global_executor = None
    state.logging = None


MAIN = Process("main", argv=list(sys.argv), pid=next(_pids))
_processes = []


def main_process():
    return MAIN


def current():
    """The process of the calling thread (threads inherit their starter's process)."""
    return getattr(threading.current_thread(), "_labkit_process", None) or MAIN


# Threads started inside a process belong to it, like threads of a real process.
_original_thread_start = threading.Thread.start


def _thread_start(self):
    proc = current()
    if getattr(self, "_labkit_process", None) is None and proc is not MAIN:
        self._labkit_process = proc
    enter = started = None
    if world.mode() == "virtual" and not getattr(self, "_labkit_world", False) and \
            _spins_rclpy(self):
        # a thread that spins rclpy takes part in virtual time from its first line, so what
        # it does is deterministic; other threads join at their first wait point (a thread
        # that never waits there, e.g. a live widget poller, must not hold the baton)
        enter, started = world.adopt(self)
    run = self.run

    def run_then_leave_world():
        # a thread that waited at a world wait point must hand the baton on when it ends
        try:
            if enter is not None:
                enter()
            run()
        finally:
            world.thread_exit()
    self.run = run_then_leave_world
    if enter is not None:
        # joining it is a wait point, or the joiner would hold the baton it needs
        self.join = lambda timeout=None: world.join(self, timeout)
    result = _original_thread_start(self)
    if started is not None:
        started()
    return result


def _spins_rclpy(thread):
    target = getattr(thread, "_target", None)
    module = getattr(target, "__module__", None) or ""
    return module.startswith(("labkit.rclpy", "rclpy"))


threading.Thread.start = _thread_start


# In virtual time a process that calls time.sleep() must not hold the world still for
# real seconds: it sleeps in virtual time (a wait point), and a stop interrupts it (in
# live time too: a `while True: ...; time.sleep(1)` program ends at Ctrl-C / its Stop).
_real_sleep = time.sleep


# Sleeps of the machinery around the notebook (ipykernel pauses 0.5 ms after
# every cell) are real pauses: they must not move the ROS clock, or stored
# timestamps would depend on the kernel's version.
_HOST_MODULES = ("ipykernel", "zmq", "tornado", "jupyter_client", "asyncio", "traitlets")


def _called_by_host() -> bool:
    caller = sys._getframe(2).f_globals.get("__name__", "")
    return caller.split(".", 1)[0] in _HOST_MODULES


def _process_sleep(seconds):
    # live time: real sleeps, but a process's sleep still ends at a stop (Ctrl-C), below
    if _called_by_host() or (world.mode() != "virtual" and current() is MAIN):
        return _real_sleep(seconds)
    proc = current()
    if proc is MAIN:
        # The notebook/script itself: its main thread and the threads the world
        # schedules (executor workers) sleep in virtual time too, so `time.sleep(1)`
        # in a cell or an execute callback lets the graph live one second.
        if threading.current_thread() is threading.main_thread() or world.is_member():
            if seconds < 0:
                raise ValueError("sleep length must be non-negative")
            return world.sleep(seconds)
        return _real_sleep(seconds)
    if seconds < 0:
        raise ValueError("sleep length must be non-negative")
    world.wait(lambda: proc._sigint, seconds)
    if proc._sigint and threading.current_thread() is proc.thread:
        proc._sigint = False
        raise KeyboardInterrupt


time.sleep = _process_sleep


# ------------------------------------------------------------ output proxy
_original = {"stdout": None, "stderr": None}
_unflushed = {"stdout": False, "stderr": False}   # the main process wrote since a flush


def flush_other(stream_name):
    """Before a line goes out on one stream, what is waiting on the other goes first: a
    kernel sends each stream when it flushes it, so without this the notebook's order
    would depend on a timer instead of on what happened first."""
    other = _original["stderr" if stream_name == "stdout" else "stdout"]
    if other is not None:
        try:
            other.flush()
        except Exception:
            pass


class _StreamProxy(io.TextIOBase):
    """sys.stdout/sys.stderr: the main process writes through, others to their own sink."""

    def __init__(self, name, target):
        self._name = name
        self._target = target

    def write(self, text):
        proc = current()
        if proc is MAIN:
            # a switch of stream sends what waits on the other one first, as a terminal
            # would show it (a kernel sends each stream on its own timer otherwise)
            other = "stderr" if self._name == "stdout" else "stdout"
            if _unflushed[other]:
                _unflushed[other] = False
                flush_other(self._name)
            _unflushed[self._name] = True
            return self._target.write(text)
        proc._write(self._name, text)
        return len(text)

    def flush(self):
        _unflushed[self._name] = False
        try:
            self._target.flush()
        except Exception:
            pass

    def __getattr__(self, item):
        return getattr(self._target, item)

    @property
    def encoding(self):
        return getattr(self._target, "encoding", "utf-8")

    def isatty(self):
        return False

    def fileno(self):
        return self._target.fileno()

    def writable(self):
        return True


def install_output_proxy():
    for name in ("stdout", "stderr"):
        stream = getattr(sys, name)
        if not isinstance(stream, _StreamProxy):
            _original[name] = stream
            setattr(sys, name, _StreamProxy(name, stream))
        else:
            _original[name] = stream._target


# ------------------------------------------------------------ start
def _resolve(argv):
    from labkit import executables, plugins
    plugins.register_all()
    if len(argv) < 2:
        raise LookupError("ros2 run needs a package and an executable")
    package, executable = argv[0], argv[1]
    target = executables.lookup(package, executable)
    if target is None:
        raise LookupError("No executable found")
    exe_path = executables.path_of(package, executable)
    program = executables.resolve(target)
    program._labkit_cpp = bool(getattr(target, "cpp", False))
    return program, [exe_path] + list(argv[2:])


def _import_here():
    """numpy (through the CDR serializer, which every message copy and bag uses) is
    imported lazily since labkit exec's start-up work; import it here, in the thread that
    starts a process, never first inside a process's own thread: under Windows a first
    import of numpy in a process thread while the notebook kept computing stalled that
    thread (`ros2 bag record` kept 1 frame of 45; tests/bag/test_lossless.py in the
    Windows job)."""
    import labkit.interfaces.cdr  # noqa: F401


def start(argv=None, name=None, *, main=None, args=None, echo=True, sink=None):
    """Start a process: `argv` as `ros2 run` gets it (package, executable, args...),
    or `main=` a callable taking args=. Returns once it reached its first wait point."""
    if main is None:
        main, args = _resolve(list(argv))
    elif args is None:
        args = [name or getattr(main, "__name__", "process")]
    if name is None:
        name = argv[1] if argv and len(argv) > 1 else getattr(main, "__name__", "process")
    _import_here()
    install_output_proxy()
    _install_argv_proxy()
    proc = Process(name, argv=args)
    proc.cpp = bool(getattr(main, "_labkit_cpp", False))
    proc.parent = current()             # who started it (a launch starts its nodes)
    proc.echo = echo
    proc.sink = sink

    def body():
        threading.current_thread()._labkit_process = proc
        code = 0
        try:
            result = main(args=args) if _takes_args(main) else main()
            if isinstance(result, int):
                code = result
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
            if exc.code is not None and not isinstance(exc.code, int):
                sys.stderr.write(f"{exc.code}\n")
        except Aborted:
            code = proc.aborted
        except KeyboardInterrupt as exc:
            if proc.aborted is not None:
                raise Aborted from None
            # SIGINT: rclcpp ends a C++ program's spin and it returns normally; a Python
            # program that does not catch it dies of it, and Python prints the traceback
            code = 0 if proc.cpp else -2
            if not proc.cpp and not proc.closing and _has_user_frames(exc):
                sys.stderr.write(python_traceback(exc))
        except BaseException as exc:
            sys.stderr.write(python_traceback(exc))
            code = 1
        finally:
            if proc.aborted is not None:
                code = proc.aborted     # std::abort(): no cleanup of its own counts
            for hook in list(proc.exit_hooks):
                try:
                    hook(code)
                except Exception:
                    pass
            proc.returncode = code
            # a real process that exits leaves nothing behind in the graph
            _clear_rclpy_state(proc)
            proc._flush_partial()
            world.notify()

    reap()
    with _lock:
        _processes.append(proc)
    if live_view is not None and echo and sink is None and proc.parent is MAIN:
        # live JupyterLab: what it prints goes to its own output area in this cell, never
        # into whatever cell runs next
        proc.view = live_view(proc)
    proc.thread = world.start_thread(body, name=f"labkit-{name}-{proc.pid}")
    proc.thread._labkit_process = proc
    _wait_first_wait_point(proc)
    return proc


def _takes_args(main):
    """console_scripts call main(); ROS templates define main(args=None)."""
    import inspect
    try:
        params = inspect.signature(main).parameters
    except (TypeError, ValueError):
        return True
    return "args" in params or any(p.kind == p.VAR_KEYWORD for p in params.values())


def argv():
    """What sys.argv is for the calling thread's process (its own argv in a process)."""
    proc = current()
    if proc is not MAIN:
        return proc.argv
    return sys.argv._main if isinstance(sys.argv, _ArgvProxy) else sys.argv


class _ArgvProxy(list):
    """sys.argv as each process sees it: a node run with `ros2 run pkg exe a b` that
    reads sys.argv (as the seed's static broadcaster does) gets [exe, 'a', 'b'], while
    the notebook or script itself keeps its own. The list's own storage holds the main
    argv, so C-level copies (list(sys.argv)) give the main one."""

    def __init__(self, main):
        super().__init__(main)
        self._main = main

    def _target(self):
        proc = current()
        return self._main if proc is MAIN else proc.argv

    def __getitem__(self, index):
        return self._target()[index]

    def __len__(self):
        return len(self._target())

    def __iter__(self):
        return iter(self._target())

    def __contains__(self, item):
        return item in self._target()

    def __eq__(self, other):
        return self._target() == other

    def __ne__(self, other):
        return self._target() != other

    def __add__(self, other):
        return list(self._target()) + list(other)

    def __repr__(self):
        return repr(self._target())

    def index(self, *args):
        return self._target().index(*args)

    def count(self, item):
        return self._target().count(item)

    def copy(self):
        return list(self._target())

    def __setitem__(self, index, value):
        self._target()[index] = value

    def append(self, item):
        self._target().append(item)

    def pop(self, *args):
        return self._target().pop(*args)


def _install_argv_proxy():
    """Wrap the current sys.argv (a script may have replaced it: labkit exec does)."""
    if not isinstance(sys.argv, _ArgvProxy):
        sys.argv = _ArgvProxy(sys.argv)


def _wait_first_wait_point(proc):
    thread = proc.thread
    if world.mode() == "virtual":
        world.wait(lambda: world.finished(thread) or world.thread_waiting(thread), None)
    else:
        world.wait_started(thread, 5.0)


def processes():
    """Running and finished-but-not-reaped background processes, in start order."""
    with _lock:
        return list(_processes)


def reap():
    """Forget processes that have ended on their own (a real shell reaps its children):
    nothing keeps a finished process, its output or its nodes alive."""
    with _lock:
        _processes[:] = [p for p in _processes
                         if p.returncode is None or (p.thread is not None and p.thread.is_alive())]


def descendants(proc):
    """`proc` and every process it started, directly or not (that are still known)."""
    found = [proc]
    for other in processes():
        p = other.parent
        while p is not None and p is not other:
            if p is proc:
                found.append(other)
                break
            p = p.parent
    return found


def flush_echo_all():
    """Show every process's unfinished line (a notebook cell has ended)."""
    for proc in processes():
        proc.flush_echo()


# called by labkit.reset() after every process stopped (jobs forget their handles, ...)
reset_hooks = []

# live JupyterLab: callable(process) -> its output area (.write(stream_name, text)) or None,
# for a process the notebook starts itself; set by `%load_ext labkit` (labkit.cli.magics)
live_view = None


def reset_all():
    """Stop every process, shut every context down, clear the graph."""
    for proc in reversed(processes()):
        proc.closing = True             # its window is closed: nothing more shows
        proc.stop()
    MAIN.stop()
    for hook in list(reset_hooks):
        try:
            hook()
        except Exception:
            pass
    from labkit.graph.registry import GRAPH
    GRAPH.clear()
    # let threads that were told to stop finish, then virtual time starts over too: what
    # follows a reset prints the same every run
    try:
        world.settle()
    except world.Deadlock:
        pass
    world.restart_clock()


# ------------------------------------------------------------ how a Python program dies
# Humble runs Python 3.10 (no ^^^ markers under a frame) and its rclpy is installed here:
HUMBLE_RCLPY = "/opt/ros/humble/local/lib/python3.10/dist-packages/rclpy/"
_LABKIT_DIR = os.path.dirname(os.path.abspath(__file__)) + os.sep
_WAIT = [("executors.py", 728, "_spin_once_impl",
          "handler, entity, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)"),
         ("executors.py", 711, "wait_for_ready_callbacks", "return next(self._cb_iter)"),
         ("executors.py", 608, "_wait_for_ready_callbacks", "wait_set.wait(timeout_nsec)")]
_SPIN_ONCE = [("executors.py", 739, "spin_once", "self._spin_once_impl(timeout_sec)")] + _WAIT
_UNTIL = [("executors.py", 303, "spin_until_future_complete",
           "self.spin_once_until_future_complete(future, timeout_sec)"),
          ("executors.py", 746, "spin_once_until_future_complete",
           "self._spin_once_impl(timeout_sec)")] + _WAIT
# where a program's code entered rclpy -> the frames Humble's rclpy 3.3.15 shows below it
# when SIGINT arrives while it waits (SingleThreadedExecutor)
_HUMBLE_FRAMES = {
    ("__init__.py", "spin"): [("__init__.py", 226, "spin", "executor.spin_once()")]
    + _SPIN_ONCE,
    ("__init__.py", "spin_once"): [("__init__.py", 206, "spin_once",
                                    "executor.spin_once(timeout_sec=timeout_sec)")] + _SPIN_ONCE,
    ("__init__.py", "spin_until_future_complete"): [
        ("__init__.py", 253, "spin_until_future_complete",
         "executor.spin_until_future_complete(future, timeout_sec)")] + _UNTIL,
    ("executors.py", "spin"): [("executors.py", 294, "spin", "self.spin_once()")] + _SPIN_ONCE,
    ("executors.py", "spin_once"): _SPIN_ONCE,
    ("executors.py", "spin_until_future_complete"): _UNTIL,
}


def _is_labkit(filename):
    return os.path.abspath(filename).startswith(_LABKIT_DIR)


def _is_cell(filename):
    """Code typed into a notebook cell (ipykernel compiles it to a temporary file)."""
    return filename.startswith("<") or \
        os.path.basename(os.path.dirname(filename)).startswith("ipykernel_")


def _has_user_frames(exc):
    """A program of files of its own (a package's node, a script) was running. A `main`
    typed into a notebook cell and started as a process has no file a terminal could
    name: its interrupt stays silent (before, and in stored outputs, the same each run)."""
    tb = exc.__traceback__
    found = False
    while tb is not None:
        filename = tb.tb_frame.f_code.co_filename
        if _is_cell(filename):
            return False
        if not _is_labkit(filename):
            found = True
        tb = tb.tb_next
    return found


# how a terminal on a Humble machine names a file (labkit.ament.index sets it: the sandbox
# home as /root, bundled packages under /opt/ros/humble)
shown_path = None


def _frame_text(filename, lineno, name, line):
    if shown_path is not None:
        try:
            filename = shown_path(filename)
        except Exception:
            pass
    text = f'  File "{filename}", line {lineno}, in {name}\n'
    return text + (f"    {line.strip()}\n" if line and line.strip() else "")


def _exception_line(exc):
    """The last line(s) as the interpreter prints them (with 'Did you mean ...?', which
    Python 3.10 and 3.11 add only there, not in the traceback module)."""
    buf = io.StringIO()
    saved_tb, saved_err = exc.__traceback__, sys.stderr
    exc.__traceback__, sys.stderr = None, buf
    try:
        sys.__excepthook__(type(exc), exc, None)
    except Exception:
        buf.write("".join(traceback.format_exception_only(type(exc), exc)))
    finally:
        exc.__traceback__, sys.stderr = saved_tb, saved_err
    lines = buf.getvalue().splitlines(keepends=True)
    if lines and lines[0].startswith("Traceback"):
        lines = lines[1:]
    return "".join(lines)


def python_traceback(exc):
    """What a real ROS 2 Humble install prints when a Python program dies of `exc`: the
    program's own frames, none of labkit's (a real install has no such files); where it
    was waiting inside rclpy, the frames Humble's rclpy shows there."""
    frames = []
    tb = exc.__traceback__
    entered = None
    while tb is not None:
        code = tb.tb_frame.f_code
        if not _is_labkit(code.co_filename):
            frames.append(_frame_text(code.co_filename, tb.tb_lineno, code.co_name,
                                      linecache.getline(code.co_filename, tb.tb_lineno)))
            entered = None
        elif entered is None:
            rel = os.path.relpath(code.co_filename, _LABKIT_DIR)
            entered = (os.path.basename(rel), code.co_name) if rel.startswith("rclpy") \
                else ("", "")
            for file, lineno, name, line in _HUMBLE_FRAMES.get(entered, ()) \
                    if isinstance(exc, KeyboardInterrupt) else ():
                frames.append(_frame_text(HUMBLE_RCLPY + file, lineno, name, line))
        tb = tb.tb_next
    head = "Traceback (most recent call last):\n" if frames else ""
    return head + "".join(frames) + _exception_line(exc)

