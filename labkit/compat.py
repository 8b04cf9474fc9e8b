"""The import hook: `import rclpy`, `from std_msgs.msg import String`, ... resolve to labkit.

`activate()` puts one finder at the front of `sys.meta_path`. It answers for
three kinds of names and leaves every other import to Python:

- module aliases (`rclpy`, `rclpy.node`, ... -> `labkit.rclpy...`): the very
  same module objects, so `rclpy.node.Node is labkit.rclpy.node.Node`;
- interface packages that labkit.interfaces knows (`std_msgs`, `std_msgs.msg`,
  `turtlesim.srv`, ...; also packages added later with `add_share_path`);
- small stand-ins for `rosidl_runtime_py` built on labkit.interfaces.

A user who sourced a real ROS 2 install keeps it: if a real `rclpy` is found
on sys.path while AMENT_PREFIX_PATH is set, nothing is activated.
"""
import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import os
import sys
import types

# Top-level name -> labkit module it stands for. Later layers (tf2, launch, bag,
# ament, vision) add theirs with register_alias().
_ALIASES = {
    'rclpy': 'labkit.rclpy',
}

_INTERFACE_KINDS = ('msg', 'srv', 'action')

_finder = None


def register_alias(name, target):
    """Make `import <name>[.sub]` resolve to `<target>[.sub]` while the hook is active."""
    _ALIASES[name] = target


def aliased_packages():
    """The ROS packages labkit stands in for as Python modules (rclpy, tf2_ros, ...)."""
    return set(_ALIASES)


def is_active():
    return _finder is not None and _finder in sys.meta_path


def sourced_rclpy():
    """Path of a real rclpy from a sourced ROS 2 install, or None."""
    if not os.environ.get('AMENT_PREFIX_PATH'):
        return None
    spec = importlib.machinery.PathFinder.find_spec('rclpy')
    if spec is None:
        return None
    origin = spec.origin or (list(spec.submodule_search_locations or [''])[0])
    here = os.path.dirname(os.path.abspath(__file__))
    if origin and os.path.abspath(origin).startswith(here + os.sep):
        return None
    return origin or '?'


def activate(*, quiet=False):
    """Install the hook; returns True when labkit now answers `import rclpy`."""
    global _finder
    if is_active():
        return True
    real = sourced_rclpy()
    if real is not None:
        if not quiet:
            print(f'labkit: a sourced ROS 2 provides rclpy ({real}); '
                  'the labkit import hook stays off.', file=sys.stderr)
        return False
    if _finder is None:
        _finder = _LabkitFinder()
    # the finder asks the interfaces layer which names are packages; let that layer (and
    # numpy, which it imports) load now, not from inside the finder during someone's
    # `import numpy` (numpy would then be executed twice and lose its submodules)
    _packages()
    sys.meta_path.insert(0, _finder)
    from labkit import plugins
    plugins.register_all()
    return True


def deactivate():
    """Remove the hook and forget the modules it handed out (a later import looks again)."""
    global _finder
    if _finder is None:
        return
    while _finder in sys.meta_path:
        sys.meta_path.remove(_finder)
    for name in list(sys.modules):
        if _finder.answered(name):
            del sys.modules[name]
    _finder = None


# --------------------------------------------------------------------------- finder

class _ExistingModuleLoader(importlib.abc.Loader):
    """Hands out an already-built module object, leaving its own __spec__ intact."""

    def __init__(self, make):
        self._make = make
        self._module = None
        self._spec = None

    def create_module(self, spec):
        self._module = self._make()
        self._spec = getattr(self._module, '__spec__', None)
        return self._module

    def exec_module(self, module):
        # importlib stamped our alias spec on the module; give it back its own.
        if self._spec is not None:
            try:
                module.__spec__ = self._spec
            except AttributeError:
                pass


class _LabkitFinder(importlib.abc.MetaPathFinder):

    def __init__(self):
        self._answered = set()

    def answered(self, name):
        return name in self._answered

    def find_spec(self, fullname, path=None, target=None):
        make = self._maker(fullname)
        if make is None:
            return None
        self._answered.add(fullname)
        is_package = '.' not in fullname or fullname.count('.') == 1 and \
            fullname.split('.')[0] in _ALIASES
        spec = importlib.util.spec_from_loader(
            fullname, _ExistingModuleLoader(make), is_package=is_package)
        return spec

    def _maker(self, fullname):
        """Return a function building the module for `fullname`, or None if not ours."""
        top, _, rest = fullname.partition('.')
        if top in _ALIASES:
            target = _ALIASES[top] + ('.' + rest if rest else '')
            if not _module_exists(target):
                if fullname == 'rclpy.serialization':
                    return _serialization_module
                return None
            return lambda: importlib.import_module(target)
        if top == 'rosidl_runtime_py':
            return _rosidl_runtime_py_maker(rest)
        if not _is_interface_package(top):
            return None
        if not rest:
            return lambda: _interface_package(top)
        kind, _, private = rest.partition('.')
        if kind not in _INTERFACE_KINDS or not _has_kind(top, kind):
            return None
        # `std_msgs.msg._string` (rclpy's private module) is the kind module too.
        if private and not private.startswith('_'):
            return None
        return lambda: _interfaces().module(f'{top}.{kind}')


def _module_exists(name):
    if name in sys.modules:
        return True
    try:
        return importlib.util.find_spec(name) is not None
    except (ImportError, ValueError):
        return False


