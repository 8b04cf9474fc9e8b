"""Which DDS domain, and how far discovery reaches: the ROS environment variables.

ROS_DOMAIN_ID (0..232; rcl refuses anything else), Humble's ROS_LOCALHOST_ONLY and
Jazzy's ROS_AUTOMATIC_DISCOVERY_RANGE. labkit's default is localhost only: the
loopback interface, no multicast, the peer 127.0.0.1 (the LAN only when asked).
"""
import os

from labkit import oslayer

MAX_DOMAIN_ID = 232
# Fast DDS in LOCALHOST mode probes only the first few participant indexes:
# Cyclone must take the lowest free one, and probe a few more itself.
MAX_PARTICIPANT_INDEX = 32
# Linux's default socket receive buffer (net.core.rmem_default): what a Fast DDS reader
# (rmw_fastrtps' default) receives into, on the learner's robot as on this machine
PEER_RECEIVE_BUFFER = 212992
NACK_DELAY = "5ms"
# loopback only (see _loopback_bursts): a writer with unacknowledged data heartbeats
# every 5 ms instead of Cyclone's 100 ms (`minsched` 2 ms: Cyclone's 20 ms floor would
# undo it), and may send a heartbeat not tied to a write (e.g. after a retransmit) 1 ms
# after the previous one (`min`; Cyclone's default 5 ms)
HEARTBEAT_INTERVAL, HEARTBEAT_MINSCHED, HEARTBEAT_MIN = "5ms", "2ms", "1ms"
# localhost mode names the loopback by its address, which every OS has (the interface is
# `lo` on Linux, `lo0` on macOS, and Windows has no such name); on Linux only,
# sockets.confine also binds Cyclone's wildcard sockets to the device LOOPBACK_DEVICE
LOOPBACK = oslayer.LOOPBACK_ADDRESS
LOOPBACK_DEVICE = oslayer.LOOPBACK_DEVICE


class ConfigError(ValueError):
    """A setting that ROS itself would refuse (the message is ROS's one line)."""


def domain_id(value=None):
    """The domain to join: `value`, else ROS_DOMAIN_ID, else 0."""
    if value is None:
        text = os.environ.get("ROS_DOMAIN_ID", "").strip()
        if not text:
            return 0
        if not text.isdigit():
            raise ConfigError("failed to get default domain id: "
                              "ROS_DOMAIN_ID is not an integral number")
        value = int(text)
    if isinstance(value, bool) or not isinstance(value, int):
        raise ConfigError(f"domain_id must be an integer, got {value!r}")
    if not 0 <= value <= MAX_DOMAIN_ID:
        raise ConfigError(f"Domain id {value} is out of range: "
                          f"it must be from 0 to {MAX_DOMAIN_ID}")
    return value


def localhost_only(value=None):
    """True (the default), or False when the user asked for the LAN.

    ROS_LOCALHOST_ONLY=0 (Humble) or ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET|SYSTEM_DEFAULT
    (Jazzy) open it up; ROS_AUTOMATIC_DISCOVERY_RANGE=OFF gives 'off' (no peers)."""
    if value is not None:
        return bool(value)
    rng = os.environ.get("ROS_AUTOMATIC_DISCOVERY_RANGE", "").strip().upper()
    if rng == "OFF":
        return "off"
    if rng in ("SUBNET", "SYSTEM_DEFAULT"):
        return False
    if rng == "LOCALHOST":
        return True
    if os.environ.get("ROS_LOCALHOST_ONLY", "").strip() == "0":
        return False
    return True


