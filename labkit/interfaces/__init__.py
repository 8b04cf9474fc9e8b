"""Layer 1: ROS 2 interfaces (.msg/.srv/.action), their Python classes, CDR and conversions.

Public functions (stable; other rooms depend on these names):

    get_type('std_msgs/msg/String' | 'std_msgs/String')  -> class (LookupError if unknown)
    type_name(cls_or_msg)                                 -> 'std_msgs/msg/String'
    copy_message(msg)                                     -> deep copy (publish hot path)
    serialize(msg) -> bytes; deserialize(data, cls)       -> CDR as on the wire / in bags
    rmw_serialize(msg)                                    -> exactly rclpy's serialize_message
    module('std_msgs.msg')                                -> module object with the classes
                                                 (also 'std_msgs', 'std_msgs.msg._string')
    list_packages(); list_interfaces(pkg=None); get_interface_text(name)
    add_share_path(path)                                  -> extra `<root>/<pkg>/<kind>/*` roots
    labkit.interfaces.convert                             -> rosidl_runtime_py's conversions
    labkit.interfaces.show.interface_show(name, ...)      -> `ros2 interface show` text
"""
from labkit.interfaces.fastcopy import copy_message
from labkit.interfaces.modules import module
from labkit.interfaces.registry import add_share_path, remove_share_path, share_paths

__all__ = ['get_type', 'type_name', 'copy_message', 'serialize', 'rmw_serialize', 'deserialize',
           'module',
           'list_packages', 'list_interfaces', 'get_interface_text', 'add_share_path',
           'share_paths', 'remove_share_path', 'is_message', 'is_service', 'is_action']


def get_type(name):
    """The class of 'pkg/msg/T', 'pkg/srv/T', 'pkg/action/T' or 'pkg/T' (a message).

    Derived names work too: 'pkg/srv/T_Request', 'pkg/action/T_SendGoal', ...
    """
    from labkit.interfaces import registry
    return registry.get_class(name)


def type_name(cls_or_obj):
    """'std_msgs/msg/String' for the class or an instance; TypeError for anything else."""
    try:
        return cls_or_obj._labkit_type
    except AttributeError:
        raise TypeError('%r is not a ROS interface type' % (cls_or_obj,)) from None


def is_message(cls_or_obj):
    return hasattr(cls_or_obj, 'SLOT_TYPES') and hasattr(cls_or_obj, '_labkit_type')


def is_service(cls_or_obj):
    return hasattr(cls_or_obj, 'Request') and hasattr(cls_or_obj, 'Response')


def is_action(cls_or_obj):
    return all(hasattr(cls_or_obj, a) for a in ('Goal', 'Result', 'Feedback'))


def serialize(msg):
    """CDR bytes as on the wire and in bags (4-byte header + data, no trailing padding)."""
    from labkit.interfaces.cdr import serialize as _serialize
    return _serialize(msg)


def rmw_serialize(msg):
    """What Humble's `rclpy.serialization.serialize_message` returns: `serialize(msg)` plus the
    trailing bytes rmw_fastrtps adds (its buffer is sized from the type support's estimate)."""
    from labkit.interfaces.cdr import rmw_serialize as _rmw_serialize
    return _rmw_serialize(msg)


def deserialize(data, cls):
    from labkit.interfaces.cdr import deserialize as _deserialize
    return _deserialize(data, cls)


def list_packages():
    """Sorted names of packages that define at least one interface."""
    from labkit.interfaces import registry
    return sorted(pkg for pkg, kinds in registry.index().items() if any(kinds.values()))


def list_interfaces(pkg=None):
    """Sorted 'pkg/kind/Name' strings, of one package or of all."""
    from labkit.interfaces import registry
    idx = registry.index()
    if pkg is not None and pkg not in idx:
        raise LookupError("Unknown package '%s'" % pkg)
    pkgs = [pkg] if pkg is not None else idx
    return sorted('%s/%s/%s' % (p, kind, name)
                  for p in pkgs for kind, names in idx[p].items() for name in names)


def get_interface_text(name):
    """The interface file's raw text (comments included), as `ros2 interface show` reads it."""
    from labkit.interfaces import registry
    pkg, kind, tname = registry.split_name(name)
    path = registry.find_file(pkg, kind, tname)
    if path is None:
        raise LookupError("unknown interface '%s/%s/%s'" % (pkg, kind, tname))
    return registry.read_text(path)


def __getattr__(name):
    # `labkit.interfaces.convert` without an explicit import
    if name in ('convert', 'cdr', 'definition', 'parser', 'show'):
        import importlib
        return importlib.import_module('labkit.interfaces.' + name)
    raise AttributeError("module 'labkit.interfaces' has no attribute '%s'" % name)
