"""The tf2 core (what `tf2_py` wraps in ROS 2 Humble): frames, time caches, lookups.

Frames are numbered as tf2 numbers them (0 is "NO_PARENT"); each child frame
has a cache of (stamp, parent, translation, rotation) entries. A lookup walks
from the source frame and from the target frame up to their common parent,
interpolating every link at the requested time (translation linearly, rotation
by slerp), and raises tf2's exceptions with tf2's texts when it cannot.

Times are integer nanoseconds; quaternions are (x, y, z, w). The math is plain
Python floats: for 3- and 4-vectors that is faster than numpy.
"""
import bisect
import math
import sys
import threading

from labkit.interfaces import copy_message, get_type

__all__ = ["BufferCore", "TransformException", "ConnectivityException", "LookupException",
           "ExtrapolationException", "InvalidArgumentException", "TimeoutException",
           "display_time"]

DEFAULT_CACHE_TIME_NS = 10 * 10**9            # tf2::BUFFER_CORE_DEFAULT_CACHE_TIME
MAX_GRAPH_DEPTH = 1000
QUATERNION_NORMALIZATION_TOLERANCE = 10e-3


# ---------------------------------------------------------------- exceptions
class TransformException(Exception):
    """Base of tf2's errors (Python name `tf2.TransformException`)."""


class ConnectivityException(TransformException):
    pass


class LookupException(TransformException):
    pass


class ExtrapolationException(TransformException):
    pass


class InvalidArgumentException(TransformException):
    pass


class TimeoutException(TransformException):
    pass


for _cls in (TransformException, ConnectivityException, LookupException,
             ExtrapolationException, InvalidArgumentException, TimeoutException):
    _cls.__module__ = "tf2"       # tracebacks read "tf2.LookupException: ..." as in ROS


def display_time(ns):
    """tf2's displayTimePoint: seconds with six decimals."""
    return "%.6f" % (ns / 1e9)


def time_ns(obj):
    """A time argument as nanoseconds: builtin_interfaces Time (sec, nanosec) or rclpy Time."""
    if hasattr(obj, "sec") and hasattr(obj, "nanosec"):
        return int(obj.sec) * 10**9 + int(obj.nanosec)
    if hasattr(obj, "nanoseconds"):
        return int(obj.nanoseconds)
    raise TypeError("time must have sec and nanosec, or nanoseconds.")


def duration_ns(obj):
    if hasattr(obj, "sec") and hasattr(obj, "nanosec"):
        return int(obj.sec) * 10**9 + int(obj.nanosec)
    if hasattr(obj, "nanoseconds"):
        return int(obj.nanoseconds)
    raise TypeError("duration must have sec and nanosec, or nanoseconds.")


# ---------------------------------------------------------------- quaternion math
def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by + ay * bw + az * bx - ax * bz,
            aw * bz + az * bw + ax * by - ay * bx,
            aw * bw - ax * bx - ay * by - az * bz)


def qrot(q, v):
    """Rotate vector v by unit quaternion q."""
    x, y, z, w = q
    vx, vy, vz = v
    # t = 2 * cross(q.xyz, v); v' = v + w t + cross(q.xyz, t)
    tx = 2.0 * (y * vz - z * vy)
    ty = 2.0 * (z * vx - x * vz)
    tz = 2.0 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty),
            vy + w * ty + (z * tx - x * tz),
            vz + w * tz + (x * ty - y * tx))


def qinv(q):
    x, y, z, w = q
    n = x * x + y * y + z * z + w * w
    return (-x / n, -y / n, -z / n, w / n)


def slerp(a, b, t):
    """Shortest-path spherical interpolation from a (t=0) to b (t=1), as tf2's Quaternion::slerp."""
    dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
    if dot < 0.0:
        b = (-b[0], -b[1], -b[2], -b[3])
        dot = -dot
    if dot > 1.0:
        dot = 1.0
    theta = math.acos(dot)
    s = math.sin(theta)
    if s < 1e-12:
        return a
    s0 = math.sin((1.0 - t) * theta) / s
    s1 = math.sin(t * theta) / s
    return (a[0] * s0 + b[0] * s1, a[1] * s0 + b[1] * s1,
            a[2] * s0 + b[2] * s1, a[3] * s0 + b[3] * s1)


