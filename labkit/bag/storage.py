"""Bag storage: Humble's sqlite3 plugin (schema 3) written here, mcap through `rosbags`.

A bag is a folder `<name>/` with `<name>_0.db3` (or `.mcap`) and `metadata.yaml`.
The sqlite3 writer writes through and commits in small batches, so a recording
whose process dies keeps what it had written; metadata.yaml comes at close().
"""
import os
import sqlite3
import time

from labkit.bag.metadata import (
    METADATA_FILENAME, BagMetadata, FileInformation, TopicInformation, TopicMetadata,
    directory_size, read_metadata, write_metadata)

DEFAULT_STORAGE_ID = 'sqlite3'
STORAGE_IDS = ('sqlite3', 'mcap')
EXTENSIONS = {'sqlite3': '.db3', 'mcap': '.mcap'}
SQLITE_SCHEMA_VERSION = 3   # Humble's kDBSchemaVersion_
COMMIT_EVERY_MESSAGES = 1000
COMMIT_EVERY_SECONDS = 0.2     # wall time: what a dying kernel may lose at most
MIN_SPLIT_FILE_SIZE = 86016     # Humble's sqlite3 plugin minimum
METADATA_EVERY_SECONDS = 0.5   # metadata.yaml follows the committed batches (see read)

_SCHEMA = (
    'CREATE TABLE schema(schema_version INTEGER PRIMARY KEY,ros_distro TEXT NOT NULL);',
    'CREATE TABLE metadata(id INTEGER PRIMARY KEY,metadata_version INTEGER NOT NULL,'
    'metadata TEXT NOT NULL);',
    'CREATE TABLE topics(id INTEGER PRIMARY KEY,name TEXT NOT NULL,type TEXT NOT NULL,'
    'serialization_format TEXT NOT NULL,offered_qos_profiles TEXT NOT NULL);',
    'CREATE TABLE messages(id INTEGER PRIMARY KEY,topic_id INTEGER NOT NULL,'
    'timestamp INTEGER NOT NULL, data BLOB NOT NULL);',
    'CREATE INDEX timestamp_idx ON messages (timestamp ASC);',
)


def storage_log(text):
    """rosbag2_storage's logger lines ('[INFO] [stamp] [rosbag2_storage]: ...')."""
    from labkit.rclpy.logging import get_logger
    get_logger('rosbag2_storage').info(text)


class BagError(RuntimeError):
    """rosbag2's std::runtime_error texts."""


# --------------------------------------------------------------------------- writing

class _SqliteFile:
    def __init__(self, path):
        self.path = path
        self.conn = sqlite3.connect(path, isolation_level=None, check_same_thread=False)
        # A rollback journal keeps a killed writer's file sound (its half batch is rolled
        # back by the next reader); PERSIST spares creating it per batch; no fsync, like
        # Humble's default pragmas.
        self.conn.execute('PRAGMA journal_mode=PERSIST')
        self.conn.execute('PRAGMA synchronous=OFF')
        for stmt in _SCHEMA:
            self.conn.execute(stmt)
        self.conn.execute('INSERT INTO schema (schema_version, ros_distro) VALUES (?, ?)',
                          (SQLITE_SCHEMA_VERSION, os.environ.get('ROS_DISTRO', 'humble')))
        self._rows = []
        self._last_commit = time.monotonic()

    @property
    def _pending(self):
        return len(self._rows)

    def create_topic(self, t):
        self.commit()
        cur = self.conn.execute(
            'INSERT INTO topics (name, type, serialization_format, offered_qos_profiles) '
            'VALUES (?, ?, ?, ?)',
            (t.name, t.type, t.serialization_format, t.offered_qos_profiles))
        return cur.lastrowid

    def write(self, topic_id, timestamp, data):
        """Queue a row; True when this made a batch that was committed."""
        self._rows.append((timestamp, topic_id, bytes(data)))
        if len(self._rows) >= COMMIT_EVERY_MESSAGES or \
                time.monotonic() - self._last_commit >= COMMIT_EVERY_SECONDS:
            self.commit()
            return True
        return False

    def commit(self):
        rows, self._rows = self._rows, []
        if rows:
            self.conn.execute('BEGIN')
            self.conn.executemany(
                'INSERT INTO messages (timestamp, topic_id, data) VALUES (?, ?, ?)', rows)
            self.conn.execute('COMMIT')
        self._last_commit = time.monotonic()

    def size(self):
        return os.path.getsize(self.path)

    def settle(self):
        """Everything committed and no -journal file left behind (the writer may go idle)."""
        self.commit()
        self.conn.execute('PRAGMA journal_mode=DELETE')

    def close(self):
        self.settle()
        self.conn.close()


