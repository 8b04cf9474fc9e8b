"""rosbag2_py._info: Info().read_metadata(uri, storage_id) -> BagMetadata.

str(metadata) is what `ros2 bag info` prints.
"""
from labkit.bag.rosbag2_py._storage import BagMetadata
from labkit.bag.storage import info_metadata


class Info:
    def read_metadata(self, uri, storage_id=''):
        return BagMetadata._wrap(info_metadata(uri, storage_id))
