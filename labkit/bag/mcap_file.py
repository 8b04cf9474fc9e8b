"""MCAP files as Humble's rosbag2_storage_mcap writes them, and a reader that survives a kill.

Written from the MCAP specification (https://mcap.dev/spec): profile `ros2`,
schemas `ros2msg` (the .msg text with its dependencies, as rosbag2's message
definition cache joins them), channels `cdr` with the `offered_qos_profiles`
metadata, a `rosbag2` metadata record with ROS_DISTRO, uncompressed chunks
without CRC (the plugin's defaults), and a summary section (schemas, channels,
statistics, chunk and metadata indexes) so any MCAP reader can seek.

One difference on purpose: a chunk is closed when it is full (libmcap's 768 KiB)
*or* CHUNK_AGE_S after its first message, and handed to the OS at once. A
recording that is SIGKILLed keeps every complete chunk; `scan()` reads such a
file record by record up to the cut, and `recover()` rewrites it whole
(`ros2 bag reindex`).
"""
import os
import re
import struct
import time

MAGIC = b'\x89MCAP0\r\n'
PROFILE = 'ros2'
LIBRARY = 'libmcap 0.8.0'          # Humble's mcap_vendor
CHUNK_SIZE = 768 * 1024            # libmcap's default chunk size
CHUNK_AGE_S = 0.5                  # wall time a message may wait in an open chunk

(HEADER, FOOTER, SCHEMA, CHANNEL, MESSAGE, CHUNK, MESSAGE_INDEX, CHUNK_INDEX, ATTACHMENT,
 ATTACHMENT_INDEX, STATISTICS, METADATA, METADATA_INDEX, SUMMARY_OFFSET, DATA_END) = range(1, 16)

_PRIMITIVES = {'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16',
               'uint16', 'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring'}
_FIELD_TYPE = re.compile(r'(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+')
_RULE = '=' * 80 + '\n'


# --------------------------------------------------------------------------- schemas

def _msg_text(name):
    import labkit.interfaces as ifc
    package, _, short = name.partition('/')
    short = short.split('/')[-1]
    return ifc.get_interface_text(f'{package}/msg/{short}')


def message_definition(type_name):
    """('ros2msg', text): the type's .msg, then each type it uses once, each after a rule
    and `MSG: pkg/Name` (how rosbag2_storage_mcap makes a schema self-contained)."""
    package = type_name.split('/')[0]
    seen = set()

    def used_by(text, context):
        found = set()
        for match in _FIELD_TYPE.finditer(text):
            kind = match.group(1)
            if kind in _PRIMITIVES:
                continue
            found.add(kind if '/' in kind else f'{context}/{kind}')
        return sorted(found)

    def expand(name, context, depth=50):
        text = _msg_text(name)
        for dep in used_by(text, context):
            if dep not in seen:
                seen.add(dep)
                text += '\n' + _RULE + f'MSG: {dep}\n' + expand(dep, dep.split('/')[0], depth - 1)
        return text

    try:
        return 'ros2msg', expand(type_name, package)
    except LookupError:
        return '', ''


# --------------------------------------------------------------------------- encoding

def _string(text):
    data = text.encode()
    return struct.pack('<I', len(data)) + data


def _map(pairs, key=_string, value=_string):
    body = b''.join(key(k) + value(v) for k, v in pairs.items())
    return struct.pack('<I', len(body)) + body


def _record(opcode, body):
    return struct.pack('<BQ', opcode, len(body)) + body


