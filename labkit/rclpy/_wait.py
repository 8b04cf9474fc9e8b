"""rclpy's blocking calls wait here: a world wait point that also notices a process stop
(which, like SIGINT on a real process, raises KeyboardInterrupt in its main thread)."""
import threading

from labkit.graph import world


def _interrupt_pending(proc):
    return proc._sigint and threading.current_thread() is proc.thread


def wait(predicate, timeout_ns=None):
    from labkit import process
    proc = process.current()
    if proc is process.MAIN:
        return world.wait(predicate, timeout_ns=timeout_ns)
    if _interrupt_pending(proc):
        proc._sigint = False
        raise KeyboardInterrupt
    result = world.wait(lambda: predicate() or proc._sigint, timeout_ns=timeout_ns)
    if _interrupt_pending(proc):
        proc._sigint = False
        raise KeyboardInterrupt
    return result and predicate()


def wait_s(predicate, timeout_s=None):
    return wait(predicate, None if timeout_s is None else max(0, int(round(timeout_s * 1e9))))
