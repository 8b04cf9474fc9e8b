"""CDR (little-endian XCDR1, as ROS 2 Humble's Fast DDS writes it) for generated classes.

Per class, straight-line (de)serializer code is generated once: nested messages
are inlined, runs of fixed-size fields become one `struct` call with the
padding computed ahead of time. The bytes equal `rclpy.serialization.serialize_message`.
"""
import array
import struct
import sys

import numpy

from labkit.interfaces import definition as d

HEADER = b'\x00\x01\x00\x00'   # CDR_LE, options 0
_FMT = {'boolean': '?', 'octet': 'c', 'int8': 'b', 'uint8': 'B', 'int16': 'h', 'uint16': 'H',
        'int32': 'i', 'uint32': 'I', 'int64': 'q', 'uint64': 'Q', 'float': 'f', 'double': 'd'}
_SIZE = {k: struct.calcsize('<' + v) for k, v in _FMT.items()}
_LITTLE = sys.byteorder == 'little'

_serializers = {}
_plain = set()
_deserializers = {}


class CdrError(ValueError):
    pass


def _is_basic(t):
    return isinstance(t, d.BasicType)


def _numeric(t):
    return isinstance(t, d.BasicType) and t.typename in d.ARRAY_TYPECODES


def is_plain(cls):
    """Fixed layout: no strings or sequences anywhere (rosidl_typesupport_fastrtps' PLAIN_TYPE)."""
    for m in cls._labkit_members:
        t = m.type
        if isinstance(t, d.Array):
            t = t.value_type
        if isinstance(t, d.NamespacedType):
            if not is_plain(m.cls):
                return False
        elif not isinstance(t, d.BasicType):
            return False
    return True


class _Layout:
    """What we know of the write position: offset % mod == rem."""

    def __init__(self, mod):
        self.mod, self.rem = mod, 0

    def static_pad(self, size):
        """Padding to align to `size` if known now, else None."""
        if self.mod % size == 0:
            return (-self.rem) % size
        return None

    def advance(self, n):
        self.rem = (self.rem + n) % self.mod

    def reset(self, mod):
        self.mod, self.rem = mod, 0


def _flatten(cls, path, out):
    """Leaf items of a message: nested single messages are inlined, in field order."""
    members = cls._labkit_members
    if not members:
        out.append(('empty', path, None, None))
        return
    for m in members:
        t = m.type
        p = '%s._%s' % (path, m.name)
        if isinstance(t, d.NamespacedType):
            out.append(('enter', p, m.cls, None))
            _flatten(m.cls, p, out)
        else:
            out.append(('leaf', p, t, m.cls))