class McapWriter:
    """One `.mcap` file, written as it goes: complete chunks reach the OS every CHUNK_AGE_S."""

    def __init__(self, path, ros_distro='humble'):
        self.path = path
        self.file = open(path, 'wb')
        self.schemas = {}         # type name -> (id, encoding, data)
        self.channels = {}        # id -> (schema id, topic, encoding, metadata)
        self.counts = {}          # channel id -> messages
        self.chunk_indexes = []
        self.metadata_indexes = []
        self.start = self.end = None
        self._chunk = bytearray()
        self._index = {}          # channel id -> [(log time, offset in chunk)]
        self._chunk_span = None
        self._chunk_opened = 0.0
        self.file.write(MAGIC)
        self._put(_record(HEADER, _string(PROFILE) + _string(LIBRARY)))
        self._put_metadata('rosbag2', {'ROS_DISTRO': ros_distro})

    def _put(self, data):
        self.file.write(data)

    def _put_metadata(self, name, values):
        offset = self.file.tell()
        record = _record(METADATA, _string(name) + _map(values))
        self._put(record)
        self.metadata_indexes.append((offset, len(record), name))

    def add_channel(self, topic, type_name, encoding='cdr', offered_qos_profiles='',
                    definition=None):
        """Schema (once per type) and channel records, outside chunks; returns the channel id.

        `definition` is (schema encoding, bytes) when known (a recovered file keeps its own)."""
        self.flush()                  # readers meet a channel before its first message
        if type_name not in self.schemas:
            if definition is None:
                schema_encoding, text = message_definition(type_name)
                definition = (schema_encoding, text.encode())
            schema = (len(self.schemas) + 1, definition[0], definition[1])
            self.schemas[type_name] = schema
            self._put(_record(SCHEMA, self._schema_body(type_name, schema)))
        channel_id = len(self.channels)
        channel = (self.schemas[type_name][0], topic, encoding,
                   {'offered_qos_profiles': offered_qos_profiles})
        self.channels[channel_id] = channel
        self.counts[channel_id] = 0
        self._put(_record(CHANNEL, self._channel_body(channel_id, channel)))
        return channel_id

    @staticmethod
    def _schema_body(name, schema):
        sid, encoding, data = schema
        return struct.pack('<H', sid) + _string(name) + _string(encoding) + \
            struct.pack('<I', len(data)) + data

    @staticmethod
    def _channel_body(channel_id, channel):
        sid, topic, encoding, metadata = channel
        return struct.pack('<HH', channel_id, sid) + _string(topic) + _string(encoding) + \
            _map(metadata)

    def write(self, channel_id, timestamp, data):
        if not self._chunk:
            self._chunk_opened = time.monotonic()
            self._chunk_span = [timestamp, timestamp]
        else:
            span = self._chunk_span
            span[0], span[1] = min(span[0], timestamp), max(span[1], timestamp)
        self._index.setdefault(channel_id, []).append((timestamp, len(self._chunk)))
        self._chunk += struct.pack('<BQHIQQ', MESSAGE, 22 + len(data), channel_id, 0,
                                   timestamp, timestamp)
        self._chunk += data
        self.counts[channel_id] += 1
        self.start = timestamp if self.start is None else min(self.start, timestamp)
        self.end = timestamp if self.end is None else max(self.end, timestamp)
        if len(self._chunk) >= CHUNK_SIZE:
            self.flush()

    def flush_if_old(self):
        """Close the open chunk if it has waited CHUNK_AGE_S (the writer thread calls this)."""
        if self._chunk and time.monotonic() - self._chunk_opened >= CHUNK_AGE_S:
            self.flush()

    def flush(self):
        """Write the open chunk and its message indexes; hand the bytes to the OS."""
        if self._chunk:
            chunk_start = self.file.tell()
            start, end = self._chunk_span
            body = struct.pack('<QQQI', start, end, len(self._chunk), 0) + _string('') + \
                struct.pack('<Q', len(self._chunk)) + bytes(self._chunk)
            self._put(_record(CHUNK, body))
            chunk_length = self.file.tell() - chunk_start
            offsets = {}
            for channel_id in sorted(self._index):
                offsets[channel_id] = self.file.tell()
                entries = b''.join(struct.pack('<QQ', t, o) for t, o in self._index[channel_id])
                self._put(_record(MESSAGE_INDEX, struct.pack('<HI', channel_id, len(entries))
                                  + entries))
            self.chunk_indexes.append((start, end, chunk_start, chunk_length, offsets,
                                       self.file.tell() - chunk_start - chunk_length,
                                       len(self._chunk)))
            self._chunk = bytearray()
            self._index = {}
        self.file.flush()

    def size(self):
        return self.file.tell() + len(self._chunk)

    def close(self):
        if self.file.closed:
            return
        self.flush()
        self._put(_record(DATA_END, struct.pack('<I', 0)))
        summary_start = self.file.tell()
        groups = []

        def group(opcode, records):
            if records:
                start = self.file.tell()
                for record in records:
                    self._put(record)
                groups.append((opcode, start, self.file.tell() - start))
        group(SCHEMA, [_record(SCHEMA, self._schema_body(n, s)) for n, s in self.schemas.items()])
        group(CHANNEL, [_record(CHANNEL, self._channel_body(i, c))
                        for i, c in self.channels.items()])
        counts = b''.join(struct.pack('<HQ', i, n) for i, n in self.counts.items())
        group(STATISTICS, [_record(STATISTICS, struct.pack(
            '<QHIIIIQQI', sum(self.counts.values()), len(self.schemas), len(self.channels), 0,
            len(self.metadata_indexes), len(self.chunk_indexes), self.start or 0, self.end or 0,
            len(counts)) + counts)])
        group(CHUNK_INDEX, [_record(CHUNK_INDEX, struct.pack('<QQQQ', s, e, at, length)
                                    + _map(offsets, lambda k: struct.pack('<H', k),
                                           lambda v: struct.pack('<Q', v))
                                    + struct.pack('<Q', index_length) + _string('')
                                    + struct.pack('<QQ', size, size))
                            for s, e, at, length, offsets, index_length, size
                            in self.chunk_indexes])
        group(METADATA_INDEX, [_record(METADATA_INDEX, struct.pack('<QQ', o, n) + _string(name))
                               for o, n, name in self.metadata_indexes])
        offset_start = self.file.tell()
        for opcode, start, length in groups:
            self._put(_record(SUMMARY_OFFSET, struct.pack('<BQQ', opcode, start, length)))
        self._put(_record(FOOTER, struct.pack('<QQI', summary_start if groups else 0,
                                              offset_start if groups else 0, 0)))
        self._put(MAGIC)
        self.file.close()


