"""rosbag2_py._info: Info().read_metadata(uri, storage_id) -> BagMetadata (str() is `ros2 bag info`)."""
from labkit.bag.storage import read_bag_metadata


class Info:
    def read_metadata(self, uri, storage_id=''):
        return read_bag_metadata(uri, storage_id)
