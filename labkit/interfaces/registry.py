"""Where interface files live, and the cache of generated classes.

Roots are searched newest first: a root added with `add_share_path` (a sourced
workspace) overrides the bundled `share/` like an overlay overrides an underlay.
Classes are generated on first request, with their nested types.
"""
import os
import threading

from labkit.interfaces import definition as d
from labkit.interfaces import generator as g
from labkit.interfaces import parser as p

BUNDLED_SHARE = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'share')
KINDS = ('msg', 'srv', 'action')
_EXT = {'msg': '.msg', 'srv': '.srv', 'action': '.action'}
_ACTION_PARTS = ('_SendGoal_Request', '_SendGoal_Response', '_GetResult_Request',
                 '_GetResult_Response', '_SendGoal', '_GetResult', '_FeedbackMessage',
                 '_Goal', '_Result', '_Feedback')

_lock = threading.RLock()
_roots = [BUNDLED_SHARE]
_index = None            # {pkg: {kind: {name: path}}}
_classes = {}            # 'pkg/kind/Name' -> class (also derived names)


def add_share_path(path):
    """Add a root holding `<pkg>/{msg,srv,action}/*`; it takes precedence over earlier ones."""
    global _index
    path = os.path.abspath(os.fspath(path))
    with _lock:
        if path in _roots:
            _roots.remove(path)
        _roots.insert(0, path)
        # packages found there may redefine types: forget what was generated for them
        pkgs = set(_scan_root(path))
        for key in [k for k in _classes if k.split('/', 1)[0] in pkgs]:
            del _classes[key]
        _index = None
        from labkit.interfaces import modules
        modules.forget(pkgs)


def share_paths():
    return list(_roots)


def _scan_root(root):
    found = {}
    try:
        entries = list(os.scandir(root))
    except OSError:
        return found
    for entry in entries:
        if not entry.is_dir():
            continue
        for kind in KINDS:
            kdir = os.path.join(entry.path, kind)
            try:
                files = os.listdir(kdir)
            except OSError:
                continue
            for f in files:
                stem, ext = os.path.splitext(f)
                if ext == _EXT[kind]:
                    found.setdefault(entry.name, {}).setdefault(kind, {})[stem] = \
                        os.path.join(kdir, f)
    return found


def index():
    global _index
    with _lock:
        if _index is None:
            merged = {}
            for root in reversed(_roots):   # later (overlay) roots win
                for pkg, kinds in _scan_root(root).items():
                    # an overlay package replaces the underlay package as a whole
                    merged[pkg] = kinds
            _index = merged
        return _index


def find_file(pkg, kind, name):
    return index().get(pkg, {}).get(kind, {}).get(name)


def read_text(path):
    with open(path, encoding='utf-8') as f:
        return f.read()


def split_name(name):
    """'pkg/msg/T' | 'pkg/T' -> (pkg, kind, T); raises LookupError if malformed."""
    if not isinstance(name, str):
        raise LookupError('invalid interface name: %r' % (name,))
    parts = name.split('/')
    if len(parts) == 2 and all(parts):
        return parts[0], 'msg', parts[1]
    if len(parts) == 3 and all(parts) and parts[1] in KINDS:
        return parts[0], parts[1], parts[2]
    raise LookupError("invalid interface name '%s'" % name)


def get_class(name):
    pkg, kind, tname = split_name(name)
    key = '%s/%s/%s' % (pkg, kind, tname)
    cls = _classes.get(key)
    if cls is not None:
        return cls
    with _lock:
        cls = _classes.get(key)
        if cls is None:
            cls = _generate(pkg, kind, tname)
        return cls


def _generate(pkg, kind, tname):
    path = find_file(pkg, kind, tname)
    if path is not None:
        text = read_text(path)
        if kind == 'msg':
            spec = p.parse_message_string(pkg, tname, text)
            return _message(pkg, kind, tname, spec)
        if kind == 'srv':
            return _service(pkg, tname, p.parse_service_string(pkg, tname, text))
        return _action(pkg, tname, p.parse_action_string(pkg, tname, text))
    # derived names: Spawn_Request, RotateAbsolute_SendGoal, ..._FeedbackMessage
    if kind == 'srv':
        for suffix in ('_Request', '_Response'):
            base = tname[:-len(suffix)]
            if tname.endswith(suffix) and find_file(pkg, 'srv', base):
                _generate_cached(pkg, 'srv', base)
                return _classes['%s/srv/%s' % (pkg, tname)]
    if kind == 'action':
        for suffix in _ACTION_PARTS:
            base = tname[:-len(suffix)]
            if tname.endswith(suffix) and find_file(pkg, 'action', base):
                _generate_cached(pkg, 'action', base)
                return _classes['%s/action/%s' % (pkg, tname)]
    raise LookupError("unknown interface '%s/%s/%s'" % (pkg, kind, tname))


def _generate_cached(pkg, kind, tname):
    key = '%s/%s/%s' % (pkg, kind, tname)
    if key not in _classes:
        _generate(pkg, kind, tname)
    return _classes[key]


