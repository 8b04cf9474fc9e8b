"""rosbag2_py._storage: the option and metadata structs (Humble's pybind names and defaults)."""
from labkit.bag import metadata as _m
from labkit.bag.metadata import TopicInformation, TopicMetadata  # noqa: F401 (re-exported)
from labkit.bag.storage import DEFAULT_STORAGE_ID


def _duration(ns):
    from labkit.rclpy.duration import Duration
    return Duration(nanoseconds=ns)


def _time(ns):
    from labkit.rclpy.time import Time
    return Time(nanoseconds=ns)


class FileInformation(_m.FileInformation):
    """Times are rclpy Time/Duration in the Python API (plain ns inside labkit)."""

    def __init__(self, path, starting_time=None, duration=None, message_count=0):
        super().__init__(path, _ns(starting_time), _ns(duration), message_count)


def _ns(value):
    return 0 if value is None else int(getattr(value, 'nanoseconds', value))


class BagMetadata:
    """rosbag2_py.BagMetadata: repr() is `ros2 bag info`'s text; times are rclpy objects."""

    def __init__(self, version=6, bag_size=0, storage_identifier='', relative_file_paths=(),
                 files=(), duration=None, starting_time=None, message_count=0,
                 topics_with_message_count=(), compression_format='', compression_mode=''):
        self._m = _m.BagMetadata(
            version=version, bag_size=bag_size, storage_identifier=storage_identifier,
            relative_file_paths=list(relative_file_paths), files=list(files),
            duration=_ns(duration), starting_time=_ns(starting_time),
            message_count=message_count,
            topics_with_message_count=list(topics_with_message_count),
            compression_format=compression_format, compression_mode=compression_mode)

    @classmethod
    def _wrap(cls, metadata):
        self = cls.__new__(cls)
        self._m = metadata
        return self

    def __getattr__(self, name):
        return getattr(self._m, name)

    def __setattr__(self, name, value):
        if name == '_m':
            object.__setattr__(self, name, value)
        elif name in ('duration', 'starting_time'):
            setattr(self._m, name, _ns(value))
        else:
            setattr(self._m, name, value)

    @property
    def duration(self):
        return _duration(self._m.duration)

    @property
    def starting_time(self):
        return _time(self._m.starting_time)

    def __repr__(self):
        return _m.format_bag_metadata(self._m)


class ConverterOptions:
    def __init__(self, input_serialization_format='', output_serialization_format=''):
        self.input_serialization_format = input_serialization_format
        self.output_serialization_format = output_serialization_format

    def __repr__(self):
        return (f'ConverterOptions({self.input_serialization_format!r}, '
                f'{self.output_serialization_format!r})')


class StorageOptions:
    def __init__(self, uri, storage_id='', max_bagfile_size=0, max_bagfile_duration=0,
                 max_cache_size=0, storage_preset_profile='', storage_config_uri='',
                 snapshot_mode=False):
        self.uri = uri
        self.storage_id = storage_id
        self.max_bagfile_size = max_bagfile_size
        self.max_bagfile_duration = max_bagfile_duration
        self.max_cache_size = max_cache_size
        self.storage_preset_profile = storage_preset_profile
        self.storage_config_uri = storage_config_uri
        self.snapshot_mode = snapshot_mode

    def __repr__(self):
        return f'StorageOptions(uri={self.uri!r}, storage_id={self.storage_id!r})'


class StorageFilter:
    def __init__(self, topics=None):
        self.topics = list(topics or [])


def get_default_storage_id():
    return DEFAULT_STORAGE_ID