def _interfaces():
    import labkit.interfaces
    return labkit.interfaces


def _packages():
    try:
        return set(_interfaces().list_packages())
    except Exception:  # the interfaces layer is missing or broken: answer nothing
        return set()


def _is_interface_package(name):
    if name.startswith('_') or name == 'labkit':
        return False
    return name in _packages()


def _has_kind(package, kind):
    try:
        names = _interfaces().list_interfaces(package)
    except Exception:
        return False
    return any(n.split('/')[1] == kind for n in names)


def _interface_package(package):
    module = types.ModuleType(package, f'ROS 2 interface package {package} (labkit)')
    module.__path__ = []
    module.__package__ = package
    return module


# --------------------------------------------------------------------------- stand-ins

def _serialization_module():
    ifc = _interfaces()
    module = types.ModuleType('rclpy.serialization')

    def serialize_message(message):
        return ifc.rmw_serialize(message)  # Humble's bytes, padding included

    def deserialize_message(serialized_message, message_type):
        return ifc.deserialize(serialized_message, message_type)

    module.serialize_message = serialize_message
    module.deserialize_message = deserialize_message
    return module


def _rosidl_runtime_py_maker(rest):
    builders = {
        '': _rosidl_runtime_py,
        'utilities': _rosidl_utilities,
        'convert': _rosidl_convert,
        'set_message': _rosidl_set_message,
        'get_interfaces': _rosidl_get_interfaces,
        'import_message': _rosidl_import_message,
    }
    return builders.get(rest)


def _new(name, **attrs):
    module = types.ModuleType(name)
    module.__dict__.update(attrs)
    return module


def _import_interface(namespaces, name):
    module = importlib.import_module('.'.join(namespaces))
    return getattr(module, name)


def _namespaced(identifier, default_kind):
    parts = identifier.split('/')
    namespaces = parts[:-1]
    if len(namespaces) == 1 and default_kind is not None:
        namespaces.append(default_kind)
    return namespaces, parts[-1]


def _is_message(i):
    return hasattr(i, 'SLOT_TYPES')


def _is_service(i):
    return hasattr(i, 'Request') and hasattr(i, 'Response')


def _is_action(i):
    return hasattr(i, 'Goal') and hasattr(i, 'Result') and hasattr(i, 'Feedback')


def _rosidl_utilities():
    def get_interface(identifier):
        return _import_interface(*_namespaced(identifier, None))

    def getter(kind, check, word):
        def get(identifier):
            interface = _import_interface(*_namespaced(identifier, kind))
            if not check(interface):
                raise ValueError(f"Expected the full name of {word}, got '{identifier}'")
            return interface
        get.__name__ = f'get_{ {"msg": "message", "srv": "service"}.get(kind, kind)}'
        return get

    return _new(
        'rosidl_runtime_py.utilities',
        get_interface=get_interface,
        get_message=getter('msg', _is_message, 'a message'),
        get_service=getter('srv', _is_service, 'a service'),
        get_action=getter('action', _is_action, 'an action'),
        is_message=_is_message, is_service=_is_service, is_action=_is_action)


def _rosidl_convert():
    conv = importlib.import_module('labkit.interfaces.convert')
    names = ('message_to_yaml', 'message_to_csv', 'message_to_ordereddict',
             'get_message_slot_types')
    return _new('rosidl_runtime_py.convert',
                **{n: getattr(conv, n) for n in names if hasattr(conv, n)})


def _rosidl_set_message():
    conv = importlib.import_module('labkit.interfaces.convert')
    return _new('rosidl_runtime_py.set_message', set_message_fields=conv.set_message_fields)


def _rosidl_get_interfaces():
    ifc = _interfaces()

    def _by_package(package_names, kind=None):
        known = set(ifc.list_packages())
        for p in package_names:
            if p not in known:
                raise LookupError(f"Unknown package '{p}'")
        result = {}
        for full in ifc.list_interfaces():
            pkg, k, name = full.split('/')
            if package_names and pkg not in package_names:
                continue
            if kind is None or k == kind:
                result.setdefault(pkg, []).append(f'{k}/{name}' if kind is None else name)
        return result

    return _new(
        'rosidl_runtime_py.get_interfaces',
        get_interface_packages=lambda: sorted(ifc.list_packages()),
        get_interfaces=lambda package_names=(): _by_package(list(package_names)),
        get_message_interfaces=lambda package_names=(): _by_package(list(package_names), 'msg'),
        get_service_interfaces=lambda package_names=(): _by_package(list(package_names), 'srv'),
        get_action_interfaces=lambda package_names=(): _by_package(list(package_names), 'action'))


def _rosidl_import_message():
    def import_message_from_namespaced_type(namespaced_type):
        return _import_interface(list(namespaced_type.namespaces), namespaced_type.name)
    return _new('rosidl_runtime_py.import_message',
                import_message_from_namespaced_type=import_message_from_namespaced_type)


def _rosidl_runtime_py():
    module = types.ModuleType('rosidl_runtime_py')
    module.__path__ = []
    subs = [_rosidl_convert(), _rosidl_set_message(), _rosidl_get_interfaces(),
            _rosidl_import_message()]
    for sub in subs:
        for key, value in vars(sub).items():
            if not key.startswith('__'):
                setattr(module, key, value)
    return module