class _McapFile:
    """mcap through rosbags (its own metadata.yaml is replaced by Humble's at close)."""

    def __init__(self, directory):
        from rosbags.rosbag2 import StoragePlugin, Writer
        os.rmdir(directory)  # rosbags makes the folder itself
        self.writer = Writer(directory, version=8, storage_plugin=StoragePlugin.MCAP)
        self.writer.open()
        self.connections = {}
        self.path = None

    def create_topic(self, t):
        from labkit.bag.typestore import typestore_for
        conn = self.writer.add_connection(t.name, t.type, typestore=typestore_for(t.type),
                                          serialization_format=t.serialization_format)
        self.connections[conn.id] = conn
        return conn.id

    def write(self, topic_id, timestamp, data):
        self.writer.write(self.connections[topic_id], timestamp, bytes(data))
        return False

    def commit(self):
        pass

    def close(self):
        self.writer.close()
        # rosbags names the file `<name>.mcap`; rosbag2 names it `<name>_0.mcap`
        made = [p for p in os.listdir(self.writer.path) if p.endswith('.mcap')][0]
        self.path = f'{self.writer.path.name}_0.mcap'
        os.replace(self.writer.path / made, self.writer.path / self.path)


class _FileStats:
    """One storage file's FileInformation, kept as messages arrive."""

    def __init__(self, path):
        self.path = path
        self.start = None
        self.end = None
        self.count = 0

    def add(self, timestamp):
        self.count += 1
        if self.start is None or timestamp < self.start:
            self.start = timestamp
        if self.end is None or timestamp > self.end:
            self.end = timestamp

    def information(self):
        if not self.count:
            return FileInformation(self.path, 0, 0, 0)
        return FileInformation(self.path, self.start, self.end - self.start, self.count)


class BagWriter:
    """rosbag2_cpp's SequentialWriter (no cache): write-through files, metadata at close().

    max_bagfile_size (bytes) / max_bagfile_duration (s) split a sqlite3 bag into
    `<name>_0.db3`, `<name>_1.db3`, ... like Humble.
    """

    def __init__(self, uri, storage_id='', max_bagfile_size=0, max_bagfile_duration=0):
        storage_id = storage_id or DEFAULT_STORAGE_ID
        if storage_id not in STORAGE_IDS:
            raise BagError("No storage could be initialized. Abort")
        if (max_bagfile_size or max_bagfile_duration) and storage_id != 'sqlite3':
            raise BagError('labkit: bag splitting works with the sqlite3 storage only')
        if max_bagfile_size and max_bagfile_size < MIN_SPLIT_FILE_SIZE:
            raise BagError('Invalid bag splitting size given. Please provide a value greater '
                           f'than {MIN_SPLIT_FILE_SIZE}. Specified value of {max_bagfile_size}')
        uri = os.fspath(uri).rstrip('/') or '.'
        if os.path.isdir(uri):
            raise BagError(f"Database directory already exists ({uri}), "
                           "can't overwrite existing database")
        try:
            os.makedirs(uri)
        except OSError:
            raise BagError(f'Failed to create database directory ({uri}).') from None
        self.uri = uri
        self.storage_id = storage_id
        self.max_size = max_bagfile_size
        self.max_duration_ns = max_bagfile_duration * 1_000_000_000
        self.base = os.path.basename(os.path.abspath(uri))
        self.files = []    # _FileStats, one per storage file
        self.topics = {}   # name -> [topic id in the current file, TopicInformation]
        self.closed = False
        self._metadata_written = 0.0
        self._open_file()

    def _open_file(self):
        relative = f'{self.base}_{len(self.files)}{EXTENSIONS[self.storage_id]}'
        if self.storage_id == 'sqlite3':
            self.file = _SqliteFile(os.path.join(self.uri, relative))
        else:
            self.file = _McapFile(self.uri)
        self.files.append(_FileStats(relative))
        storage_log(f"Opened database '{os.path.join(self.uri, relative)}' for READ_WRITE.")
        for entry in self.topics.values():  # every file describes every topic
            entry[0] = self.file.create_topic(entry[1].topic_metadata)

    @property
    def relative_path(self):
        return self.files[-1].path

    def create_topic(self, topic):
        if topic.name in self.topics:
            return
        self.topics[topic.name] = [self.file.create_topic(topic),
                                   TopicInformation(topic, 0)]
        self._refresh_metadata()

    def remove_topic(self, topic):
        self.topics.pop(topic.name, None)

    def _should_split(self, timestamp):
        current = self.files[-1]
        if self.max_size and self.file.size() >= self.max_size:
            return True
        return bool(self.max_duration_ns and current.count and
                    timestamp - current.start > self.max_duration_ns)

    def split(self):
        self.file.close()
        self._open_file()
        self._refresh_metadata()

    def write(self, topic_name, data, timestamp):
        if self.closed:
            raise BagError('Bag is not open. Call open() before writing.')
        entry = self.topics.get(topic_name)
        if entry is None:
            raise BagError(f"Failed to write on topic '{topic_name}'. "
                           'Call create_topic() before first write.')
        timestamp = int(timestamp)
        if (self.max_size or self.max_duration_ns) and self._should_split(timestamp):
            self.split()
            entry = self.topics[topic_name]
        committed = self.file.write(entry[0], timestamp, data)
        entry[1].message_count += 1
        self.files[-1].add(timestamp)
        if committed and time.monotonic() - self._metadata_written >= METADATA_EVERY_SECONDS:
            self._refresh_metadata()

    def flush(self):
        getattr(self.file, 'settle', self.file.commit)()
        self._refresh_metadata()

    def _refresh_metadata(self):
        # rosbag2 writes metadata.yaml once, at close. A writer that is never closed (a
        # killed kernel) would leave no metadata at all, so committed batches refresh it
        # now and then; a reader that finds more rows than it describes reindexes.
        if self.storage_id == 'sqlite3':
            write_metadata(self.uri, self.metadata())
            self._metadata_written = time.monotonic()

    def metadata(self):
        files = [f.information() for f in self.files]
        used = [f for f in files if f.message_count]
        start = min((f.starting_time for f in used), default=0)
        end = max((f.starting_time + f.duration for f in used), default=0)
        return BagMetadata(
            storage_identifier=self.storage_id,
            relative_file_paths=[f.path for f in files], files=files,
            duration=end - start, starting_time=start,
            message_count=sum(f.message_count for f in files),
            topics_with_message_count=[e[1] for e in self.topics.values()])

    def close(self):
        if self.closed:
            return
        self.closed = True
        self.file.close()
        if self.storage_id == 'mcap' and self.file.path:
            self.files[-1].path = self.file.path
        write_metadata(self.uri, self.metadata())


