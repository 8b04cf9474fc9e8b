"""Bag storage: Humble's sqlite3 plugin (schema 3) and mcap plugin (mcap_file.py).

A bag is a folder `<name>/` with `<name>_0.db3` (or `.mcap`) and `metadata.yaml`.
The sqlite3 writer commits in small batches and the mcap writer closes a chunk at
least every half second, so a recording whose process dies keeps what it had written
(`ros2 bag reindex` makes it whole); metadata.yaml comes at close(). `ros2 bag record`
writes through rosbag2's message cache and a writer thread (MessageCache, BagWriter).
"""
import os
import sqlite3
import struct
import threading
import time

from labkit.bag.metadata import (
    METADATA_FILENAME, BagMetadata, FileInformation, MetadataError, TopicInformation,
    TopicMetadata, directory_size, read_metadata, write_metadata)

DEFAULT_STORAGE_ID = 'sqlite3'
STORAGE_IDS = ('sqlite3', 'mcap')
EXTENSIONS = {'sqlite3': '.db3', 'mcap': '.mcap'}
SQLITE_SCHEMA_VERSION = 3   # Humble's kDBSchemaVersion_
COMMIT_EVERY_MESSAGES = 1000
COMMIT_EVERY_SECONDS = 0.2     # wall time: what a dying kernel may lose at most
MIN_SPLIT_FILE_SIZE = {'sqlite3': 86016, 'mcap': 1024}   # each Humble plugin's minimum
CACHE_WAIT_SECONDS = 0.1       # the writer thread looks at least this often (mcap chunk age)
WAKE_AT_MESSAGES = 1000        # ... and at once when this many messages wait
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


class StorageWriteError(Exception):
    """The storage refused a write (a full disk): the C++ exception rosbag2 lets escape."""

    def __init__(self, cpp_class, what):
        super().__init__(what)
        self.cpp_class = cpp_class
        self.what = what


def _no_space(error):
    import errno
    return isinstance(error, OSError) and error.errno in (errno.ENOSPC, errno.EDQUOT)


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

    def write_many(self, rows):
        """(topic id, timestamp, data) rows from the writer thread's batch."""
        self._rows.extend((t, i, d) for i, t, d in rows)
        if len(self._rows) >= COMMIT_EVERY_MESSAGES:
            self.commit()

    def tick(self):
        if self._rows and time.monotonic() - self._last_commit >= COMMIT_EVERY_SECONDS:
            self.commit()

    def commit(self):
        rows, self._rows = self._rows, []
        if rows:
            try:
                self.conn.execute('BEGIN')
                self.conn.executemany(
                    'INSERT INTO messages (timestamp, topic_id, data) VALUES (?, ?, ?)', rows)
                self.conn.execute('COMMIT')
            except sqlite3.Error as e:
                try:
                    self.conn.execute('ROLLBACK')   # the batches before stay whole
                except sqlite3.Error:
                    pass
                raise StorageWriteError('rosbag2_storage_plugins::SqliteException',
                                        _sqlite_what(e)) from None
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
    """Humble's mcap plugin (labkit/bag/mcap_file.py): `<name>_<n>.mcap`, complete chunks as
    it goes."""

    def __init__(self, path):
        from labkit.bag.mcap_file import McapWriter
        self.path = path
        self.writer = McapWriter(path, os.environ.get('ROS_DISTRO', 'humble'))
        self.full = False


    def create_topic(self, t):
        return self.writer.add_channel(t.name, t.type, t.serialization_format,
                                       t.offered_qos_profiles)

    # Humble's mcap FileWriter does not check fwrite: on a full disk what does not fit is
    # lost without a word and recording goes on (rosbag2_storage_mcap 0.15 / mcap 0.8)
    def _quiet(self, call, *args):
        if self.full:
            return False
        try:
            call(*args)
        except OSError as e:
            if not _no_space(e):
                raise
            self.full = True
        return False

    def write(self, topic_id, timestamp, data):
        return self._quiet(self.writer.write, topic_id, timestamp, bytes(data))

    def write_many(self, rows):
        write = self.writer.write
        self._quiet(lambda: [write(t, s, d) for t, s, d in rows])

    def tick(self):
        self._quiet(self.writer.flush_if_old)

    def commit(self):
        self._quiet(self.writer.flush)

    def settle(self):
        self._quiet(self.writer.flush)

    def size(self):
        return self.writer.size()

    def close(self):
        self.full = False
        self._quiet(self.writer.close)


