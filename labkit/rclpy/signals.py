"""rclpy.signals: what SIGINT does to a program that called rclpy.init().

Humble's rclpy installs a signal handler at init (SignalHandlerOptions.ALL unless told
otherwise): on SIGINT it shuts every context of the process down (so `rclpy.ok()` is
False and a later `rclpy.shutdown()` raises RCLError: rcl_shutdown already called) and
then calls the handler that was there before (Python's: KeyboardInterrupt).

In labkit a background process gets its "SIGINT" from a stop (Process.stop: the Stop
button, `%ros2 jobs stop`, `job.stop()`), which does the same to its contexts. The real
handler below is installed only for the program itself in a terminal (`labkit exec`,
a plain script): inside a Jupyter kernel an interrupt stays the kernel's own (it must not
shut the notebook's rclpy down for good).
"""
from enum import IntEnum
import signal
import threading


class SignalHandlerOptions(IntEnum):
    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


_installed = {}          # signal number -> the handler that was there before ours


def _in_kernel():
    import sys
    if 'IPython' not in sys.modules:      # no kernel without it: do not import it (slow)
        return False
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and getattr(shell, 'kernel', None) is not None


def _shutdown_contexts_of_main():
    from labkit import process
    for ctx in list(process.main_process().rclpy.contexts):
        # lock-free: a signal handler runs between two bytecodes of the main thread,
        # which may hold any lock; the executors see ok() turn False
        ctx._ok = False


def _handler(signum, frame):
    _shutdown_contexts_of_main()
    previous = _installed.get(signum)
    if callable(previous):
        return previous(signum, frame)
    if previous == signal.SIG_DFL and signum == signal.SIGINT:
        raise KeyboardInterrupt
    if previous == signal.SIG_DFL:
        signal.signal(signum, signal.SIG_DFL)
        signal.raise_signal(signum)


def install_signal_handlers(options=SignalHandlerOptions.ALL):
    from labkit import process
    options = SignalHandlerOptions(options)
    if options == SignalHandlerOptions.NO or _installed:
        return
    if threading.current_thread() is not threading.main_thread() or \
            process.current() is not process.main_process() or _in_kernel():
        return
    wanted = []
    if options in (SignalHandlerOptions.SIGINT, SignalHandlerOptions.ALL):
        wanted.append(signal.SIGINT)
    if options in (SignalHandlerOptions.SIGTERM, SignalHandlerOptions.ALL):
        wanted.append(signal.SIGTERM)
    for signum in wanted:
        previous = signal.getsignal(signum)
        if previous is signal.SIG_IGN:
            continue            # a shell that ignores it for us (a background job)
        _installed[signum] = previous
        signal.signal(signum, _handler)
    _installed.setdefault('options', options)


def get_current_signal_handlers_options():
    return _installed.get('options', SignalHandlerOptions.NO)


def uninstall_signal_handlers():
    if threading.current_thread() is not threading.main_thread():
        return
    for signum, previous in list(_installed.items()):
        if signum == 'options':
            continue
        if signal.getsignal(signum) is _handler:
            signal.signal(signum, previous if previous is not None else signal.SIG_DFL)
    _installed.clear()


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
