"""A `rosbags` typestore that knows every labkit message type (for mcap's definitions)."""
import re

_store = None


def _store_base():
    global _store
    if _store is None:
        from rosbags.typesys import Stores, get_typestore
        _store = get_typestore(Stores.ROS2_HUMBLE)
    return _store


def _full(name):
    """'geometry_msgs/Vector3' -> 'geometry_msgs/msg/Vector3'."""
    parts = name.split('/')
    return f'{parts[0]}/msg/{parts[1]}' if len(parts) == 2 else name


def typestore_for(msgtype):
    """The shared typestore, with `msgtype` and what it uses registered from labkit's .msg text."""
    from rosbags.typesys import get_types_from_msg
    import labkit.interfaces as ifc
    store = _store_base()
    todo, seen, types = [_full(msgtype)], set(), {}
    while todo:
        name = todo.pop()
        if name in seen or name in store.fielddefs:
            continue
        seen.add(name)
        types.update(get_types_from_msg(ifc.get_interface_text(name), name))
        cls = ifc.get_type(name)
        for ftype in cls.get_fields_and_field_types().values():
            base = re.sub(r'^sequence<([^,>]+).*>$', r'\1', ftype).split('[')[0]
            if '/' in base:
                todo.append(_full(base))
    if types:
        store.register(types)
    return store
