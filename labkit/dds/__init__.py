"""labkit on a real ROS 2 network (layer 2.5: between the graph and rclpy).

    connect(domain_id=None, localhost_only=None)   join DDS (one participant per process)
    disconnect()                                    leave; the in-process graph stays
    current()                                       the Bridge of this process, or None

A connected process mirrors its nodes, topics and services on Cyclone DDS exactly as
a ROS 2 node does (see bridge.py), so real ROS 2 nodes (Humble or later, Fast DDS or
Cyclone) and other labkit processes see each other. Not connected, nothing changes:
the in-process path does not know this room exists.

Time: DDS peers live in wall-clock time, so a connection needs live time. In virtual
time (CI, notebook execution) `connect()` refuses with one line, and `labkit exec` /
`labkit ros2` stay in-process; a notebook that talks to real ROS 2 calls
`labkit.set_time_mode('live')` first. LABKIT_DDS=off keeps a process in-process
(the test suite sets it so parallel runs never see each other).

connect(domain_id=N) also makes N the process's ROS_DOMAIN_ID (nodes and ros2 verbs
started afterwards are on it); disconnect() and labkit.reset() put it back. A domain DDS
cannot map to ports (233 and above) is refused with Fast DDS's one line (UnmappableDomain;
a notebook shows that line and no traceback).

`labkit exec` joins as Humble's rmw does: with the program's first node (rclpy.init() alone
makes no participant), in a background thread while the program goes on
(join_at_first_node); connect(), disconnect(), settle_discovery() and wait_until() wait for
a join under way, and a program that ends meanwhile makes no participant.

What it does not do (yet): a real Fast DDS *client* calling a labkit service gets no
reply (Fast DDS matches replies by the RTPS related-sample-identity, which Cyclone's
API cannot set): labkit prints one line with the remedy,
RMW_IMPLEMENTATION=rmw_cyclonedds_cpp on the real side. On loopback labkit sends a
large sample in bursts a default Linux socket buffer holds (config.py): a 640x480 image
reaches a Fast DDS reader whole, in about 24 ms (five round trips to it); the first
fragmented sample of a Fast DDS writer just matched can be dropped by Cyclone's reader
(see benchmarks/README.md). Cyclone binds its two unicast receive sockets to the wildcard
address (in the 11.0.1 library receive sockets bind to any, and no configuration
element changes it): in localhost mode labkit binds them to the loopback device, so
they take only datagrams sent from this machine (sockets.py). No SROS2 security, no
type_description service, no content-filtered topics.

Bad input on DDS: CYCLONEDDS_URI (files or XML, as rmw_cyclonedds_cpp reads it) is
applied after labkit's own configuration; a message larger than its MaxSampleSize is
not sent (one line, once per topic; Cyclone also traces each dropped sample), local
subscribers still get it. No valid ROS name is mangled: rcl's 247-character limit is
exactly what keeps 'rq/<name>Request' within the 256 characters of a DDS topic name.
A server that goes away mid-call ends `ros2 service call` with one line (the real
verb waits forever); a server killed without leaving is noticed when its DDS lease
runs out (Fast DDS: 20 s, Cyclone: 10 s).
"""
import os
import sys
import threading

from labkit.dds.config import ConfigError

__all__ = ["connect", "disconnect", "current", "is_connected", "ConfigError", "ConnectError",
           "UnmappableDomain", "join_at_first_node",
           "auto_enabled", "settle_discovery", "wait_until"]

_bridge = None
_lock = threading.Lock()
_saved_domain = []       # ROS_DOMAIN_ID before connect() set it


class ConnectError(RuntimeError):
    """Joining DDS failed; the message is one line for the user."""


# Fast DDS (Humble's default rmw) maps domain d to UDP ports 7400 + 250 * d + offsets:
# from 233 on they pass 65535 and the participant is refused with this line
# (PortParameters.h; labkit.rclpy.node says the same for a node on such a domain)
PORT_TOO_HIGH = ("Calculated port number is too high. Probably the domainId is over 232 "
                 "or portBase is too high.")
MAX_MAPPABLE_DOMAIN_ID = 232


class UnmappableDomain(ConfigError):
    """A domain id DDS cannot map to ports: ROS's one line, shown without a traceback
    in a notebook (IPython shows what `_render_traceback_` returns instead)."""

    def __init__(self):
        super().__init__(PORT_TOO_HIGH)

    def _render_traceback_(self):
        return [PORT_TOO_HIGH]


