"""tf2 lookup speed (printed, not asserted).

    .venv/bin/python benchmarks/bench_tf2.py

`Buffer.lookup_transform` through a 10-frame chain (each link with 100 stamps, the
lookup interpolating between two of them, and a latest-time lookup) against the same
chain as ten precomputed 4x4 matrices multiplied in numpy. Goal: within 5x of numpy.
"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from labkit.interfaces import get_type  # noqa: E402
from labkit.rclpy.time import Time  # noqa: E402
from labkit.tf2.ros import Buffer  # noqa: E402
from labkit.tf2.transformations import quaternion_from_euler, quaternion_matrix  # noqa: E402

TransformStamped = get_type("geometry_msgs/msg/TransformStamped")
EPOCH = 1704067200
LINKS = 10


def build():
    buffer = Buffer()
    mats = []
    for i in range(LINKS):
        q = quaternion_from_euler(0.01 * i, 0.02 * i, 0.1 * i)
        for k in range(100):
            t = TransformStamped()
            t.header.frame_id = "f%d" % i
            t.child_frame_id = "f%d" % (i + 1)
            t.header.stamp.sec = EPOCH + k // 10
            t.header.stamp.nanosec = (k % 10) * 100_000_000
            t.transform.translation.x = 0.1 * i + 0.001 * k
            t.transform.translation.y = 1.0
            r = t.transform.rotation
            r.x, r.y, r.z, r.w = (float(v) for v in q)
            buffer.set_transform(t, "bench")
        m = quaternion_matrix(q)
        m[:3, 3] = (0.1 * i, 1.0, 0.0)
        mats.append(m)
    return buffer, mats


def per_call(fn, n):
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(n):
            fn()
        best = min(best, (time.perf_counter() - start) / n)
    return best


def main():
    buffer, mats = build()
    mid = Time(seconds=EPOCH + 5, nanoseconds=50_000_000)   # between two stamps

    def numpy_chain():
        r = mats[0]
        for m in mats[1:]:
            r = r @ m
        return r

    def lookup_interp():
        return buffer.lookup_transform("f0", "f%d" % LINKS, mid)

    def lookup_latest():
        return buffer.lookup_transform("f0", "f%d" % LINKS, Time())

    n = 5000
    t_np = per_call(numpy_chain, n)
    t_interp = per_call(lookup_interp, n)
    t_latest = per_call(lookup_latest, n)
    print("10-frame chain, per call (best of 5 x %d):" % n)
    print("  numpy 4x4 matrix chain          %7.1f us" % (t_np * 1e6))
    print("  lookup_transform (interpolated) %7.1f us  (%.1fx numpy)" % (t_interp * 1e6,
                                                                         t_interp / t_np))
    print("  lookup_transform (latest)       %7.1f us  (%.1fx numpy)" % (t_latest * 1e6,
                                                                         t_latest / t_np))
    print("  goal: within 5x numpy")


if __name__ == "__main__":
    main()