def compose(t1, q1, t2, q2):
    """(t1, q1) * (t2, q2) as rigid transforms."""
    r = qrot(q1, t2)
    return (t1[0] + r[0], t1[1] + r[1], t1[2] + r[2]), qmul(q1, q2)


def invert(t, q):
    qi = qinv(q)
    r = qrot(qi, t)
    return (-r[0], -r[1], -r[2]), qi


# ---------------------------------------------------------------- caches
class _Entry:
    __slots__ = ("stamp", "parent", "t", "q")

    def __init__(self, stamp, parent, t, q):
        self.stamp = stamp
        self.parent = parent
        self.t = t
        self.q = q

    def same(self, other):
        return (self.stamp == other.stamp and self.parent == other.parent
                and self.t == other.t and self.q == other.q)


class TimeCache:
    """A frame's history, oldest first (tf2 keeps newest first; the answers are the same)."""
    is_static = False

    def __init__(self, max_storage_ns):
        self.max_storage_ns = max_storage_ns
        self.stamps = []
        self.entries = []

    def _closest(self, time, err):
        """(one, two) around `time` (two None when exact), or None with err[0] set."""
        entries = self.entries
        if not entries:
            return None
        if time == 0:
            return entries[-1], None
        if len(entries) == 1:
            if entries[0].stamp == time:
                return entries[0], None
            err[0] = ("Lookup would require extrapolation at time %s, but only time %s is in "
                      "the buffer" % (display_time(time), display_time(entries[0].stamp)))
            return None
        latest = entries[-1].stamp
        earliest = entries[0].stamp
        if time == latest:
            return entries[-1], None
        if time == earliest:
            return entries[0], None
        if time > latest:
            err[0] = ("Lookup would require extrapolation into the future.  Requested time %s "
                      "but the latest data is at time %s"
                      % (display_time(time), display_time(latest)))
            return None
        if time < earliest:
            err[0] = ("Lookup would require extrapolation into the past.  Requested time %s "
                      "but the earliest data is at time %s" % (display_time(time),
                                                               display_time(earliest)))
            return None
        i = bisect.bisect_right(self.stamps, time)      # stamps[i-1] <= time < stamps[i]
        older = entries[i - 1]
        if older.stamp == time:
            return older, None
        return older, entries[i]

    def get_data(self, time, err):
        found = self._closest(time, err)
        if found is None:
            return None
        one, two = found
        if two is None or one.parent != two.parent:
            return one
        ratio = (time - one.stamp) / (two.stamp - one.stamp)
        a, b = one.t, two.t
        t = (a[0] + (b[0] - a[0]) * ratio, a[1] + (b[1] - a[1]) * ratio,
             a[2] + (b[2] - a[2]) * ratio)
        return _Entry(one.stamp, one.parent, t, slerp(one.q, two.q, ratio))

    def get_parent(self, time, err):
        found = self._closest(time, err)
        return 0 if found is None else found[0].parent

    def insert(self, entry):
        latest = self.latest_stamp()
        self._prune(latest)
        if self.entries and entry.stamp < latest - self.max_storage_ns:
            return False
        i = bisect.bisect_right(self.stamps, entry.stamp)
        j = i
        while j > 0 and self.stamps[j - 1] == entry.stamp:
            if self.entries[j - 1].same(entry):
                return True
            j -= 1
        self.stamps.insert(i, entry.stamp)
        self.entries.insert(i, entry)
        return True

    def _prune(self, latest):
        cut = 0
        while cut < len(self.stamps) and self.stamps[cut] + self.max_storage_ns < latest:
            cut += 1
        if cut:
            del self.stamps[:cut]
            del self.entries[:cut]

    def latest_time_and_parent(self):
        if not self.entries:
            return 0, 0
        e = self.entries[-1]
        return e.stamp, e.parent

    def latest_stamp(self):
        return self.entries[-1].stamp if self.entries else 0

    def oldest_stamp(self):
        return self.entries[0].stamp if self.entries else 0

    def __len__(self):
        return len(self.entries)


