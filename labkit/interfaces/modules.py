"""Module objects like the generated Python packages: `std_msgs.msg`, `std_msgs.msg._string`.

Classes are made on first attribute access (PEP 562 `__getattr__`), so importing
`std_msgs.msg` costs nothing until a class is used.
"""
import sys
import threading
import types

from labkit.interfaces import generator as g
from labkit.interfaces import registry

_lock = threading.Lock()
_modules = {}


class InterfaceModule(types.ModuleType):
    """`pkg.kind` (all interfaces of a kind) or `pkg.kind._stem` (one file's classes)."""

    def __init__(self, name, pkg, kind, names):
        super().__init__(name)
        self._labkit_pkg = pkg
        self._labkit_kind = kind
        self._labkit_names = tuple(names)
        self.__all__ = list(names)
        depth = name.count('.')
        self.__package__ = name if depth < 2 else name.rsplit('.', 1)[0]
        if depth < 2:
            self.__path__ = []      # a package: `import std_msgs.msg._string` can resolve

    def __getattr__(self, attr):
        if attr.startswith('__') or attr not in self._labkit_names:
            raise AttributeError("module '%s' has no attribute '%s'" % (self.__name__, attr))
        if self._labkit_kind is None:       # the package itself: its msg/srv/action modules
            value = module('%s.%s' % (self._labkit_pkg, attr))
        else:
            value = registry.get_class('%s/%s/%s' % (self._labkit_pkg, self._labkit_kind, attr))
        setattr(self, attr, value)
        return value

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._labkit_names))


def _file_classes(kind, name):
    """Class names one interface file defines in its `_stem` module."""
    if kind == 'msg':
        return [name]
    if kind == 'srv':
        return [name + '_Request', name + '_Response', name]
    return [name + s for s in ('_Goal', '_Result', '_Feedback', '_SendGoal_Request',
                               '_SendGoal_Response', '_SendGoal', '_GetResult_Request',
                               '_GetResult_Response', '_GetResult', '_FeedbackMessage', '')]


def module(name):
    """Module object for 'std_msgs', 'std_msgs.msg' or 'std_msgs.msg._string' (else LookupError)."""
    mod = _modules.get(name)
    if mod is not None:
        return mod
    parts = name.split('.')
    if len(parts) == 1:
        kinds = registry.index().get(name)
        if not kinds:
            raise LookupError("no interface module '%s'" % name)
        mod = InterfaceModule(name, name, None, [k for k in registry.KINDS if kinds.get(k)])
        with _lock:
            return _modules.setdefault(name, mod)
    if len(parts) not in (2, 3) or parts[1] not in registry.KINDS:
        raise LookupError("no interface module '%s'" % name)
    pkg, kind = parts[0], parts[1]
    names = sorted(registry.index().get(pkg, {}).get(kind, {}))
    if len(parts) == 2:
        if not names:
            raise LookupError("no interface module '%s'" % name)
        mod = InterfaceModule(name, pkg, kind, names)
    else:
        stem = parts[2]
        match = [n for n in names if '_' + g.camel_to_snake(n) == stem]
        if not match:
            raise LookupError("no interface module '%s'" % name)
        mod = InterfaceModule(name, pkg, kind, _file_classes(kind, match[0]))
    with _lock:
        return _modules.setdefault(name, mod)


def forget(pkgs):
    with _lock:
        for key in [k for k in _modules if k.split('.', 1)[0] in pkgs]:
            del _modules[key]
    # an imported `pkg.msg` would go on serving the old names: the next import rebuilds it
    for key, mod in list(sys.modules.items()):
        if isinstance(mod, InterfaceModule) and key.split('.', 1)[0] in pkgs:
            del sys.modules[key]