class _FileStats:
    """One storage file's FileInformation, kept as messages arrive."""

    def __init__(self, path):
        self.path = path
        self.start = None
        self.end = None
        self.count = 0

    def add_many(self, stamps):
        low, high = min(stamps), max(stamps)
        if self.start is None or low < self.start:
            self.start = low
        if self.end is None or high > self.end:
            self.end = high
        self.count += len(stamps)

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


class MessageCache:
    """rosbag2_cpp's message cache: callbacks push into one buffer while the writer thread
    empties the other (they swap). A buffer holding `max_bytes` or more drops what comes
    next until the swap, counting per topic; close() reports the losses as rosbag2 does.

    rosbag2 wakes its writer for every message; a Python thread woken 1000 times a second
    costs more than the writing, so the writer here sleeps until WAKE_AT_MESSAGES are
    waiting, half the cache is used, or CACHE_WAIT_SECONDS have passed."""

    def __init__(self, max_bytes):
        self.max_bytes = max_bytes
        self.cond = threading.Condition()
        self.buffer = []
        self.bytes = 0
        self.full = False
        self.flushing = False
        self.sleeping = False
        self.dropped = {}          # topic -> messages lost

    def _enough(self):
        return len(self.buffer) >= WAKE_AT_MESSAGES or 2 * self.bytes >= self.max_bytes

    def push(self, topic, data, timestamp):
        with self.cond:
            if self.full:
                self.dropped[topic] = self.dropped.get(topic, 0) + 1
            else:
                self.buffer.append((topic, data, timestamp))
                self.bytes += len(data)
                self.full = self.bytes >= self.max_bytes
            if self.sleeping and self._enough():
                self.cond.notify()

    def swap(self, timeout):
        """The writer thread's turn: everything pushed so far (waits up to `timeout` for it)."""
        with self.cond:
            if not self.flushing and not self._enough():
                self.sleeping = True
                self.cond.wait(timeout)
                self.sleeping = False
            batch, self.buffer, self.bytes, self.full = self.buffer, [], 0, False
            return batch

    def begin_flushing(self):
        with self.cond:
            self.flushing = True
            self.cond.notify()

    def log_dropped(self):
        from labkit.rclpy.logging import get_logger
        lost = {t: n for t, n in self.dropped.items() if n}
        if lost:
            text = 'Cache buffers lost messages per topic: ' + ''.join(
                f'\n\t{t}: {n}' for t, n in lost.items())
            get_logger('rosbag2_cpp').warn(f'{text}\nTotal lost: {sum(lost.values())}')