class _Writer:
    """Emits serializer source for one class."""

    def __init__(self, cls, mod):
        self.split = mod == 8     # top level: may hand big arrays over without copying
        self.ns = {'pack_I': struct.Struct('<I').pack, 'Z': bytes(8)}
        self.lines = []
        self.run_fmt, self.run_args = '', []
        self.layout = _Layout(mod)
        self.count = 0
        items = []
        _flatten(cls, 'm', items)
        for kind, path, t, sub in items:
            if kind == 'empty':
                self.prim('uint8', '0')
            elif kind == 'leaf':
                self.leaf(path, t, sub)

    def name(self, prefix):
        self.count += 1
        return '%s%d' % (prefix, self.count)

    def flush(self):
        if self.run_fmt:
            s = self.name('S')
            self.ns[s] = struct.Struct('<' + self.run_fmt).pack
            self.lines.append('    b += %s(%s)' % (s, ', '.join(self.run_args)))
            self.run_fmt, self.run_args = '', []

    def align(self, size):
        pad = self.layout.static_pad(size)
        if pad is None:
            self.flush()
            self.lines.append('    b += Z[:(4 - len(b)) %% %d]' % size)
            self.layout.reset(size)
        elif pad:
            self.run_fmt += '%dx' % pad
            self.layout.advance(pad)

    def prim(self, typename, expr):
        size = _SIZE[typename]
        self.align(size)
        self.run_fmt += _FMT[typename]
        self.run_args.append(expr)
        self.layout.advance(size)

    def raw(self, code, mod_after):
        """Dynamic-size bytes: flush the run, then the position is only known modulo `mod_after`."""
        self.flush()
        self.lines.extend(code)
        self.layout.reset(mod_after)

    def leaf(self, path, t, sub):
        if _is_basic(t):
            self.prim(t.typename, path)
        elif isinstance(t, d.AbstractGenericString):
            v = self.name('s')
            wide = isinstance(t, d.AbstractWString)
            if wide:
                self.lines.insert(0, '    %s = %s.encode("utf-32-le")' % (v, path))
                self.prim('uint32', 'len(%s) // 4' % v)
                self.raw(['    b += %s' % v], 4)
            else:
                self.lines.insert(0, '    %s = %s.encode()' % (v, path))
                self.prim('uint32', 'len(%s) + 1' % v)
                self.raw(['    b += %s' % v, "    b.append(0)"], 1)
        elif isinstance(t, d.AbstractNestedType):
            self.nested(path, t, sub)
        else:
            raise CdrError('cannot serialize %r' % (t,))

    def nested(self, path, t, sub):
        vt = t.value_type
        fixed = isinstance(t, d.Array)
        v = self.name('v')
        if not fixed:
            self.flush()
            self.lines.append('    %s = %s' % (v, path))
            self.prim('uint32', 'len(%s)' % v)
            self.flush()
        else:
            self.flush()
            self.lines.append('    %s = %s' % (v, path))
        if _numeric(vt):
            size = _SIZE[vt.typename]
            if fixed:
                self.align(size)
                self.flush()
                self.lines.append('    b += %s' % self.tobytes(v, vt, fixed))
                self.layout.advance(size * t.size)
            else:
                self.lines.append('    if %s:' % v)
                self.lines.append('        b += Z[:(4 - len(b)) %% %d]' % size)
                if self.split and _LITTLE:
                    # a big block joins the output as is: growing a bytearray by
                    # megabytes costs far more than one final join
                    self.lines.append('        if len(%s) > 4096:' % v)
                    self.lines.append('            parts.append(memoryview(b)[skip:])')
                    self.lines.append('            parts.append(%s)' % v)
                    self.lines.append('            skip = (len(b) + %d * len(%s)) %% 8' % (size, v))
                    self.lines.append('            b = bytearray(skip)')
                    self.lines.append('        else:')
                    self.lines.append('            b += %s' % self.tobytes(v, vt, fixed))
                else:
                    self.lines.append('        b += %s' % self.tobytes(v, vt, fixed))
                self.layout.reset(min(4, size))
        elif _is_basic(vt) and vt.typename == 'boolean':
            self.raw(['    b += bytes(%s)' % v], 1)
            if fixed:
                self.layout.reset(1)
        elif _is_basic(vt) and vt.typename == 'octet':
            self.raw(["    b += b''.join(%s)" % v], 1)
        else:
            # strings and messages: one call per element
            key = self.name('e')
            self.ns[key] = _element_serializer(vt, sub)
            self.raw(['    for x in %s:' % v, '        %s(x, b)' % key], 1)

    def tobytes(self, v, vt, fixed):
        if fixed:
            dt = '<' + numpy.dtype(d.NUMPY_DTYPES[vt.typename]).str[1:]
            self.ns['dt_' + vt.typename] = numpy.dtype(dt)
            return 'numpy.asarray(%s, dtype=dt_%s).tobytes()' % (v, vt.typename)
        if _LITTLE:
            return '%s.tobytes()' % v
        return '_swapped(%s)' % v

    def source(self, fname):
        self.flush()
        self.ns.update({'numpy': numpy, '_swapped': _swapped})
        if self.split:
            return 'def %s(m, b, parts):\n    skip = 0\n%s\n    return b, skip\n' % (
                fname, '\n'.join(self.lines))
        body = self.lines or ['    pass']
        return 'def %s(m, b):\n%s\n' % (fname, '\n'.join(body))


def _swapped(a):
    a = array.array(a.typecode, a)
    a.byteswap()
    return a.tobytes()


