"""Late access to message classes of labkit.interfaces (layer 1), with type helpers."""
_cache = {}


def msg_class(name):
    cls = _cache.get(name)
    if cls is None:
        from labkit.interfaces import get_type
        cls = _cache[name] = get_type(name)
    return cls


def type_name(cls_or_msg):
    """'pkg/msg/Name' of a message/service class or instance."""
    t = getattr(cls_or_msg, "_labkit_type", None)
    if t is not None:
        return t
    try:
        from labkit.interfaces import type_name as _tn
        return _tn(cls_or_msg)
    except Exception:
        cls = cls_or_msg if isinstance(cls_or_msg, type) else type(cls_or_msg)
        mod = cls.__module__.split(".")
        if len(mod) >= 2:
            return f"{mod[0]}/{mod[1]}/{cls.__name__}"
        return cls.__name__


def copy_message(msg):
    global copy_message
    try:
        from labkit.interfaces import copy_message as _copy
    except Exception:
        import copy as _c
        _copy = _c.deepcopy
    copy_message = _copy
    return _copy(msg)