def _resolve(nt, field):
    """The class of a nested type, or rosidl's UnknownMessageType."""
    try:
        return _generate_cached(nt.namespaces[0], nt.namespaces[1], nt.name)
    except LookupError:
        raise p.UnknownMessageType(
            "Message interface '%s/%s' contains an unknown field type: %s %s"
            % (nt.namespaces[0], nt.name, field.msg_type, field.name)) from None


def _members_of(spec):
    members = []
    for f in spec.fields:
        t = f.type
        base = t.value_type if isinstance(t, d.AbstractNestedType) else t
        cls = _resolve(base, f) if isinstance(base, d.NamespacedType) else None
        members.append(g.Member(f.name, t, f.default, cls))
    return members


def _message(pkg, kind, tname, spec, module_stem=None):
    module_name = '%s.%s._%s' % (pkg, kind, g.camel_to_snake(module_stem or tname))
    cls = g.make_message_class('%s/%s/%s' % (pkg, kind, tname), module_name, tname,
                               _members_of(spec), spec.constants)
    cls._labkit_spec = spec
    _classes['%s/%s/%s' % (pkg, kind, tname)] = cls
    return cls


def _derived(pkg, kind, tname, members, module_stem):
    module_name = '%s.%s._%s' % (pkg, kind, g.camel_to_snake(module_stem))
    cls = g.make_message_class('%s/%s/%s' % (pkg, kind, tname), module_name, tname, members)
    _classes['%s/%s/%s' % (pkg, kind, tname)] = cls
    return cls


def _service(pkg, name, spec, kind='srv'):
    request = _message(pkg, kind, name + '_Request', spec.request, module_stem=name)
    response = _message(pkg, kind, name + '_Response', spec.response, module_stem=name)
    return _service_of(pkg, kind, name, request, response, name)


def _service_of(pkg, kind, name, request, response, module_stem):
    module_name = '%s.%s._%s' % (pkg, kind, g.camel_to_snake(module_stem))
    cls = g.make_service_class('%s/%s/%s' % (pkg, kind, name), module_name, name,
                               request, response)
    _classes['%s/%s/%s' % (pkg, kind, name)] = cls
    return cls


def _action(pkg, name, spec):
    k = 'action'
    goal = _message(pkg, k, name + '_Goal', spec.goal, module_stem=name)
    result = _message(pkg, k, name + '_Result', spec.result, module_stem=name)
    feedback = _message(pkg, k, name + '_Feedback', spec.feedback, module_stem=name)
    uuid = _generate_cached('unique_identifier_msgs', 'msg', 'UUID')
    time = _generate_cached('builtin_interfaces', 'msg', 'Time')
    goal_id_t = d.NamespacedType(['unique_identifier_msgs', 'msg'], 'UUID')

    def nt(n):
        return d.NamespacedType([pkg, k], n)
    send_goal = _service_of(pkg, k, name + '_SendGoal', _derived(
        pkg, k, name + '_SendGoal_Request',
        [g.Member('goal_id', goal_id_t, None, uuid),
         g.Member('goal', nt(name + '_Goal'), None, goal)], name), _derived(
        pkg, k, name + '_SendGoal_Response',
        [g.Member('accepted', d.BasicType('boolean')),
         g.Member('stamp', d.NamespacedType(['builtin_interfaces', 'msg'], 'Time'), None, time)],
        name), name)
    get_result = _service_of(pkg, k, name + '_GetResult', _derived(
        pkg, k, name + '_GetResult_Request',
        [g.Member('goal_id', goal_id_t, None, uuid)], name), _derived(
        pkg, k, name + '_GetResult_Response',
        [g.Member('status', d.BasicType('int8')),
         g.Member('result', nt(name + '_Result'), None, result)], name), name)
    feedback_message = _derived(
        pkg, k, name + '_FeedbackMessage',
        [g.Member('goal_id', goal_id_t, None, uuid),
         g.Member('feedback', nt(name + '_Feedback'), None, feedback)], name)
    cancel = _generate_cached('action_msgs', 'srv', 'CancelGoal')
    status = _generate_cached('action_msgs', 'msg', 'GoalStatusArray')
    module_name = '%s.%s._%s' % (pkg, k, g.camel_to_snake(name))
    cls = g.make_action_class('%s/%s/%s' % (pkg, k, name), module_name, name, goal, result,
                              feedback, send_goal, get_result, feedback_message, cancel, status)
    _classes['%s/%s/%s' % (pkg, k, name)] = cls
    return cls


def remove_share_path(path):
    """Undo `add_share_path` (the bundled root stays)."""
    global _index
    path = os.path.abspath(os.fspath(path))
    with _lock:
        if path not in _roots or path == BUNDLED_SHARE:
            return
        _roots.remove(path)
        pkgs = set(_scan_root(path))
        for key in [k for k in _classes if k.split('/', 1)[0] in pkgs]:
            del _classes[key]
        _index = None
        from labkit.interfaces import modules
        modules.forget(pkgs)