def _checked_settings(domain_id, localhost_only):
    """(domain, localhost) for a join, or the one-line refusal connect() gives: virtual
    time, a domain DDS cannot map to ports, a bad value."""
    from labkit.dds import config
    from labkit.graph import world
    if world.mode() != "live":
        raise ConnectError("labkit.connect(): DDS peers run in wall-clock time; virtual time "
                           "stays in-process (call labkit.set_time_mode('live') first)")
    _refuse_unmappable(domain_id)
    return config.domain_id(domain_id), config.localhost_only(localhost_only)


def _refuse_unmappable(domain_id):
    """Before labkit's own range check: an integer domain past 232 (given, or from
    ROS_DOMAIN_ID) gets Fast DDS's line, as Humble's rmw refuses its participant."""
    if domain_id is None:
        text = os.environ.get("ROS_DOMAIN_ID", "").strip()
        domain_id = int(text) if text.isdigit() else None
    if (isinstance(domain_id, int) and not isinstance(domain_id, bool)
            and domain_id > MAX_MAPPABLE_DOMAIN_ID):
        raise UnmappableDomain()


def current():
    """The Bridge of this process (None when not connected, or still joining)."""
    return _bridge


# ------------------------------------------------------------ joining with the first node
# Humble's rmw creates a process's participant with its first node (rclpy.init() alone
# joins nothing). `labkit exec` does the same, and in the background: the program goes on
# (its node, publishers, first messages in-process) while Cyclone DDS is imported and the
# participant made; the bridge then mirrors every endpoint made meanwhile (a transient-local
# publisher's history included), as it mirrors any endpoint a moment after it appears.
_defer_lock = threading.Lock()   # never held while taking GRAPH.lock or _lock
_deferred = None                 # the graph listener waiting for the first node
_pending = None                  # the thread joining now
_leaving = False                 # disconnect() is waiting for it: it must not join


def join_at_first_node(domain_id=None, localhost_only=None):
    """Join DDS when this process makes its first node, in a background thread.

    The settings are checked now (ConfigError / UnmappableDomain, one line, as connect());
    connect(), disconnect(), settle_discovery() and wait_until() wait for a join under way."""
    global _deferred, _leaving
    from labkit.graph.registry import GRAPH
    domain, reach = _checked_settings(domain_id, localhost_only)

    def first_node():
        global _deferred, _pending
        if not GRAPH.nodes:
            return
        with _defer_lock:
            if _deferred is not first_node:
                return
            _deferred = None
            thread = threading.Thread(target=_join_now, args=(domain, reach),
                                      name="labkit-dds-join", daemon=True)
            try:      # it belongs to the program (the main process), whoever made the node
                from labkit import process
                thread._labkit_process = process.MAIN
            except (ImportError, AttributeError):
                pass
            _pending = thread
        _unlisten(first_node)
        thread.start()

    _cancel_deferred()
    _await_pending()
    with _defer_lock:
        _deferred = first_node
        _leaving = False
    GRAPH.listeners.append(first_node)
    first_node()                      # a node made already


def _unlisten(listener):
    from labkit.graph.registry import GRAPH
    try:
        GRAPH.listeners.remove(listener)
    except ValueError:
        pass


def _cancel_deferred():
    global _deferred
    with _defer_lock:
        listener, _deferred = _deferred, None
    if listener is not None:
        _unlisten(listener)


def _join_now(domain, reach):
    try:
        import labkit.dds.bridge  # noqa: F401  (the slow part: Cyclone DDS's Python API)
        # CDR (and numpy), here rather than at the program's first publish over DDS
        import labkit.interfaces.cdr  # noqa: F401
    except ImportError:
        pass                      # connect() says so
    if _leaving:                  # the program ended meanwhile: join nothing
        return
    try:
        connect(domain, reach)
    except ConfigError as e:
        print(f"labkit: {e}", file=sys.stderr, flush=True)
    except Exception as e:      # no DDS here: keep working in-process, say so once
        print(f"[WARN] [labkit.dds]: {e}; staying in-process", file=sys.stderr, flush=True)


def _await_pending(leaving=False):
    """Wait for a background join under way (labkit exec's first node) to finish;
    leaving (disconnect): one that has not made its participant yet makes none."""
    global _pending, _leaving
    thread = _pending
    if leaving and thread is not None:
        _leaving = True
    if thread is not None and thread is not threading.current_thread():
        thread.join()
        with _defer_lock:
            if _pending is thread:
                _pending = None