class BagWriter:
    """rosbag2_cpp's SequentialWriter: storage files, metadata.yaml at close().

    With `max_cache_size` (bytes, the recorder's --max-cache-size) writes go through a
    MessageCache to a writer thread of their own, as in rosbag2: a subscription callback
    only appends, so a slow disk or a big commit never holds up the recording. Without
    it (rosbag2_py's default, 0) each write goes straight to the file.

    max_bagfile_size (bytes) / max_bagfile_duration (s) split a bag into
    `<name>_0.db3`, `<name>_1.db3`, ... like Humble.
    """

    def __init__(self, uri, storage_id='', max_bagfile_size=0, max_bagfile_duration=0,
                 max_cache_size=0):
        storage_id = storage_id or DEFAULT_STORAGE_ID
        if storage_id not in STORAGE_IDS:
            raise BagError("No storage could be initialized. Abort")
        minimum = MIN_SPLIT_FILE_SIZE[storage_id]
        if max_bagfile_size and max_bagfile_size < minimum:
            raise BagError('Invalid bag splitting size given. Please provide a value greater '
                           f'than {minimum}. Specified value of {max_bagfile_size}')
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
        self._lock = threading.RLock()      # the storage file: writer thread vs create_topic
        self._open_file()
        self.cache = None
        if max_cache_size > 0:
            self.cache = MessageCache(max_cache_size)
            self._consumer = threading.Thread(target=self._consume, daemon=True,
                                              name=f'rosbag2 writer {self.base}')
            self._consumer.start()

    def _open_file(self):
        relative = f'{self.base}_{len(self.files)}{EXTENSIONS[self.storage_id]}'
        if self.storage_id == 'sqlite3':
            self.file = _SqliteFile(os.path.join(self.uri, relative))
            storage_log(f"Opened database '{_shown(os.path.join(self.uri, relative))}' "
                        "for READ_WRITE.")
        else:  # (Humble's mcap plugin logs no line when it opens a file)
            self.file = _McapFile(os.path.join(self.uri, relative))
        self.files.append(_FileStats(relative))
        for entry in self.topics.values():  # every file describes every topic
            entry[0] = self.file.create_topic(entry[1].topic_metadata)

    @property
    def relative_path(self):
        return self.files[-1].path

    def create_topic(self, topic):
        with self._lock:
            if topic.name in self.topics:
                return
            self.topics[topic.name] = [self.file.create_topic(topic),
                                       TopicInformation(topic, 0)]
            self._refresh_metadata()

    def remove_topic(self, topic):
        with self._lock:
            self.topics.pop(topic.name, None)

    def _should_split(self, timestamp):
        current = self.files[-1]
        if self.max_size and self.file.size() >= self.max_size:
            return True
        return bool(self.max_duration_ns and current.count and
                    timestamp - current.start > self.max_duration_ns)

    def split(self):
        with self._lock:
            self.file.close()
            self._open_file()
            self._refresh_metadata()

    def write(self, topic_name, data, timestamp):
        if self.closed:
            raise BagError('Bag is not open. Call open() before writing.')
        if topic_name not in self.topics:
            raise BagError(f"Failed to write on topic '{topic_name}'. "
                           'Call create_topic() before first write.')
        if self.cache is not None:
            self.cache.push(topic_name, data, int(timestamp))
        else:
            with self._lock:
                try:
                    self._write_now(topic_name, data, int(timestamp))
                except StorageWriteError as e:
                    self._abort(e)

    def _abort(self, error):
        """A write the storage refused escapes rosbag2 (a C++ exception nobody catches):
        std::terminate, the process aborts; the bag keeps the batches committed before
        (metadata.yaml is not written: no destructor runs)."""
        self.failed = True
        from labkit.process import Aborted, abort_current
        abort_current(f"terminate called after throwing an instance of '{error.cpp_class}'\n"
                      f"  what():  {error.what}\n")
        raise Aborted(error.what)

    def _write_now(self, topic_name, data, timestamp):
        entry = self.topics.get(topic_name)
        if entry is None:             # removed while its messages waited in the cache
            return
        if (self.max_size or self.max_duration_ns) and self._should_split(timestamp):
            self.split()
            entry = self.topics[topic_name]
        committed = self.file.write(entry[0], timestamp, data)
        entry[1].message_count += 1
        self.files[-1].add(timestamp)
        if committed and time.monotonic() - self._metadata_written >= METADATA_EVERY_SECONDS:
            self._refresh_metadata()

    def _write_all(self, batch):
        """What the cache handed over: at once, or one by one when a split may come between."""
        if self.max_size or self.max_duration_ns:
            for topic_name, data, timestamp in batch:
                self._write_now(topic_name, data, timestamp)
        elif batch:
            self._write_batch(batch)

    def _write_batch(self, batch):
        """_write_now for a whole batch, when no split can come in between."""
        topics, rows, stamps = self.topics, [], []
        for topic_name, data, timestamp in batch:
            entry = topics.get(topic_name)
            if entry is not None:
                entry[1].message_count += 1
                rows.append((entry[0], timestamp, data))
                stamps.append(timestamp)
        if rows:
            self.file.write_many(rows)
            self.files[-1].add_many(stamps)
            if time.monotonic() - self._metadata_written >= METADATA_EVERY_SECONDS:
                self._refresh_metadata()

    def _consume(self):
        """The writer thread (rosbag2_cpp's CacheConsumer): swap, write, repeat; the last
        round after close() began empties the cache."""
        from labkit.process import Aborted
        cache = self.cache
        last = False
        while True:
            batch = cache.swap(CACHE_WAIT_SECONDS)
            with self._lock:
                try:
                    self._write_all(batch)
                    self.file.tick()   # a sqlite3 batch or an mcap chunk that waited too long
                except StorageWriteError as e:
                    try:
                        self._abort(e)
                    except Aborted:
                        return
            if last:
                return
            last = cache.flushing

    def flush(self):
        """Everything written so far on disk (the cache's waiting messages too)."""
        with self._lock:
            if self.cache is not None:
                self._write_all(self.cache.swap(0))
            getattr(self.file, 'settle', self.file.commit)()
            self._refresh_metadata()

    def _refresh_metadata(self):
        # rosbag2 writes metadata.yaml once, at close. A writer that is never closed (a
        # killed kernel) would leave no metadata at all, so committed batches refresh it
        # now and then; a reader that finds more rows than it describes reindexes.
        if self.storage_id == 'sqlite3':
            try:
                write_metadata(self.uri, self.metadata())
            except OSError as e:       # labkit's own extra file: a full disk is the
                if not _no_space(e):   # storage's to report
                    raise
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
        if getattr(self, 'failed', False):     # aborted: nothing more reaches the disk
            try:
                self.file.conn.close()
            except Exception:
                pass
            return
        if self.cache is not None:
            from labkit.rclpy.logging import get_logger
            get_logger('rosbag2_cpp').info(
                'Writing remaining messages from cache to the bag. It may take a while')
            self.cache.begin_flushing()
            self._consumer.join()
            self.cache.log_dropped()
        with self._lock:
            try:
                self.file.close()
            except StorageWriteError as e:
                self._abort(e)
            try:
                write_metadata(self.uri, self.metadata())
            except OSError as e:       # yaml-cpp's ofstream does not check either
                if not _no_space(e):
                    raise


