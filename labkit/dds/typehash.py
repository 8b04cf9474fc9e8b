"""RIHS01 type hashes (REP-2011), as Jazzy's rmw puts them in an endpoint's user data.

Since Iron every DDS reader and writer of a ROS 2 node carries `typehash=RIHS01_<hex>;`
in its USER_DATA QoS; real `ros2 topic info -v` prints it ("Topic type hash: ...") and
prints INVALID for an endpoint without one. Humble has no type hashes, so labkit sends
them only on Jazzy's wire (`ROS_DISTRO=jazzy`).

The hash is the SHA-256 of a JSON text: the type's description (its name and, per
field, the name and a FieldType: type id, capacity, string capacity, nested type
name; default values left out) followed by the descriptions of every type it refers
to, directly or not, sorted by name. The text is written with ', ' and ': ' between
items and keys in this fixed order. It is computed here from labkit's own generated
classes (their field list is the .msg file's, as rosidl reads it).
"""
import hashlib
import json

from labkit.interfaces import definition as d

PREFIX = "RIHS01_"

# type_description_interfaces/msg/FieldType: the id of each value type, and what
# is added for fixed arrays, bounded and unbounded sequences
_VALUE_IDS = {
    "int8": 2, "uint8": 3, "int16": 4, "uint16": 5, "int32": 6, "uint32": 7,
    "int64": 8, "uint64": 9, "float": 10, "double": 11, "long double": 12,
    "char": 13, "wchar": 14, "boolean": 15, "octet": 16,
}
_NESTED, _STRING, _WSTRING, _BOUNDED_STRING, _BOUNDED_WSTRING = 1, 17, 18, 21, 22
_ARRAY_OFFSET, _BOUNDED_OFFSET, _UNBOUNDED_OFFSET = 48, 96, 144

_cache = {}


def _value_id(value_type):
    if isinstance(value_type, d.BasicType):
        return _VALUE_IDS[value_type.typename]
    if isinstance(value_type, d.AbstractGenericString):
        wide = isinstance(value_type, d.AbstractWString)
        if value_type.has_maximum_size():
            return _BOUNDED_WSTRING if wide else _BOUNDED_STRING
        return _WSTRING if wide else _STRING
    return _NESTED


def _nested_name(value_type):
    if isinstance(value_type, d.NamespacedType):
        return "/".join((*value_type.namespaces, value_type.name))
    return ""


def field_type(t):
    """The FieldType dict of one member type (a labkit/rosidl type descriptor)."""
    value = t.value_type if isinstance(t, d.AbstractNestedType) else t
    type_id, capacity = _value_id(value), 0
    if isinstance(t, d.Array):
        type_id, capacity = type_id + _ARRAY_OFFSET, t.size
    elif isinstance(t, d.BoundedSequence):
        type_id, capacity = type_id + _BOUNDED_OFFSET, t.maximum_size
    elif isinstance(t, d.UnboundedSequence):
        type_id += _UNBOUNDED_OFFSET
    string_capacity = (value.maximum_size if isinstance(value, d.AbstractGenericString)
                       and value.has_maximum_size() else 0)
    return {"type_id": type_id, "capacity": capacity, "string_capacity": string_capacity,
            "nested_type_name": _nested_name(value)}


def individual_description(type_name):
    """{'type_name', 'fields'} of one message type ('pkg/msg/Name')."""
    from labkit.interfaces.registry import get_class
    cls = get_class(type_name)
    fields = [{"name": name, "type": field_type(t)}
              for name, t in zip(cls.get_fields_and_field_types(), cls.SLOT_TYPES)]
    if not fields:   # rosidl gives an empty structure one uint8 member
        fields = [{"name": d.EMPTY_STRUCTURE_REQUIRED_MEMBER_NAME,
                   "type": field_type(d.BasicType("uint8"))}]
    return {"type_name": type_name, "fields": fields}


def type_description(type_name):
    """The hashed form of a type: its description and every type it refers to."""
    main = individual_description(type_name)
    seen, queue = {}, [main]
    while queue:
        for field in queue.pop()["fields"]:
            nested = field["type"]["nested_type_name"]
            if nested and nested not in seen:
                seen[nested] = individual_description(nested)
                queue.append(seen[nested])
    return {"type_description": main,
            "referenced_type_descriptions": [seen[name] for name in sorted(seen)]}


def type_hash(type_name):
    """'RIHS01_<64 hex digits>' of a message type such as 'std_msgs/msg/String'."""
    value = _cache.get(type_name)
    if value is None:
        text = json.dumps(type_description(type_name), ensure_ascii=True, allow_nan=False,
                          separators=(", ", ": "))
        value = _cache[type_name] = PREFIX + hashlib.sha256(text.encode("utf-8")).hexdigest()
    return value


def user_data(type_name):
    """The USER_DATA bytes Jazzy's rmw gives an endpoint of this type (b'' if unknown)."""
    try:
        return ("typehash=%s;" % type_hash(type_name)).encode("ascii")
    except (LookupError, KeyError, ValueError):
        return b""
