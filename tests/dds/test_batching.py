"""A fast labkit publisher packs its small samples several to a datagram (writer
batching); slow ones, and large samples, go out one by one at once."""
import pytest

from labkit.dds import batching
from tests.dds.test_real_peers import (ROSREF, domain, finish, labkit,  # noqa: F401
                                       needs_rosref, real)


class _Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_only_a_burst_is_batched_and_the_bridge_sends_what_is_left(monkeypatch):
    clock, flushed, woken = _Clock(), [], []
    monkeypatch.setattr(batching.time, "perf_counter", clock)
    monkeypatch.setattr(batching, "flush", flushed.append)
    batch = batching.Batch(7, lambda: woken.append(1))
    for _ in range(20):                    # a timer, a ping-pong: each sent at once
        clock.now += 2e-4
        batch.wrote(40)
    assert flushed == [7] * 20 and not woken
    flushed.clear()
    clock.now += batching.IDLE_S
    for _ in range(batching.STREAK + 1 + batching.MAX_PENDING + 10):   # a tight loop
        clock.now += 4e-6
        batch.wrote(40)
    # at once until the streak, then one datagram batch per MAX_PENDING samples
    assert len(flushed) == batching.STREAK + 1
    assert batch.pending == 11 and woken == [1, 1]
    batch.send()                          # the bridge thread: the rest of the burst
    assert len(flushed) == batching.STREAK + 2 and batch.pending == 0
    batch.send()
    assert len(flushed) == batching.STREAK + 2
    clock.now += 4e-6
    batch.wrote(batching.LARGE)           # in a burst, but fragments go out at once
    assert len(flushed) == batching.STREAK + 3 and batch.pending == 0
    clock.now += 2e-4                     # the OS ran another process for a while:
    batch.wrote(40)                       # this one goes out at once with the batch,
    clock.now += 4e-6
    batch.wrote(40)                       # but the burst goes on
    assert len(flushed) == batching.STREAK + 4 and batch.pending == 1
    clock.now += batching.IDLE_S          # a pause ends it
    batch.wrote(40)
    assert len(flushed) == batching.STREAK + 5 and batch.pending == 0
    shallow, flushed[:] = batching.Batch(8, lambda: None, depth=10), []
    for _ in range(batching.STREAK + 1 + 25):  # keep last 10: batches of 10 samples
        clock.now += 4e-6
        shallow.wrote(40)
    assert len(flushed) == batching.STREAK + 2 and shallow.pending == 6


def test_the_writer_qos_asks_cyclone_for_batching():
    from cyclonedds.qos import Qos, Policy, _CQos
    import ctypes
    cqos = _CQos.qos_to_cqos(Qos(Policy.History.KeepLast(10), batching.POLICY))
    lib = batching._ddsc()
    lib.dds_qget_writer_batching.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_bool)]
    lib.dds_qget_writer_batching.restype = ctypes.c_bool
    on = ctypes.c_bool(False)
    assert lib.dds_qget_writer_batching(cqos, ctypes.byref(on)) and on.value
    _CQos.cqos_destroy(cqos)


BURST = 3001

SINK = """
from std_msgs.msg import String
from rclpy.qos import QoSProfile
rclpy.init(args=[])
node = rclpy.create_node('{name}')
got = []
node.create_subscription(String, 'burst', lambda m: got.append(int(m.data)),
                         QoSProfile(depth={burst}))
print('ready', flush=True)
spin_until(node, lambda: len(got) >= {burst}, 40)
print('received', len(got), 'in order', got == list(range(len(got))))
"""


@needs_rosref
def test_a_burst_reaches_real_and_labkit_subscribers_whole_in_few_datagrams(tmp_path, domain):
    """3001 Strings published in a tight loop reach a real rclpy (Fast DDS) and a labkit
    subscriber whole and in order, in far fewer flushes (datagram batches) than samples;
    what is left of the burst is sent by the bridge thread, not by a later write."""
    sinks = [real(tmp_path, "real_sink", SINK.format(name="real_sink", burst=BURST), domain),
             labkit(tmp_path, "lk_sink", SINK.format(name="lk_sink", burst=BURST), domain)]
    for sink in sinks:
        assert sink.stdout.readline().strip() == "ready"
    source = labkit(tmp_path, "lk_source", f"""
        from std_msgs.msg import String
        from rclpy.qos import QoSProfile
        from labkit.dds import batching
        flushes = []
        sent = batching.flush
        batching.flush = lambda ref: flushes.append(ref) or sent(ref)
        rclpy.init()
        node = rclpy.create_node('lk_source')
        pub = node.create_publisher(String, 'burst', QoSProfile(depth={BURST}))
        spin_until(node, lambda: pub.get_subscription_count() >= 2, 20)
        spin_until(node, lambda: False, 1.0)       # the DDS readers match after discovery
        before = len(flushes)
        for i in range({BURST}):
            pub.publish(String(data=str(i)))
        during = len(flushes) - before
        left = [m.batch.pending for m in __import__('labkit').dds.current()._mirrors.values()
                if m.batch is not None]
        time.sleep(1.0)                            # the GIL is free: the bridge thread runs
        after = [m.batch.pending for m in __import__('labkit').dds.current()._mirrors.values()
                 if m.batch is not None]
        print('flushes', during, 'left', sum(left), 'after', sum(after), flush=True)
        spin_until(node, lambda: False, 3.0)
    """, domain)
    out, err = finish(source, 60)
    results = [finish(sink, 60) for sink in sinks]
    words = out.split()
    assert words[0] == "flushes", out + err
    flushes, left, after = int(words[1]), int(words[3]), int(words[5])
    assert flushes < BURST // 3, out
    assert after == 0, out
    for sink_out, sink_err in results:
        assert f"received {BURST} in order True" in sink_out, sink_out + sink_err
