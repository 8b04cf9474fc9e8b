"""rosbag2_py._storage: the option and metadata structs (Humble's pybind names and defaults)."""
from labkit.bag.metadata import (  # noqa: F401  (re-exported as rosbag2_py's own)
    BagMetadata, FileInformation, TopicInformation, TopicMetadata)
from labkit.bag.storage import DEFAULT_STORAGE_ID


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
