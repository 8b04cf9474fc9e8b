"""A fast publisher's small samples, several to a datagram (Cyclone's writer batching).

A Python loop publishing through labkit writes ~15 times as many messages per second as
real rclpy can: one datagram each overran a real subscriber's socket buffer (tens of
thousands dropped, repaired by retransmits) and the peer's receive thread spent its core
on datagrams. A topic writer created with `POLICY` (Cyclone's WRITER_BATCHING QoS) queues
what it writes until `dds_write_flush`; `Batch.wrote` sends at once unless the writer is
in a burst (this write and `STREAK` before it, since its last pause of `IDLE_S`, each
followed the previous one within `GAP_S`), and then every `limit` samples (the writer's
history depth, at most `MAX_PENDING`: a reader as deep as the writer holds a whole batch);
the bridge thread, woken, sends what is left of a burst as soon as it gets the GIL (at once
when the publishing thread waits). A write after a pause of `GAP_S` or more goes out at
once with the batch before it (a pause shorter than `IDLE_S`, e.g. the OS running another
process, does not end the burst).
Samples, their order, QoS and reliability are unchanged: only how many share a datagram
(RTPS allows several DATA submessages in one). A publisher slower than 1/GAP_S messages
per second (ping-pong, timers, real rclpy's own rate) sends every sample at once, as
rmw_cyclonedds_cpp does (it never batches).
"""
import ctypes
import time

from cyclonedds.qos import BasePolicy, _CQos

GAP_S = 50e-6        # writes closer together than this are a burst
STREAK = 8           # ... once this many came in a row
IDLE_S = 1e-3        # a pause this long ends a burst
MAX_PENDING = 256    # a batch is sent after this many samples at most
LARGE = 8192         # bytes: a sample this large is sent at once (fragments, heartbeat)

_lib = None


def _ddsc():
    global _lib
    if _lib is None:
        from cyclonedds.__library__ import library_path
        lib = ctypes.CDLL(str(library_path))     # the library cyclonedds already loaded
        lib.dds_qset_writer_batching.argtypes = [ctypes.c_void_p, ctypes.c_bool]
        lib.dds_qset_writer_batching.restype = None
        lib.dds_write_flush.argtypes = [ctypes.c_int32]
        lib.dds_write_flush.restype = ctypes.c_int32
        _lib = lib
    return _lib


class WriterBatching(BasePolicy):
    """The WRITER_BATCHING policy (cyclonedds' Python Qos has no class for it)."""
    __scope__ = "WriterBatching"

    def __repr__(self):
        return "Policy.WriterBatching"


def _set_writer_batching(cqos, policy):
    _ddsc().dds_qset_writer_batching(cqos, True)


# _CQos.qos_to_cqos applies a policy through _CQos._set_p_<scope>
_CQos._set_p_writerbatching = staticmethod(_set_writer_batching)
POLICY = WriterBatching()


def flush(writer_ref):
    return _ddsc().dds_write_flush(writer_ref)


class Batch:
    """When one batching writer's queued samples go out."""

    def __init__(self, writer_ref, wake, depth=MAX_PENDING):
        self.ref = writer_ref
        self.limit = max(1, min(depth, MAX_PENDING))
        self.wake = wake              # asks the bridge thread to call send()
        self.last = 0.0
        self.streak = 0
        self.pending = 0

    def wrote(self, size):
        """After each write of `size` bytes."""
        now = time.perf_counter()
        gap, self.last = now - self.last, now
        if gap >= IDLE_S:
            self.streak = 0
        elif gap < GAP_S:
            self.streak += 1
        if (gap >= GAP_S or self.streak < STREAK or size >= LARGE
                or self.pending + 1 >= self.limit):
            self.pending = 0
            flush(self.ref)
        else:
            self.pending += 1
            if self.pending == 1:
                self.wake()

    def send(self):
        """What is left of a burst (the bridge thread)."""
        if self.pending:
            self.pending = 0
            flush(self.ref)