def is_connected():
    return _bridge is not None


def auto_enabled():
    """May `labkit exec` / terminal `labkit ros2` join by default? (live time, not LABKIT_DDS=off)"""
    from labkit.graph import world
    if os.environ.get("LABKIT_DDS", "").strip().lower() in ("0", "off", "false", "no"):
        return False
    return world.mode() == "live"


def connect(domain_id=None, localhost_only=None):
    """Join the ROS 2 graph on DDS domain `domain_id` (default ROS_DOMAIN_ID or 0).

    localhost_only None follows ROS_LOCALHOST_ONLY / ROS_AUTOMATIC_DISCOVERY_RANGE and
    is True unless they open it up; False reaches the LAN (multicast discovery)."""
    global _bridge
    _cancel_deferred()
    _await_pending()
    domain, reach = _checked_settings(domain_id, localhost_only)
    with _lock:
        if _bridge is not None:
            if _bridge.domain_id == domain and _bridge.localhost == reach:
                return _bridge
            _bridge.close()
            _bridge = None
        try:
            from labkit.dds.bridge import Bridge
        except ImportError:
            raise ConnectError("labkit.connect(): the 'cyclonedds' package is not installed "
                               "(pip install cyclonedds)") from None
        try:
            _bridge = Bridge(domain, reach)
        except Exception as exc:
            raise ConnectError(f"labkit.connect(): could not create a DDS participant on "
                               f"domain {domain}: {exc}") from None
        # the process now lives on that domain, like `export ROS_DOMAIN_ID=...`: nodes
        # and ros2 verbs started from here on join it (disconnect() puts it back)
        try:   # stopping everything (labkit.reset, a test's clean-up) leaves DDS too
            from labkit import process
            if disconnect not in process.reset_hooks:
                process.reset_hooks.append(disconnect)
        except ImportError:
            pass
        if not _saved_domain:         # a reconnect keeps the value from before the first
            _saved_domain.append(os.environ.get("ROS_DOMAIN_ID"))
        os.environ["ROS_DOMAIN_ID"] = str(domain)
    return _bridge


def disconnect():
    """Leave the DDS network: remote nodes vanish from the graph; local ones stay."""
    global _bridge
    _cancel_deferred()
    _await_pending(leaving=True)
    with _lock:
        b, _bridge = _bridge, None
        if _saved_domain:
            value = _saved_domain.pop()
            if value is None:
                os.environ.pop("ROS_DOMAIN_ID", None)
            else:
                os.environ["ROS_DOMAIN_ID"] = value
    if b is not None:
        b.close()


QUIET_S = 0.3


def settle_discovery(seconds=0.5, longest=4.0):
    """Give discovery a moment (ros2cli's direct node spins 0.5 s for the same reason),
    and up to `longest` for peers whose node list has not arrived yet (a Fast DDS
    writer sends its stored ros_discovery_info at its next heartbeat, up to 3 s)."""
    import time
    _await_pending()
    b = _bridge
    if b is None:
        return
    start = time.monotonic()
    while True:
        time.sleep(0.05)
        now = time.monotonic()
        waited = now - start
        if waited >= longest:
            break
        # done when nothing new arrived for a moment and every peer's node list is in;
        # while no peer at all has answered, a loaded machine may just be slow to: a
        # little longer (an empty graph costs LONELY_S more, a busy one nothing)
        if (waited >= seconds and now - b.last_discovery >= QUIET_S
                and not b.missing_infos() and (b.peers() or waited >= seconds + LONELY_S)):
            break
    b.sync()


LONELY_S = 1.0
PATIENCE_S = 8.0


def wait_until(cond, longest=PATIENCE_S):
    """True once cond() holds. A fresh terminal process has not discovered everything
    when it starts (a real `ros2` verb asks the daemon, which has been listening all
    along): when connected, a verb that names a node waits for it to appear, up to
    `longest` seconds; not connected, the in-process graph is complete: no wait."""
    import time
    _await_pending()
    b = _bridge
    if cond():
        return True
    if b is None:
        return False
    end = time.monotonic() + longest
    while time.monotonic() < end:
        b.wait_news(0.1)
        b.sync()
        if cond():
            return True
    return False
