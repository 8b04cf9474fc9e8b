"""rosbag2_py._writer: SequentialWriter (write-through unless StorageOptions.max_cache_size;
metadata.yaml when closed)."""
import threading
import weakref

from labkit.bag.storage import STORAGE_IDS, BagWriter


class SequentialWriter:
    def __init__(self):
        self._bag = None
        self._lock = threading.Lock()

    def open(self, storage_options, converter_options=None):
        with self._lock:
            if self._bag is not None:
                self._bag.close()
            self._bag = BagWriter(storage_options.uri, storage_options.storage_id,
                                  storage_options.max_bagfile_size,
                                  storage_options.max_bagfile_duration,
                                  storage_options.max_cache_size)
        self._flush_on_shutdown()

    def _flush_on_shutdown(self):
        # A real process closes the writer in its destructor when it exits; a labkit
        # process is a thread, so commit and write metadata when its rclpy shuts down.
        try:
            from labkit.rclpy import get_default_context
            context = get_default_context()
        except Exception:
            return
        if context is None or not context.ok():
            return
        ref = weakref.ref(self)

        def flush():
            writer = ref()
            if writer is not None:
                writer._flush()
        try:
            context.on_shutdown(flush)
        except Exception:
            pass

    def _flush(self):
        with self._lock:
            if self._bag is not None and not self._bag.closed:
                self._bag.flush()

    def _require(self):
        if self._bag is None or self._bag.closed:
            raise RuntimeError('Bag is not open. Call open() before writing.')
        return self._bag

    def create_topic(self, topic_metadata):
        with self._lock:
            self._require().create_topic(topic_metadata)

    def remove_topic(self, topic_metadata):
        with self._lock:
            self._require().remove_topic(topic_metadata)

    def write(self, topic_name, message, time_stamp):
        with self._lock:
            self._require().write(topic_name, message, time_stamp)

    # Humble's SequentialWriter has no close() (Jazzy added it): the bag is finished
    # (metadata.yaml written) when the writer is let go (`del writer`) or opened again
    def _close(self):
        with self._lock:
            if self._bag is not None:
                self._bag.close()

    def __del__(self):
        try:
            if self._bag is not None:
                self._bag.close()
        except Exception:
            pass


def get_registered_writers():
    return set(STORAGE_IDS)


def get_registered_serializers():
    return {'cdr_converter'}


def get_registered_compressors():
    return set()