def open_writer(uri, storage_id=''):
    return BagWriter(uri, storage_id)


# --------------------------------------------------------------------------- reading

class _SqliteReader:
    def __init__(self, path):
        self.path = path
        self.topics = {}
        query = ('SELECT id, name, type, serialization_format, offered_qos_profiles '
                 'FROM topics ORDER BY id')
        # read-only first; a bag whose writer was killed mid-batch has a hot journal,
        # which only a writable connection can roll back (leaving the committed batches)
        for mode in ('ro', 'rw'):
            self.conn = sqlite3.connect(f'file:{os.path.abspath(path)}?mode={mode}', uri=True,
                                        check_same_thread=False)
            try:
                rows = self.conn.execute(query).fetchall()
                break
            except sqlite3.OperationalError:
                self.conn.close()
                if mode == 'rw':
                    raise
        for tid, name, typ, fmt, qos in rows:
            self.topics[tid] = TopicMetadata(name, typ, fmt, qos)

    def messages(self, topics=None, start=None):
        ids = {tid: t.name for tid, t in self.topics.items()
               if topics is None or t.name in topics}
        if not ids:
            return
        query = (f'SELECT topic_id, timestamp, data FROM messages WHERE topic_id IN '
                 f'({",".join(str(i) for i in ids)})')
        params = ()
        if start is not None:
            query += ' AND timestamp >= ?'
            params = (int(start),)
        for tid, stamp, data in self.conn.execute(query + ' ORDER BY timestamp, id', params):
            yield ids[tid], data, stamp  # (sqlite3 gives BLOBs as bytes)

    def file_information(self, relative):
        row = self.conn.execute('SELECT MIN(timestamp), MAX(timestamp), COUNT(*) '
                                'FROM messages').fetchone()
        lo, hi, n = row
        counts = dict(self.conn.execute(
            'SELECT topic_id, COUNT(*) FROM messages GROUP BY topic_id').fetchall())
        info = FileInformation(relative, lo or 0, (hi - lo) if n else 0, n)
        return info, [TopicInformation(t, counts.get(tid, 0)) for tid, t in self.topics.items()]

    def close(self):
        self.conn.close()


class _McapReader:
    def __init__(self, directory):
        from rosbags.rosbag2 import Reader
        self.reader = Reader(directory)
        self.reader.open()
        self.topics = {}
        for c in self.reader.connections:
            self.topics[c.id] = TopicMetadata(c.topic, c.msgtype, c.ext.serialization_format, '')

    def messages(self, topics=None, start=None):
        conns = [c for c in self.reader.connections if topics is None or c.topic in topics]
        if not conns:
            return
        for c, stamp, data in self.reader.messages(connections=conns, start=start):
            yield c.topic, bytes(data), stamp

    def close(self):
        self.reader.close()


