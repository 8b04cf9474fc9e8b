"""ros_discovery_info: which nodes own which DDS readers and writers.

Every ROS 2 process publishes one `rmw_dds_common/msg/ParticipantEntitiesInfo`
(reliable, transient local, keep last 1) listing its nodes and the gids of their
readers and writers; `ros2 node list` is built from these. A gid is the entity's
16-byte RTPS GUID; Humble's Gid.msg is `char[24]` (the GUID and 8 zero bytes),
Jazzy's `char[16]`. The codec is written out here so both layouts can be read.
"""
import struct

TOPIC = "ros_discovery_info"
DDS_TYPE = "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"
HUMBLE_GID, JAZZY_GID = 24, 16
ENCAPSULATION = b"\x00\x01\x00\x00"       # CDR, little endian


def gid_size(distro):
    """The Gid.msg size the ROS distribution uses (Humble unless told otherwise)."""
    return JAZZY_GID if (distro or "").strip().lower() not in ("", "humble") else HUMBLE_GID


def make_gid(guid16, size=HUMBLE_GID):
    if len(guid16) != 16:
        raise ValueError("an RTPS GUID is 16 bytes")
    return bytes(guid16) + bytes(size - 16)


class _Writer:
    def __init__(self):
        self.buf = bytearray()

    def align(self, n):
        self.buf += bytes(-len(self.buf) % n)

    def u32(self, value):
        self.align(4)
        self.buf += struct.pack("<I", value)

    def string(self, text):
        data = text.encode("utf-8")
        self.u32(len(data) + 1)
        self.buf += data + b"\x00"


def encode(participant_gid, nodes, size=HUMBLE_GID):
    """CDR bytes (with encapsulation) of a ParticipantEntitiesInfo.

    nodes: [(namespace, name, [reader gids], [writer gids])], gids as 16-byte GUIDs
    (padded to `size`) or already `size` bytes long."""
    w = _Writer()

    def gid(value):
        value = bytes(value)
        w.buf += value + bytes(size - len(value)) if len(value) <= size else value[:size]

    gid(participant_gid)
    w.u32(len(nodes))
    for namespace, name, readers, writers in nodes:
        w.string(namespace)
        w.string(name)
        for seq in (readers, writers):
            w.u32(len(seq))
            for g in seq:
                gid(g)
    return ENCAPSULATION + bytes(w.buf)


class DecodeError(ValueError):
    pass


def decode(data, size=None):
    """(participant gid, [(namespace, name, [reader gids], [writer gids])]); gids as
    16-byte GUIDs. size None tries Humble's layout, then Jazzy's."""
    if size is None:
        for candidate in (HUMBLE_GID, JAZZY_GID):
            try:
                return decode(data, candidate)
            except DecodeError:
                continue
        raise DecodeError("not a ParticipantEntitiesInfo")
    body = memoryview(bytes(data))[4:]
    pos = 0

    def need(n):
        if pos + n > len(body):
            raise DecodeError("truncated")

    def align(n):
        nonlocal pos
        pos += -pos % n

    def u32():
        nonlocal pos
        align(4)
        need(4)
        value = struct.unpack_from("<I", body, pos)[0]
        pos += 4
        return value

    def gid():
        nonlocal pos
        need(size)
        value = bytes(body[pos:pos + 16])
        if any(body[pos + 16:pos + size]):
            raise DecodeError("gid padding is not zero")
        pos += size
        return value

    def string():
        nonlocal pos
        n = u32()
        if n == 0 or n > 257:
            raise DecodeError("bad string")
        need(n)
        raw = bytes(body[pos:pos + n])
        if raw[-1:] != b"\x00":
            raise DecodeError("string without NUL")
        pos += n
        return raw[:-1].decode("utf-8")

    participant = gid()
    count = u32()
    if count > 100000:
        raise DecodeError("too many nodes")
    nodes = []
    for _ in range(count):
        namespace, name = string(), string()
        seqs = []
        for _ in range(2):
            n = u32()
            if n * size > len(body):
                raise DecodeError("bad sequence")
            seqs.append([gid() for _ in range(n)])
        nodes.append((namespace, name, seqs[0], seqs[1]))
    if len(body) - pos >= 4:
        raise DecodeError("trailing data")
    return participant, nodes