# --------------------------------------------------------------------------- reading

class Contents:
    """What a scan found: schemas {id: (name, encoding, data)}, channels {id: (schema id,
    topic, encoding, metadata)}, messages [(channel id, log time, data)], complete?"""

    def __init__(self):
        self.schemas = {}
        self.channels = {}
        self.messages = []
        self.metadata = {}
        self.complete = False

    def type_of(self, channel_id):
        return self.schemas.get(self.channels[channel_id][0], ('', '', b''))[0]


class _Cursor:
    def __init__(self, data, at=0):
        self.data = data
        self.at = at

    def take(self, fmt):
        values = struct.unpack_from(fmt, self.data, self.at)
        self.at += struct.calcsize(fmt)
        return values

    def string(self):
        n, = self.take('<I')
        text = bytes(self.data[self.at:self.at + n]).decode()
        self.at += n
        return text

    def blob(self, fmt='<I'):
        n, = self.take(fmt)
        data = bytes(self.data[self.at:self.at + n])
        self.at += n
        return data

    def string_map(self):
        n, = self.take('<I')
        end, out = self.at + n, {}
        while self.at < end:
            key = self.string()
            out[key] = self.string()
        return out


def _decompress(compression, data, size):
    if compression == '':
        return data
    if compression == 'zstd':
        import zstandard
        return zstandard.ZstdDecompressor().decompress(data, max_output_size=size)
    if compression == 'lz4':
        import lz4.frame
        return lz4.frame.decompress(data)
    raise ValueError(f'unsupported chunk compression {compression!r}')


def _records(data, start, end):
    """(opcode, body start, body end) for each whole record in data[start:end]."""
    at = start
    while at + 9 <= end:
        opcode, length = struct.unpack_from('<BQ', data, at)
        if at + 9 + length > end:
            return                    # cut short (a killed writer)
        yield opcode, at + 9, at + 9 + length
        at += 9 + length


def scan(path):
    """Read an MCAP file front to back, keeping every whole record (a cut file too)."""
    with open(path, 'rb') as f:
        data = f.read()
    if not data.startswith(MAGIC):
        raise ValueError('not an MCAP file')
    found = Contents()
    _read_records(found, data, len(MAGIC), len(data), top=True)
    return found


def _read_records(found, data, start, end, top=False):
    for opcode, a, b in _records(data, start, end):
        c = _Cursor(data, a)
        if opcode == SCHEMA:
            sid, = c.take('<H')
            name, encoding = c.string(), c.string()
            found.schemas.setdefault(sid, (name, encoding, c.blob()))
        elif opcode == CHANNEL:
            cid, sid = c.take('<HH')
            topic, encoding = c.string(), c.string()
            found.channels.setdefault(cid, (sid, topic, encoding, c.string_map()))
        elif opcode == MESSAGE:
            cid, _, log_time, _ = c.take('<HIQQ')
            found.messages.append((cid, log_time, bytes(data[c.at:b])))
        elif opcode == CHUNK and top:
            _, _, size, _ = c.take('<QQQI')
            compression = c.string()
            records = _decompress(compression, c.blob('<Q'), size)
            _read_records(found, records, 0, len(records))
        elif opcode == METADATA and top:
            name = c.string()
            found.metadata[name] = c.string_map()
        elif opcode == DATA_END and top:
            found.complete = data.endswith(MAGIC) and len(data) > 2 * len(MAGIC)
            return


def recover(path, ros_distro='humble'):
    """Rewrite a cut MCAP file whole (summary, footer): what `ros2 bag reindex` does for mcap.
    Returns the scan of what was kept."""
    found = scan(path)
    if found.complete:
        return found
    partial = path + '.reindex'
    writer = McapWriter(partial, found.metadata.get('rosbag2', {}).get('ROS_DISTRO', ros_distro))
    ids = {}
    for cid, (sid, topic, encoding, metadata) in sorted(found.channels.items()):
        name, schema_encoding, schema_data = found.schemas.get(sid, ('', '', b''))
        ids[cid] = writer.add_channel(topic, name, encoding,
                                      metadata.get('offered_qos_profiles', ''),
                                      (schema_encoding, schema_data))
    for cid, stamp, data in found.messages:
        if cid in ids:
            writer.write(ids[cid], stamp, data)
    writer.close()
    os.replace(partial, path)
    return scan(path)