class BagReader:
    """SequentialReader's storage side: metadata, topics, messages in time order."""

    def __init__(self, uri, storage_id=''):
        uri = os.fspath(uri)
        if not os.path.exists(uri):
            raise BagError("No storage could be initialized from the inputs.")
        self.uri = uri
        self.metadata = read_bag_metadata(uri, storage_id)
        self.storage_id = self.metadata.storage_identifier
        directory = uri if os.path.isdir(uri) else os.path.dirname(uri) or '.'
        if self.storage_id == 'mcap':
            self.files = [_McapReader(directory)]
        else:
            paths = [os.path.join(directory, p) for p in self.metadata.relative_file_paths] \
                if os.path.isdir(uri) else [uri]
            self.files = [_SqliteReader(p) for p in paths]
        if self.metadata.relative_file_paths:
            first = self.metadata.relative_file_paths[0]
            opened = os.path.join(uri, first) if os.path.isdir(uri) else uri
            storage_log(f"Opened database '{opened}' for READ_ONLY.")

    def topics(self):
        return [t.topic_metadata for t in self.metadata.topics_with_message_count]

    def messages(self, topics=None, start=None):
        """(topic, cdr bytes, timestamp ns) in time order over every file."""
        import heapq
        streams = [f.messages(topics, start) for f in self.files]
        if len(streams) == 1:
            yield from streams[0]
            return
        yield from heapq.merge(*streams, key=lambda m: m[2])

    def close(self):
        for f in self.files:
            f.close()


def _storage_files(directory):
    def index(name):  # `bag_10.db3` comes after `bag_9.db3`
        stem = os.path.splitext(name)[0]
        tail = stem.rsplit('_', 1)[-1]
        return (int(tail) if tail.isdigit() else -1, name)
    return sorted((p for p in os.listdir(directory) if p.endswith(('.db3', '.mcap'))), key=index)


def _stale(directory, m):
    """True when a sqlite3 file holds more messages than metadata.yaml says (a writer that
    died after its last metadata refresh)."""
    if m.storage_identifier != 'sqlite3' or not m.files:
        return False
    for f in m.files:
        path = os.path.join(directory, f.path)
        if not os.path.exists(path):
            return False
        try:
            conn = sqlite3.connect(f'file:{os.path.abspath(path)}?mode=ro', uri=True)
            try:
                last = conn.execute('SELECT MAX(id) FROM messages').fetchone()[0] or 0
            finally:
                conn.close()
        except sqlite3.Error:
            return True  # a hot journal: let the reindexing reader roll it back
        if last > f.message_count:
            return True
    return False


def read_bag_metadata(uri, storage_id=''):
    """metadata.yaml if the bag has one, else what `ros2 bag reindex` would rebuild."""
    uri = os.fspath(uri)
    if os.path.isdir(uri) and os.path.exists(os.path.join(uri, METADATA_FILENAME)):
        m = read_metadata(uri)
        m.bag_size = directory_size(uri)
        if not _stale(uri, m):
            return m
    if os.path.isdir(uri):
        directory, names = uri, _storage_files(uri)
    else:
        directory, names = os.path.dirname(uri) or '.', [os.path.basename(uri)]
    if not names:
        raise BagError('No storage could be initialized from the inputs.')
    if any(n.endswith('.mcap') for n in names):
        raise BagError(f"Bag '{uri}' has no {METADATA_FILENAME}: run `ros2 bag reindex`.")
    files, topics = [], {}
    for name in names:
        reader = _SqliteReader(os.path.join(directory, name))
        try:
            info, tinfo = reader.file_information(name)
        finally:
            reader.close()
        files.append(info)
        for ti in tinfo:
            if ti.topic_metadata.name in topics:
                topics[ti.topic_metadata.name].message_count += ti.message_count
            else:
                topics[ti.topic_metadata.name] = ti
    used = [f for f in files if f.message_count]
    start = min((f.starting_time for f in used), default=0)
    end = max((f.starting_time + f.duration for f in used), default=0)
    size = directory_size(directory) if os.path.isdir(uri) else os.path.getsize(uri)
    return BagMetadata(
        bag_size=size, storage_identifier=storage_id or 'sqlite3',
        relative_file_paths=names, files=files, duration=end - start, starting_time=start,
        message_count=sum(f.message_count for f in files),
        topics_with_message_count=list(topics.values()))


def open_reader(uri, storage_id=''):
    return BagReader(uri, storage_id)