def _element_serializer(vt, cls):
    if isinstance(vt, d.NamespacedType):
        return loose_serializer(cls)
    wide = isinstance(vt, d.AbstractWString)
    pack_I = struct.Struct('<I').pack

    def ser_string(x, b):
        b += bytes((4 - len(b)) % 4)
        if wide:
            e = x.encode('utf-32-le')
            b += pack_I(len(e) // 4)
            b += e
        else:
            e = x.encode()
            b += pack_I(len(e) + 1)
            b += e
            b.append(0)
    return ser_string


def _compile(cls, mod, cache, builder, fname):
    fn = cache.get(cls)
    if fn is None:
        w = builder(cls, mod)
        src = w.source(fname)
        exec(compile(src, '<labkit cdr %s>' % cls._labkit_type, 'exec'), w.ns)
        fn = cache[cls] = w.ns[fname]
    return fn


_loose_ser = {}
_loose_de = {}


def loose_serializer(cls):
    """Serializer usable at any position (elements of sequences)."""
    return _compile(cls, 1, _loose_ser, _Writer, 'ser')


def serialize(msg):
    """CDR bytes as they travel on the wire and are stored in bags (rosbags gives the same)."""
    cls = msg.__class__
    fn = _serializers.get(cls)
    if fn is None:
        if not hasattr(cls, '_labkit_members'):
            raise TypeError('serialize() expects a ROS message, got %r' % (msg,))
        fn = _compile(cls, 8, _serializers, _Writer, 'ser')
        if is_plain(cls):
            _plain.add(cls)
    parts = []
    b, skip = fn(msg, bytearray(HEADER), parts)
    if not parts:
        return bytes(b)
    parts.append(memoryview(b)[skip:])
    return b''.join(parts)


class _Reader:
    """Emits deserializer source for one class: builds objects without running setters."""

    def __init__(self, cls, mod):
        self.ns = {'new': object.__new__, 'unpack_I': struct.Struct('<I').unpack_from,
                   'array': array.array, 'numpy': numpy}
        self.lines = []
        self.run_fmt, self.run_targets = '', []
        self.layout = _Layout(mod)
        self.count = 0
        self.pending_pos = 0          # bytes of the current run
        self.ns['C0'] = cls
        self.lines.append('    m = new(C0)')
        items = []
        _flatten(cls, 'm', items)
        for kind, path, t, sub in items:
            if kind == 'enter':
                c = self.name('C')
                self.ns[c] = t
                self.lines.append('    %s = new(%s)' % (path.replace('.', '_'), c))
                parent, _, attr = path.rpartition('.')
                self.lines.append('    %s.%s = %s' % (self.var(parent), attr,
                                                       path.replace('.', '_')))
            elif kind == 'empty':
                self.prim('uint8', None)
            else:
                self.leaf(self.target(path), t, sub)

    @staticmethod
    def var(path):
        return path.replace('.', '_')

    def target(self, path):
        parent, _, attr = path.rpartition('.')
        return '%s.%s' % (self.var(parent), attr)

    def name(self, prefix):
        self.count += 1
        return '%s%d' % (prefix, self.count)

    def flush(self):
        if self.run_fmt and not self.run_targets:      # only padding
            self.lines.append('    pos += %d' % struct.calcsize('<' + self.run_fmt))
            self.run_fmt = ''
        elif self.run_fmt:
            s = self.name('U')
            st = struct.Struct('<' + self.run_fmt)
            self.ns[s] = st.unpack_from
            targets = [t or '_' for t in self.run_targets]
            if len(targets) == 1:
                targets[0] += ','
            self.lines.append('    %s = %s(data, pos)' % (', '.join(targets), s))
            self.lines.append('    pos += %d' % st.size)
            self.run_fmt, self.run_targets = '', []

    def align(self, size):
        pad = self.layout.static_pad(size)
        if pad is None:
            self.flush()
            self.lines.append('    pos += (4 - pos) %% %d' % size)
            self.layout.reset(size)
        elif pad:
            self.run_fmt += '%dx' % pad
            self.layout.advance(pad)

    def prim(self, typename, target):
        size = _SIZE[typename]
        self.align(size)
        self.run_fmt += _FMT[typename]
        self.run_targets.append(target)
        self.layout.advance(size)

    def leaf(self, target, t, sub):
        if _is_basic(t):
            self.prim(t.typename, target)
        elif isinstance(t, d.AbstractGenericString):
            n = self.name('n')
            self.prim('uint32', n)
            self.flush()
            if isinstance(t, d.AbstractWString):
                self.lines.append("    %s = data[pos:pos + 4 * %s].decode('utf-32-le')"
                                  % (target, n))
                self.lines.append('    pos += 4 * %s' % n)
                self.layout.reset(4)
            else:
                self.lines.append("    %s = data[pos:pos + %s - 1].decode()" % (target, n))
                self.lines.append('    pos += %s' % n)
                self.layout.reset(1)
        else:
            self.nested(target, t, sub)

    def nested(self, target, t, sub):
        vt = t.value_type
        fixed = isinstance(t, d.Array)
        n = self.name('n')
        if fixed:
            self.flush()
            self.lines.append('    %s = %d' % (n, t.size))
        else:
            self.prim('uint32', n)
            self.flush()
        if _numeric(vt):
            size = _SIZE[vt.typename]
            if fixed:
                self.align(size)
                self.flush()
                dt = numpy.dtype('<' + numpy.dtype(d.NUMPY_DTYPES[vt.typename]).str[1:])
                key = 'dt_' + vt.typename
                self.ns[key] = dt
                self.lines.append('    %s = numpy.frombuffer(data, %s, %s, pos).astype(%r)'
                                  % (target, key, n, d.NUMPY_DTYPES[vt.typename]))
                self.lines.append('    pos += %d' % (size * t.size))
                self.layout.advance(size * t.size)
            else:
                tc = d.ARRAY_TYPECODES[vt.typename]
                v = self.name('a')
                self.lines.append("    %s = array(%r)" % (v, tc))
                self.lines.append('    if %s:' % n)
                self.lines.append('        pos += (4 - pos) %% %d' % size)
                self.lines.append('        %s.frombytes(memoryview(data)[pos:pos + %d * %s])'
                                  % (v, size, n))
                if not _LITTLE:
                    self.lines.append('        %s.byteswap()' % v)
                self.lines.append('        pos += %d * %s' % (size, n))
                self.lines.append('    %s = %s' % (target, v))
                self.layout.reset(min(4, size))
        elif _is_basic(vt) and vt.typename == 'boolean':
            self.lines.append('    %s = [x != 0 for x in data[pos:pos + %s]]' % (target, n))
            self.lines.append('    pos += %s' % n)
            self.layout.reset(1)
        elif _is_basic(vt) and vt.typename == 'octet':
            self.lines.append('    %s = [bytes((x,)) for x in data[pos:pos + %s]]' % (target, n))
            self.lines.append('    pos += %s' % n)
            self.layout.reset(1)
        else:
            key = self.name('e')
            self.ns[key] = _element_deserializer(vt, sub)
            v = self.name('l')
            self.lines.append('    %s = []' % v)
            self.lines.append('    for _ in range(%s):' % n)
            self.lines.append('        x, pos = %s(data, pos)' % key)
            self.lines.append('        %s.append(x)' % v)
            self.lines.append('    %s = %s' % (target, v))
            self.layout.reset(1)

    def source(self, fname):
        self.flush()
        return 'def %s(data, pos):\n%s\n    return m, pos\n' % (fname, '\n'.join(self.lines))


def _element_deserializer(vt, cls):
    if isinstance(vt, d.NamespacedType):
        return _compile(cls, 1, _loose_de, _Reader, 'de')
    wide = isinstance(vt, d.AbstractWString)
    unpack_I = struct.Struct('<I').unpack_from

    def de_string(data, pos):
        pos += (4 - pos) % 4
        (n,) = unpack_I(data, pos)
        pos += 4
        if wide:
            return data[pos:pos + 4 * n].decode('utf-32-le'), pos + 4 * n
        return data[pos:pos + n - 1].decode(), pos + n
    return de_string


def deserialize(data, cls):
    """Message of class `cls` from CDR bytes (with the 4-byte encapsulation header)."""
    if not hasattr(cls, '_labkit_members'):
        raise TypeError('deserialize() expects a ROS message class, got %r' % (cls,))
    data = bytes(data)
    if len(data) < 4 or data[1] != 1:
        raise CdrError('only little-endian CDR is supported')
    fn = _deserializers.get(cls)
    if fn is None:
        fn = _compile(cls, 8, _deserializers, _Reader, 'de')
    try:
        msg, _ = fn(data, 4)
    except (struct.error, IndexError, UnicodeDecodeError) as e:
        raise CdrError('cannot deserialize %s: %s' % (cls._labkit_type, e)) from None
    return msg


def _estimate(msg, ca):
    """Humble's generated get_serialized_size(): an upper estimate used by rmw_serialize."""
    start = ca
    members = msg._labkit_members
    if not members:
        return 1
    for m in members:
        t = m.type
        value = getattr(msg, '_' + m.name)
        if isinstance(t, d.AbstractNestedType):
            vt = t.value_type
            if not isinstance(t, d.Array):
                ca += 4 + (-ca) % 4
            if isinstance(vt, d.AbstractGenericString):
                for s in value:
                    ca += 4 + (-ca) % 4 + _string_units(s, vt)
            elif isinstance(vt, d.BasicType):
                size = _SIZE[vt.typename]
                ca += len(value) * size + (-ca) % size
            else:
                for sub in value:
                    ca += _estimate(sub, ca)
        elif isinstance(t, d.AbstractGenericString):
            ca += 4 + (-ca) % 4 + _string_units(value, t)
        elif isinstance(t, d.BasicType):
            size = _SIZE[t.typename]
            ca += size + (-ca) % size
        else:
            ca += _estimate(value, ca)
    return ca - start


def _string_units(s, t):
    if isinstance(t, d.AbstractWString):
        return 4 * (len(s.encode('utf-16-le')) // 2 + 1)
    return len(s.encode()) + 1


def rmw_serialize(msg):
    """The bytes `rclpy.serialization.serialize_message` returns on Humble (rmw_fastrtps_cpp).

    The CDR data are `serialize(msg)`'s; only the length differs: rmw sizes the buffer
    from the type support's estimate (plain types: their fixed size rounded up to 4;
    others: get_serialized_size(), which aligns even empty sequences), and the bytes
    past the data are left as they were (zeros here).
    """
    data = serialize(msg)
    cls = msg.__class__
    if cls in _plain:
        # rmw_fastrtps gives fixed-layout ("plain") types their maximum size rounded to 4
        return data + bytes((-len(data)) % 4)
    size = 4 + _estimate(msg, 0)
    if size > len(data):
        data += bytes(size - len(data))
    return data