def open_writer(uri, storage_id=''):
    return BagWriter(uri, storage_id)


# --------------------------------------------------------------------------- reading

def _file_reader(path, storage_id, listed=False):
    """The storage plugin's reader for one file; a file it cannot open: rosbag2's line.

    `listed`: the file is named by metadata.yaml (SequentialReader::load_current_file):
    Humble's StorageFactory logs why the plugin could not open it, then the reader aborts."""
    if storage_id == 'mcap' or path.endswith('.mcap'):
        return _McapReader(path)
    try:
        return _SqliteReader(path)
    except sqlite3.Error as e:
        if not listed:
            raise BagError('No storage could be initialized from the inputs.') from None
        from labkit.rclpy.logging import get_logger
        log = get_logger('rosbag2_storage')
        log.error(f"Could not open '{_shown(path)}' with 'sqlite3'. Error: Failed to setup storage. "
                  f"Error: {_sqlite_what(e)}")
        log.error("Could not load/open plugin with storage id 'sqlite3'")
        raise BagError('No storage could be initialized. Abort') from None


def _shown(path):
    """A bag file's path as Humble on Ubuntu prints it ('/' on every OS, /root/...)."""
    from labkit.ament import files
    return files.display(path)


# sqlite3_errstr() of the primary result codes a broken bag file gives
_SQLITE_ERRSTR = {5: 'database is locked', 8: 'attempt to write a readonly database',
                  10: 'disk I/O error', 11: 'database disk image is malformed',
                  13: 'database or disk is full', 14: 'unable to open database file',
                  26: 'file is not a database'}