def cyclone_xml(localhost=True):
    """The Cyclone DDS configuration: loopback and unicast to 127.0.0.1 by default."""
    if localhost is False:
        general = "<Interfaces><NetworkInterface autodetermine=\"true\"/></Interfaces>"
        discovery = "<ParticipantIndex>auto</ParticipantIndex>"
    else:
        # loopback carries 64 kB datagrams: a 640x480 image is 15 of them instead of
        # 63 (fewer datagrams overflow a peer's socket buffer less often)
        general = (f"<Interfaces><NetworkInterface address=\"{LOOPBACK}\"/></Interfaces>"
                   "<AllowMulticast>false</AllowMulticast>"
                   "<MaxMessageSize>65000B</MaxMessageSize><FragmentSize>62000B</FragmentSize>")
        peers = "" if localhost == "off" else "<Peers><Peer address=\"127.0.0.1\"/></Peers>"
        discovery = ("<ParticipantIndex>auto</ParticipantIndex>"
                     f"<MaxAutoParticipantIndex>{MAX_PARTICIPANT_INDEX}</MaxAutoParticipantIndex>"
                     + peers)
    return ("<CycloneDDS><Domain Id=\"any\"><General>" + general + "</General>"
            "<Discovery>" + discovery + "</Discovery>"
            # the watermarks bound only a KEEP_ALL writer's unacknowledged data: Cyclone
            # 11.0.1 never blocks a KEEP_LAST one (ROS's usual depth N) on them. A KEEP_ALL
            # writer past WhcHigh waits until WhcLow (1 kB) or max_blocking_time (labkit's
            # 100 ms; then the sample is dropped); a sample larger than WhcHigh is still
            # taken, the next write waits for it. rmw_cyclonedds_cpp keeps the 500 kB
            # default but waits forever (DDS_INFINITY): 32 MB keeps labkit's KEEP_ALL
            # writes from failing where rmw's would only wait (e.g. on 640x480 frames)
            "<Internal><Watermarks><WhcHigh>32MB</WhcHigh></Watermarks>"
            # a reader NACKs what a heartbeat says it misses after 5 ms, as a Fast DDS
            # reader does (its heartbeatResponseDelay), not after Cyclone's 100 ms: a
            # 640x480 frame missing one datagram stalled the frames queued behind it
            # for ~200 ms between two labkit processes
            f"<NackDelay>{NACK_DELAY}</NackDelay>"
            + ("" if localhost is False else _loopback_bursts()) + "</Internal>"
            "<Tracing><Verbosity>none</Verbosity></Tracing></Domain></CycloneDDS>")


def _loopback_bursts():
    """On loopback a sample's datagrams arrive as fast as Cyclone sends them: a whole
    640x480 image (15 datagrams of 62 kB) overran a Fast DDS reader's socket buffer, the
    heartbeat sent after them was dropped too, the reader fell more than its history
    depth behind and skipped frames. Cyclone assumes a peer that does not announce its
    buffer has one as large as its own (2 MB here); send at most 2/3 of Linux's default
    buffer at a time, the rest when the reader asks for it (NACKFRAG), as Cyclone does
    for peers that announce a small buffer. MaxInitTransmit 0: a first transmission is
    bounded like a retransmission. On a LAN the wire paces the sender: defaults there.

    Cyclone 11.0.1 cannot bound bursts per peer: a writer's limit is the smallest receive
    buffer among its readers, and a Cyclone peer announces the very size Cyclone assumes
    for a Fast DDS one (its own), so labkit -> labkit frames go in bursts too. Then each
    frame is repaired NACK by NACK, and a NACKFRAG that arrives before the writer has
    finished its first burst gets its fragments but no heartbeat after them (Cyclone
    follows a retransmit with one only for what it has already sent), so the reader waits
    for the writer's next periodic heartbeat: 100 ms by default (plus a NackDelay when
    only a final heartbeat came), which the frames queued behind shared (~200 ms stalls).
    HEARTBEAT_INTERVAL bounds that wait (heartbeats go out only while a reader has not
    acknowledged everything: none on an idle or fully acknowledged writer)."""
    burst = PEER_RECEIVE_BUFFER * 2 // 3
    return (f"<BurstSize><MaxRexmit>{burst}B</MaxRexmit>"
            "<MaxInitTransmit>0</MaxInitTransmit></BurstSize>"
            f"<HeartbeatInterval min=\"{HEARTBEAT_MIN}\" minsched=\"{HEARTBEAT_MINSCHED}\">"
            f"{HEARTBEAT_INTERVAL}</HeartbeatInterval>")


def with_user_config(xml):
    """labkit's configuration, then the user's CYCLONEDDS_URI (files or XML, as
    rmw_cyclonedds_cpp reads it): what the user sets there wins."""
    user = os.environ.get("CYCLONEDDS_URI", "").strip()
    return xml + "," + user if user else xml


def distro():
    return os.environ.get("ROS_DISTRO", "humble")
