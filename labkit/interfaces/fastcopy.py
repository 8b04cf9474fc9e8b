"""`copy_message`: one deep copy per publish, built per class as straight-line code.

Immutable values (numbers, str, bytes) are shared; array.array and numpy arrays
are copied with one memcpy; nested messages and lists are copied recursively.

The copy is what a subscriber would get from real rclpy, where every message
crosses into C and back: scalar float32 fields come back rounded to float32
(0.1 -> 0.10000000149011612) and sequences come back as lists.
"""
import struct

from labkit.interfaces import definition as d

_copiers = {}


def _kind(t):
    if isinstance(t, d.BasicType) and t.typename == 'float':
        return 'float32'
    if isinstance(t, d.AbstractNestedType):
        vt = t.value_type
        if isinstance(vt, d.BasicType) and vt.typename in d.ARRAY_TYPECODES:
            return 'ndarray' if isinstance(t, d.Array) else 'array'
        return 'msglist' if isinstance(vt, d.NamespacedType) else 'list'
    return 'msg' if isinstance(t, d.NamespacedType) else 'value'


def _build(cls):
    members = cls._labkit_members
    ns = {'new': object.__new__, 'cls': cls, 'list': list}
    lines = ['def copy(m):', '    n = new(cls)']
    floats = ['_' + m.name for m in members if _kind(m.type) == 'float32']
    if floats:
        # one struct round trip rounds all float32 fields, as the C message would
        fmt = struct.Struct('<%df' % len(floats))
        ns['f32pack'], ns['f32unpack'] = fmt.pack, fmt.unpack
        targets = ', '.join('n.%s' % f for f in floats)
        sources = ', '.join('m.%s' % f for f in floats)
        lines.append('    %s, = f32unpack(f32pack(%s))' % (targets, sources))
    for i, mem in enumerate(members):
        s = '_' + mem.name
        k = _kind(mem.type)
        if k == 'float32':
            continue
        if k == 'value':
            lines.append('    n.%s = m.%s' % (s, s))
        elif k == 'array':
            lines.append('    n.%s = m.%s[:]' % (s, s))
        elif k == 'ndarray':
            lines.append('    n.%s = m.%s.copy()' % (s, s))
        elif k == 'list':
            lines.append('    n.%s = list(m.%s)' % (s, s))
        elif k == 'msg':
            ns['c%d' % i] = copier(mem.cls)
            lines.append('    n.%s = c%d(m.%s)' % (s, i, s))
        else:
            ns['c%d' % i] = copier(mem.cls)
            lines.append('    n.%s = [c%d(x) for x in m.%s]' % (s, i, s))
    lines.append('    return n')
    exec('\n'.join(lines), ns)
    return ns['copy']


def copier(cls):
    fn = _copiers.get(cls)
    if fn is None:
        fn = _copiers[cls] = _build(cls)
    return fn


def copy_message(msg):
    fn = _copiers.get(msg.__class__)
    if fn is None:
        fn = copier(msg.__class__)
    return fn(msg)
