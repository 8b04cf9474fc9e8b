"""rosbag2_py._reader: SequentialReader."""
from labkit.bag.storage import STORAGE_IDS, BagReader


class SequentialReader:
    def __init__(self):
        self._bag = None
        self._iter = None
        self._next = None
        self._filter = None
        self._start = None

    def open(self, storage_options, converter_options=None):
        self._close()
        self._bag = BagReader(storage_options.uri, storage_options.storage_id)
        self._restart()

    def _restart(self):
        self._iter = self._bag.messages(self._filter, self._start)
        self._next = next(self._iter, None)

    def _require(self):
        if self._bag is None:
            raise RuntimeError('Bag is not open. Call open() before reading.')

    def get_all_topics_and_types(self):
        self._require()
        return self._bag.topics()

    def get_metadata(self):
        from labkit.bag.rosbag2_py._storage import BagMetadata
        self._require()
        return BagMetadata._wrap(self._bag.metadata)

    def has_next(self):
        self._require()
        return self._next is not None

    def read_next(self):
        """(topic name, serialized bytes, timestamp in ns), in time order."""
        self._require()
        if self._next is None:
            raise RuntimeError('Bag is at end. No next message.')
        current, self._next = self._next, next(self._iter, None)
        return current

    def set_filter(self, storage_filter):
        self._require()
        self._filter = list(storage_filter.topics) or None
        self._restart()

    def reset_filter(self):
        self._require()
        self._filter = None
        self._restart()

    def seek(self, timestamp):
        self._require()
        self._start = int(timestamp)
        self._restart()

    # Humble's SequentialReader has no close() (Jazzy added it): the file is let go when
    # the reader is (`del reader`), or when open() is called again
    def _close(self):
        if self._bag is not None:
            self._bag.close()
            self._bag = None

    def __del__(self):
        try:
            self._close()
        except Exception:
            pass


def get_registered_readers():
    return set(STORAGE_IDS)