def _sqlite_what(error):
    """SqliteStatementWrapper::execute_and_reset's text for a failed step (the first one
    Humble's SqliteWrapper runs on open is `PRAGMA schema_version;`; extended result codes
    are switched on only after it)."""
    code = getattr(error, 'sqlite_errorcode', None)
    if code is None:
        return f'SQL error: {error}'
    code &= 0xff
    return (f'Error when processing SQL statement. SQLite error ({code}): '
            f'{_SQLITE_ERRSTR.get(code, str(error))}')


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
                self.conn.execute('PRAGMA schema_version;').fetchall()   # as SqliteWrapper
                rows = self.conn.execute(query).fetchall()
                break
            except sqlite3.OperationalError:
                self.conn.close()
                if mode == 'rw':
                    raise
            except sqlite3.Error:
                self.conn.close()
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
    """Every whole record of an `.mcap` file (one cut short by a kill too), in time order."""

    def __init__(self, path):
        from labkit.bag.mcap_file import scan
        try:
            self.contents = scan(path)
        except (OSError, ValueError, struct.error):
            raise BagError('No storage could be initialized from the inputs.') from None
        c = self.contents
        self.topics = {cid: TopicMetadata(topic, c.type_of(cid), encoding,
                                          metadata.get('offered_qos_profiles', ''))
                       for cid, (_, topic, encoding, metadata) in c.channels.items()}

    def messages(self, topics=None, start=None):
        names = {cid: t.name for cid, t in self.topics.items()
                 if topics is None or t.name in topics}
        chosen = [(stamp, n, cid, data) for n, (cid, stamp, data)
                  in enumerate(self.contents.messages)
                  if cid in names and (start is None or stamp >= start)]
        chosen.sort(key=lambda m: (m[0], m[1]))
        for stamp, _, cid, data in chosen:
            yield names[cid], data, stamp

    def file_information(self, relative):
        stamps = [m[1] for m in self.contents.messages if m[0] in self.topics]
        counts = {}
        for cid, _, _ in self.contents.messages:
            counts[cid] = counts.get(cid, 0) + 1
        info = FileInformation(relative, min(stamps, default=0),
                               (max(stamps) - min(stamps)) if stamps else 0, len(stamps))
        return info, [TopicInformation(t, counts.get(cid, 0)) for cid, t in self.topics.items()]

    def close(self):
        pass


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
        paths = [os.path.join(directory, p) for p in self.metadata.relative_file_paths] \
            if os.path.isdir(uri) else [uri]
        listed = os.path.isdir(uri) and os.path.exists(os.path.join(uri, METADATA_FILENAME))
        self.files = [_file_reader(p, self.storage_id, listed) for p in paths]
        if self.metadata.relative_file_paths and self.storage_id == 'sqlite3':
            storage_log(f"Opened database '{_shown(paths[0])}' for READ_ONLY.")

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


def storage_files(directory):
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
        except sqlite3.Error as e:
            if (getattr(e, 'sqlite_errorcode', 0) & 0xff) in (11, 26):
                return False  # a broken file: opening it says so (metadata.yaml is whole)
            return True  # a hot journal: let the reindexing reader roll it back
        if last > f.message_count:
            return True
    return False


def read_bag_metadata(uri, storage_id=''):
    """metadata.yaml if the bag has one, else what `ros2 bag reindex` would rebuild."""
    uri = os.fspath(uri)
    if os.path.isdir(uri) and os.path.exists(os.path.join(uri, METADATA_FILENAME)):
        try:
            m = read_metadata(uri)
        except MetadataError as e:
            raise BagError(str(e)) from None
        m.bag_size = directory_size(uri)
        if not _stale(uri, m):
            return m
    if os.path.isdir(uri):
        directory, names = uri, storage_files(uri)
    else:
        directory, names = os.path.dirname(uri) or '.', [os.path.basename(uri)]
    if not names:
        raise BagError('No storage could be initialized from the inputs.')
    files, topics = [], {}
    for name in names:
        reader = _file_reader(os.path.join(directory, name), '')
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
    found = 'mcap' if names[0].endswith('.mcap') else 'sqlite3'
    return BagMetadata(
        bag_size=size, storage_identifier=storage_id or found,
        relative_file_paths=names, files=files, duration=end - start, starting_time=start,
        message_count=sum(f.message_count for f in files),
        topics_with_message_count=list(topics.values()))


def info_metadata(uri, storage_id=''):
    """rosbag2_cpp::Info::read_metadata (`ros2 bag info`, rosbag2_py.Info): metadata.yaml,
    or a single storage file asked directly; a folder without metadata.yaml is refused
    (`ros2 bag reindex` makes one)."""
    uri = os.fspath(uri)
    if not os.path.exists(uri):
        raise BagError(f'Bag path {uri} does not exist.')
    if os.path.isdir(uri) and not os.path.exists(os.path.join(uri, METADATA_FILENAME)):
        raise BagError(f'Could not find metadata in bag directory {uri}')
    if not os.path.isdir(uri):
        try:
            return read_bag_metadata(uri, storage_id)
        except BagError:
            raise BagError(f'No plugin detected that could open file {uri}') from None
    return read_bag_metadata(uri, storage_id)


def open_reader(uri, storage_id=''):
    return BagReader(uri, storage_id)
