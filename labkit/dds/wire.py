"""What goes on the DDS wire for a ROS 2 entity: names, type names, QoS, payload framing.

ROS 2 puts a topic `/chatter` on the DDS topic `rt/chatter`, a service `/add` on
`rq/addRequest` + `rr/addReply`, and names a type `std_msgs/msg/String` as
`std_msgs::msg::dds_::String_`. Payloads are XCDR1 (CDR with the 4-byte
encapsulation header): exactly labkit's `rmw_serialize` bytes.
"""
import struct
from dataclasses import dataclass

TOPIC, REQUEST, REPLY = "rt", "rq", "rr"
HEADER = struct.Struct("<Qq")      # rmw_cyclonedds_cpp's request header: client id, sequence


def topic_to_dds(name):
    return TOPIC + name


def request_topic(name):
    return REQUEST + name + "Request"


def reply_topic(name):
    return REPLY + name + "Reply"


def type_to_dds(type_name, suffix=""):
    """'std_msgs/msg/String' -> 'std_msgs::msg::dds_::String_' (suffix '_Request')."""
    pkg, kind, name = type_name.split("/")
    return f"{pkg}::{kind}::dds_::{name}{suffix}_"


def type_from_dds(dds_type):
    """The ROS type and which part it is: ('std_srvs/srv/Empty', 'Request'); None if not ROS."""
    parts = dds_type.split("::")
    if len(parts) != 4 or parts[2] != "dds_" or not parts[3].endswith("_"):
        return None, None
    pkg, kind, _, name = parts
    name = name[:-1]
    for part in ("Request", "Response"):
        if kind == "srv" or (kind == "action" and name.endswith("_" + part)):
            if name.endswith("_" + part):
                return f"{pkg}/{kind}/{name[:-len(part) - 1]}", part
    return f"{pkg}/{kind}/{name}", None


def entity_from_dds(topic_name):
    """('rt'|'rq'|'rr', ROS name) for a ROS topic; (None, None) for anything else."""
    prefix, _, rest = topic_name.partition("/")
    if not rest:
        return None, None
    if prefix == TOPIC:
        return TOPIC, "/" + rest
    if prefix == REQUEST and rest.endswith("Request"):
        return REQUEST, "/" + rest[:-len("Request")]
    if prefix == REPLY and rest.endswith("Reply"):
        return REPLY, "/" + rest[:-len("Reply")]
    return None, None


def pad4(data):
    # DDS serialized payloads are a whole number of 4-byte words
    extra = -len(data) % 4
    return data + bytes(extra) if extra else data


def frame_request(client_id, seq, payload):
    """Put rmw_cyclonedds_cpp's header between the encapsulation and the body."""
    return pad4(payload[:4] + HEADER.pack(client_id, seq) + payload[4:])


def unframe_request(data):
    """(client id, sequence, payload without the header)."""
    client_id, seq = HEADER.unpack_from(data, 4)
    return client_id, seq, data[:4] + data[4 + HEADER.size:]


_TYPES = {}


def raw_type(dds_type):
    """A cyclonedds type that only carries the DDS type name: labkit reads and writes
    the bytes itself. Cyclone checks each received sample against the declared
    structure and accepts trailing bytes, so one octet (every ROS message has at
    least one) lets any payload through, rmw_cyclonedds_cpp's service header included."""
    cls = _TYPES.get(dds_type)
    if cls is None:
        from cyclonedds.idl import IdlStruct
        from cyclonedds.idl.types import uint8

        @dataclass
        class Raw(IdlStruct, typename=dds_type):
            first_octet: uint8
        cls = _TYPES[dds_type] = Raw
    return cls


# ------------------------------------------------------------------ QoS, both ways
_INFINITE_NS = (0, 2**63 - 1)


def qos_to_dds(qos, *, reader=False, user_data=b""):
    """A cyclonedds Qos with the same reliability, durability, history, depth,
    deadline, lifespan and liveliness as an rclpy QoSProfile (rmw's mapping), and
    `user_data` (Jazzy's `typehash=...;`) as the endpoint's USER_DATA."""
    from cyclonedds.qos import Qos, Policy
    policies = [Policy.Userdata(user_data)] if user_data else []
    rel = int(qos.reliability)
    policies.append(Policy.Reliability.BestEffort if rel == 2 else
                    Policy.Reliability.Reliable(max_blocking_time=100_000_000))
    dur = int(qos.durability)
    policies.append(Policy.Durability.TransientLocal if dur == 1 else Policy.Durability.Volatile)
    if int(qos.history) == 2:
        policies.append(Policy.History.KeepAll)
    else:
        policies.append(Policy.History.KeepLast(max(1, int(qos.depth or 10))))
    for name, policy in (("deadline", Policy.Deadline), ("lifespan", Policy.Lifespan)):
        ns = getattr(qos, name).nanoseconds
        if ns not in _INFINITE_NS and not (reader and name == "lifespan"):
            policies.append(policy(ns))
    lease = qos.liveliness_lease_duration.nanoseconds
    if int(qos.liveliness) == 3:
        policies.append(Policy.Liveliness.ManualByTopic(lease if lease not in _INFINITE_NS
                                                        else 2**63 - 1))
    elif lease not in _INFINITE_NS:
        policies.append(Policy.Liveliness.Automatic(lease))
    return Qos(*policies)


def qos_from_dds(dds_qos):
    """The QoSProfile a discovered endpoint offers (what `topic info -v` prints)."""
    from cyclonedds.qos import Policy
    from labkit.rclpy.qos import (QoSProfile, HistoryPolicy, ReliabilityPolicy,
                                  DurabilityPolicy, LivelinessPolicy)
    from labkit.rclpy.duration import Duration, Infinite

    def get(policy):
        try:
            return dds_qos[policy]
        except (KeyError, TypeError, AttributeError):
            return None

    def dur(value):
        if value is None or value >= 2**63 - 1:
            return Infinite
        return Duration(nanoseconds=value)

    rel = get(Policy.Reliability)
    durability = get(Policy.Durability)
    history = get(Policy.History)
    live = get(Policy.Liveliness)
    deadline = get(Policy.Deadline)
    lifespan = get(Policy.Lifespan)
    profile = QoSProfile(
        history=(HistoryPolicy.KEEP_ALL if history is not None and "KeepAll" in repr(history)
                 else HistoryPolicy.KEEP_LAST),
        depth=getattr(history, "depth", 1) or 1,
        reliability=(ReliabilityPolicy.BEST_EFFORT if rel is not None and "BestEffort" in repr(rel)
                     else ReliabilityPolicy.RELIABLE),
        durability=(DurabilityPolicy.TRANSIENT_LOCAL
                    if durability is not None and "TransientLocal" in repr(durability)
                    else DurabilityPolicy.VOLATILE),
        liveliness=(LivelinessPolicy.MANUAL_BY_TOPIC
                    if live is not None and "ManualByTopic" in repr(live)
                    else LivelinessPolicy.AUTOMATIC),
    )
    profile.deadline = dur(getattr(deadline, "deadline", None))
    profile.lifespan = dur(getattr(lifespan, "lifespan", None))
    profile.liveliness_lease_duration = dur(getattr(live, "lease_duration", None))
    return profile