class StaticCache:
    """A static frame: one entry, valid at every time."""
    is_static = True

    def __init__(self):
        self.entry = None

    def get_data(self, time, err):
        e = self.entry
        if e is None:
            return None
        return _Entry(time, e.parent, e.t, e.q)

    def get_parent(self, time, err):
        return 0 if self.entry is None else self.entry.parent

    def insert(self, entry):
        self.entry = entry
        return True

    def latest_time_and_parent(self):
        return 0, (0 if self.entry is None else self.entry.parent)

    def latest_stamp(self):
        return 0

    def oldest_stamp(self):
        return 0

    def __len__(self):
        return 1


# ---------------------------------------------------------------- the buffer core
def _strip_slash(name):
    return name[1:] if name.startswith("/") else name


def _console(level, text, line):
    # console_bridge's default handler: level tag, text, then where it came from
    sys.stderr.write("%s%s\n         at line %d in ./src/buffer_core.cpp\n"
                     % ("Error:   " if level == "error" else "Warning: ", text, line))


class BufferCore:
    """`tf2_py.BufferCore`: keeps the frames; the ROS-facing Buffer builds on it."""

    def __init__(self, cache_time=None):
        self._cache_ns = DEFAULT_CACHE_TIME_NS if cache_time is None else duration_ns(cache_time)
        self._frame_lock = threading.RLock()
        self.clear_all()

    def clear_all(self):
        with self._frame_lock:
            self._ids = {"NO_PARENT": 0}
            self._names = ["NO_PARENT"]
            self._caches = [None]
            self._authority = {}

    # -- inserting
    def set_transform(self, transform, authority):
        return self._set(transform, authority, False)

    def set_transform_static(self, transform, authority):
        return self._set(transform, authority, True)

    def _set(self, msg, authority, is_static):
        tr = msg.transform.translation
        ro = msg.transform.rotation
        t = (float(tr.x), float(tr.y), float(tr.z))
        q = (float(ro.x), float(ro.y), float(ro.z), float(ro.w))
        stamp = int(msg.header.stamp.sec) * 10**9 + int(msg.header.stamp.nanosec)
        # tf2 strips one leading slash from incoming names (lookups refuse them)
        frame_id = _strip_slash(msg.header.frame_id)
        child = _strip_slash(msg.child_frame_id)
        error = False
        if child == frame_id:
            _console("error", 'TF_SELF_TRANSFORM: Ignoring transform from authority "%s" with '
                     'frame_id and  child_frame_id "%s" because they are the same'
                     % (authority, child), 212)
            error = True
        if not child:
            _console("error", 'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "%s" '
                     'because child_frame_id not set ' % authority, 220)
            error = True
        if not frame_id:
            _console("error", 'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "%s"  from '
                     'authority "%s" because frame_id not set' % (child, authority), 227)
            error = True
        if any(math.isnan(v) for v in t + q):
            _console("error", 'TF_NAN_INPUT: Ignoring transform for child_frame_id "%s" from '
                     'authority "%s" because of a nan value in the transform (%f %f %f) '
                     '(%f %f %f %f)' % ((child, authority) + t + q), 238)
            error = True
        elif abs(sum(v * v for v in q) - 1.0) >= QUATERNION_NORMALIZATION_TOLERANCE:
            _console("error", 'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id '
                     '"%s" from authority "%s" because of an invalid quaternion in the transform '
                     '(%f %f %f %f)' % ((child, authority) + q), 257)
            error = True
        if error:
            return False
        with self._frame_lock:
            cid = self._number(child, insert=True)
            cache = self._caches[cid]
            if cache is None or cache.is_static != is_static:
                cache = StaticCache() if is_static else TimeCache(self._cache_ns)
                self._caches[cid] = cache
            if not cache.insert(_Entry(stamp, self._number(frame_id, insert=True), t, q)):
                _console("warn", "TF_OLD_DATA ignoring data from the past for frame %s at time %s "
                         "according to authority %s\nPossible reasons are listed at "
                         "http://wiki.ros.org/tf/Errors%%20explained"
                         % (child, display_time(stamp), authority), 295)
                return False
            self._authority[cid] = authority
        return True

    def _number(self, name, insert=False):
        fid = self._ids.get(name, 0)
        if fid == 0 and insert:
            fid = len(self._names)
            self._ids[name] = fid
            self._names.append(name)
            self._caches.append(None)
        return fid

    def _validate(self, function_arg, frame):
        """validateFrameId, the throwing form used by lookups."""
        if not frame:
            raise InvalidArgumentException('Invalid argument "%s" passed to %s - in tf2 frame_ids '
                                           'cannot be empty' % (frame, function_arg))
        if frame[0] == "/":
            raise InvalidArgumentException('Invalid argument "%s" passed to %s - in tf2 frame_ids '
                                           "cannot start with a '/'" % (frame, function_arg))
        fid = self._ids.get(frame, 0)
        if fid == 0:
            raise LookupException('"%s" passed to %s does not exist. ' % (frame, function_arg))
        return fid

    def _check(self, function_arg, frame, err):
        """validateFrameId, the error-message form used by canTransform."""
        if not frame:
            why = "in tf2 frame_ids cannot be empty"
        elif frame[0] == "/":
            why = "in tf2 frame_ids cannot start with a '/'"
        else:
            fid = self._ids.get(frame, 0)
            if fid:
                return fid
            why = "frame does not exist"
        err[0] = 'Invalid frame ID "%s" passed to %s - %s' % (frame, function_arg, why)
        return 0

    # -- walking the tree
    def _loop_error(self):
        return ("The tf tree is invalid because it contains a loop.\n"
                + self.all_frames_as_string() + "\n")

    def _connectivity_error(self, source_id, target_id):
        return ("Could not find a connection between '%s' and '%s' because they are not part of "
                "the same tree.Tf has two or more unconnected trees."
                % (self._names[target_id], self._names[source_id]))

    def _latest_common_time(self, target_id, source_id):
        """(error class or None, time ns, message)."""
        caches = self._caches
        if source_id == 0 or target_id == 0:
            return LookupException, 0, ""
        if source_id == target_id:
            cache = caches[source_id]
            return None, (cache.latest_stamp() if cache else 0), ""
        chain = []                 # (stamp, parent) walking up from the source
        frame = source_id
        common = None
        depth = 0
        while frame:
            cache = caches[frame]
            if cache is None:
                break
            stamp, parent = cache.latest_time_and_parent()
            if parent == 0:
                break
            if stamp and (common is None or stamp < common):
                common = stamp
            chain.append((stamp, parent))
            frame = parent
            if frame == target_id:
                return None, common or 0, ""
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LookupException, 0, self._loop_error()
        frame = target_id
        depth = 0
        common = None
        common_parent = 0
        parents = {p for _, p in chain}
        while True:
            cache = caches[frame]
            if cache is None:
                break
            stamp, parent = cache.latest_time_and_parent()
            if parent == 0:
                break
            if stamp and (common is None or stamp < common):
                common = stamp
            if parent in parents:
                common_parent = parent
                break
            frame = parent
            if frame == source_id:
                return None, common or 0, ""
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LookupException, 0, self._loop_error()
        if common_parent == 0:
            return ConnectivityException, 0, self._connectivity_error(source_id, target_id)
        for stamp, parent in chain:
            if stamp and (common is None or stamp < common):
                common = stamp
            if parent == common_parent:
                break
        return None, common or 0, ""

    def _walk(self, time, target_id, source_id, accumulate):
        """walkToTopParent. Returns (error class or None, message, result).

        With accumulate, result is (translation, rotation, time) of source in target;
        otherwise only reachability is checked (canTransform)."""
        if source_id == target_id:
            return None, "", ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), time)
        if time == 0:
            exc, time, msg = self._latest_common_time(target_id, source_id)
            if exc is not None:
                return exc, msg, None
        caches = self._caches
        err = [""]
        src_t, src_q = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)
        frame = source_id
        top = frame
        depth = 0
        maybe_extrapolation = False
        extrapolation_error = [""]
        while frame:
            cache = caches[frame]
            if cache is None:
                top = frame
                break
            if accumulate:
                st = cache.get_data(time, extrapolation_error)
                parent = st.parent if st is not None else 0
            else:
                parent = cache.get_parent(time, extrapolation_error)
            if parent == 0:
                top = frame
                maybe_extrapolation = True
                break
            if frame == target_id:
                return None, "", (src_t, src_q, time)
            if accumulate:
                r = qrot(st.q, src_t)
                src_t = (r[0] + st.t[0], r[1] + st.t[1], r[2] + st.t[2])
                src_q = qmul(st.q, src_q)
            top = frame
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LookupException, self._loop_error(), None
        frame = target_id
        depth = 0
        tgt_t, tgt_q = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)
        while frame != top:
            cache = caches[frame]
            if cache is None:
                break
            if accumulate:
                st = cache.get_data(time, err)
                parent = st.parent if st is not None else 0
            else:
                parent = cache.get_parent(time, err)
            if parent == 0:
                return ExtrapolationException, (
                    "%s, when looking up transform from frame [%s] to frame [%s]"
                    % (err[0], self._names[source_id], self._names[target_id])), None
            if frame == source_id:
                t, q = invert(tgt_t, tgt_q)
                return None, "", (t, q, time)
            if accumulate:
                r = qrot(st.q, tgt_t)
                tgt_t = (r[0] + st.t[0], r[1] + st.t[1], r[2] + st.t[2])
                tgt_q = qmul(st.q, tgt_q)
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LookupException, self._loop_error(), None
        if frame != top:
            if maybe_extrapolation:
                return ExtrapolationException, (
                    "%s, when looking up transform from frame [%s] to frame [%s]"
                    % (extrapolation_error[0], self._names[source_id],
                       self._names[target_id])), None
            return ConnectivityException, self._connectivity_error(source_id, target_id), None
        if not accumulate:
            return None, "", None
        inv_t, inv_q = invert(tgt_t, tgt_q)
        t, q = compose(inv_t, inv_q, src_t, src_q)
        return None, "", (t, q, time)

    # -- lookups
    def _lookup(self, target_frame, source_frame, time):
        """(translation, rotation, time ns) of source_frame expressed in target_frame."""
        with self._frame_lock:
            if target_frame == source_frame:
                if time == 0:
                    fid = self._ids.get(target_frame, 0)
                    cache = self._caches[fid] if fid else None
                    time = cache.latest_stamp() if cache else 0
                return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), time
            target_id = self._validate("lookupTransform argument target_frame", target_frame)
            source_id = self._validate("lookupTransform argument source_frame", source_frame)
            exc, msg, result = self._walk(time, target_id, source_id, True)
            if exc is not None:
                raise exc(msg)
            return result

    def lookup_transform_core(self, target_frame, source_frame, time):
        t, q, stamp = self._lookup(target_frame, source_frame, time_ns(time))
        return _transform_msg(target_frame, source_frame, t, q, stamp)

    def lookup_transform_full_core(self, target_frame, target_time, source_frame, source_time,
                                   fixed_frame):
        target_ns, source_ns = time_ns(target_time), time_ns(source_time)
        with self._frame_lock:
            self._validate("lookupTransform argument target_frame", target_frame)
            self._validate("lookupTransform argument source_frame", source_frame)
            self._validate("lookupTransform argument fixed_frame", fixed_frame)
            t1, q1, _ = self._lookup(fixed_frame, source_frame, source_ns)
            t2, q2, stamp = self._lookup(target_frame, fixed_frame, target_ns)
        t, q = compose(t2, q2, t1, q1)
        return _transform_msg(target_frame, source_frame, t, q, stamp)

    def can_transform_core(self, target_frame, source_frame, time):
        """(bool, error message) like tf2_py."""
        ns = time_ns(time)
        err = [""]
        with self._frame_lock:
            ok = self._can(target_frame, source_frame, ns, err)
        return ok, err[0]

    def _can(self, target_frame, source_frame, ns, err):
        if target_frame == source_frame:
            return True
        target_id = self._check("canTransform argument target_frame", target_frame, err)
        if not target_id:
            return False
        source_id = self._check("canTransform argument source_frame", source_frame, err)
        if not source_id:
            return False
        return self._can_ids(target_id, source_id, ns, err)

    def _can_ids(self, target_id, source_id, ns, err):
        if target_id == source_id:
            return True
        exc, msg, _ = self._walk(ns, target_id, source_id, False)
        if exc is not None:
            err[0] = msg
            return False
        return True

    def can_transform_full_core(self, target_frame, target_time, source_frame, source_time,
                                fixed_frame):
        target_ns, source_ns = time_ns(target_time), time_ns(source_time)
        err = [""]
        with self._frame_lock:
            ids = []
            for arg, frame in (("target_frame", target_frame), ("source_frame", source_frame),
                               ("fixed_frame", fixed_frame)):
                fid = self._check("canTransform argument " + arg, frame, err)
                if not fid:
                    return False, err[0]
                ids.append(fid)
            target_id, source_id, fixed_id = ids
            ok = (self._can_ids(target_id, fixed_id, target_ns, err)
                  and self._can_ids(fixed_id, source_id, source_ns, err))
        return ok, err[0]

    # -- introspection
    def _parent_now(self, fid):
        cache = self._caches[fid]
        st = cache.get_data(0, [""]) if cache is not None else None
        return st.parent if st is not None else 0

    def all_frames_as_string(self):
        with self._frame_lock:
            lines = []
            for fid in range(1, len(self._names)):
                if self._caches[fid] is None:
                    continue
                lines.append("Frame %s exists with parent %s.\n"
                             % (self._names[fid], self._names[self._parent_now(fid)]))
            return "".join(lines)

    def frames(self):
        """{child: (parent, cache)} for every frame that has data (for view_frames and snapshot)."""
        with self._frame_lock:
            out = {}
            for fid in range(1, len(self._names)):
                cache = self._caches[fid]
                if cache is None or (not cache.is_static and not len(cache)):
                    continue
                out[self._names[fid]] = (self._names[self._parent_now(fid)], cache,
                                         self._authority.get(fid, "no recorded authority"))
            return out

    def all_frames_as_yaml(self, current_time=None):
        now = 0 if current_time is None else time_ns(current_time)
        frames = self.frames()
        if not frames and len(self._names) == 1:
            return "[]"
        out = []
        for name, (parent, cache, authority) in frames.items():
            latest, oldest = cache.latest_stamp(), cache.oldest_stamp()
            span = latest - oldest
            rate = len(cache) * 1e9 / (span if span > 100_000 else 100_000)
            out.append("%s: \n  parent: '%s'\n  broadcaster: '%s'\n  rate: %.3f\n"
                       "  most_recent_transform: %s\n  oldest_transform: %s\n"
                       % (name, parent, authority, rate, display_time(latest),
                          display_time(oldest)))
            if now:
                out.append("  transform_delay: %.3f\n" % ((now - latest) / 1e9))
            out.append("  buffer_length: %.3f\n" % (span / 1e9))
        return "".join(out)

    def _getFrameStrings(self):
        with self._frame_lock:
            return [self._names[fid] for fid in range(1, len(self._names))
                    if self._caches[fid] is not None]

    def _frameExists(self, frame_id):
        return self._ids.get(frame_id, 0) != 0

    def get_latest_common_time(self, target_frame, source_frame):
        from labkit.rclpy.time import Time
        with self._frame_lock:
            target_id = self._validate("get_latest_common_time", target_frame)
            source_id = self._validate("get_latest_common_time", source_frame)
            exc, ns, msg = self._latest_common_time(target_id, source_id)
        if exc is not None:
            raise TransformException(msg)
        return Time(nanoseconds=ns)

    def clear(self):
        """Drop every stored transform (frames keep their numbers, as in tf2)."""
        with self._frame_lock:
            for fid in range(1, len(self._caches)):
                cache = self._caches[fid]
                if cache is not None and not cache.is_static:
                    self._caches[fid] = TimeCache(self._cache_ns)


_template = None


def _transform_msg(target_frame, source_frame, t, q, stamp):
    global _template
    if _template is None:
        _template = get_type("geometry_msgs/msg/TransformStamped")()
    msg = copy_message(_template)       # much cheaper than building the nested message anew
    msg.header.stamp.sec = stamp // 10**9
    msg.header.stamp.nanosec = stamp % 10**9
    msg.header.frame_id = target_frame
    msg.child_frame_id = source_frame
    tr = msg.transform.translation
    tr.x, tr.y, tr.z = t
    ro = msg.transform.rotation
    ro.x, ro.y, ro.z, ro.w = q
    return msg
