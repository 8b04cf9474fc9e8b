"""`import rosbag2_py` on labkit (the import hook aliases it here)."""
from labkit.bag.rosbag2_py._info import Info
from labkit.bag.rosbag2_py._reader import SequentialReader, get_registered_readers
from labkit.bag.rosbag2_py._storage import (
    BagMetadata, ConverterOptions, FileInformation, StorageFilter, StorageOptions,
    TopicInformation, TopicMetadata, get_default_storage_id)
from labkit.bag.rosbag2_py._writer import (
    SequentialWriter, get_registered_compressors, get_registered_serializers,
    get_registered_writers)

__all__ = [
    'BagMetadata', 'ConverterOptions', 'FileInformation', 'Info', 'SequentialReader',
    'SequentialWriter', 'StorageFilter', 'StorageOptions', 'TopicInformation', 'TopicMetadata',
    'get_default_storage_id', 'get_registered_compressors', 'get_registered_readers',
    'get_registered_serializers', 'get_registered_writers',
]
