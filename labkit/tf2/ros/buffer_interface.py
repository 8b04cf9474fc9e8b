"""tf2_ros.buffer_interface: `transform()` through registered per-type functions."""
from copy import deepcopy

from labkit.rclpy.duration import Duration

__all__ = ["BufferInterface", "Stamped", "TypeException", "NotImplementedException",
           "TransformRegistration", "ConvertRegistration", "convert"]


class BufferInterface:
    """What Buffer offers beyond the core: transform an object into another frame."""

    def __init__(self):
        self.registration = TransformRegistration()

    def transform(self, object_stamped, target_frame, timeout=Duration(), new_type=None):
        do_transform = self.registration.get(type(object_stamped))
        res = do_transform(object_stamped, self.lookup_transform(
            target_frame, object_stamped.header.frame_id, object_stamped.header.stamp, timeout))
        return res if new_type is None else convert(res, new_type)

    def transform_full(self, object_stamped, target_frame, target_time, fixed_frame,
                       timeout=Duration(), new_type=None):
        do_transform = self.registration.get(type(object_stamped))
        res = do_transform(object_stamped, self.lookup_transform_full(
            target_frame, target_time, object_stamped.header.frame_id,
            object_stamped.header.stamp, fixed_frame, timeout))
        return res if new_type is None else convert(res, new_type)

    def lookup_transform(self, target_frame, source_frame, time, timeout=Duration()):
        raise NotImplementedException()

    def lookup_transform_full(self, target_frame, target_time, source_frame, source_time,
                              fixed_frame, timeout=Duration()):
        raise NotImplementedException()

    def can_transform(self, target_frame, source_frame, time, timeout=Duration()):
        raise NotImplementedException()

    def can_transform_full(self, target_frame, target_time, source_frame, source_time,
                           fixed_frame, timeout=Duration()):
        raise NotImplementedException()


def Stamped(obj, stamp, frame_id):
    from labkit.interfaces import get_type
    obj.header = get_type("std_msgs/msg/Header")(frame_id=frame_id, stamp=stamp)
    return obj


class TypeException(Exception):
    def __init__(self, errstr):
        super().__init__(errstr)
        self.errstr = errstr


class NotImplementedException(Exception):
    def __init__(self):
        super().__init__("CanTransform or LookupTransform not implemented")
        self.errstr = "CanTransform or LookupTransform not implemented"


class TransformRegistration:
    """type -> do_transform(obj, transform_stamped); shared by every instance, as in ROS."""
    _type_map = {}

    def print_me(self):
        print(TransformRegistration._type_map)

    def add(self, key, callback):
        TransformRegistration._type_map[key] = callback

    def get(self, key):
        if key not in TransformRegistration._type_map:
            raise TypeException("Type %s is not loaded or supported" % str(key))
        return TransformRegistration._type_map[key]


class ConvertRegistration:
    _to_msg_map = {}
    _from_msg_map = {}
    _convert_map = {}

    def add_from_msg(self, key, callback):
        ConvertRegistration._from_msg_map[key] = callback

    def add_to_msg(self, key, callback):
        ConvertRegistration._to_msg_map[key] = callback

    def add_convert(self, key, callback):
        ConvertRegistration._convert_map[key] = callback

    def _get(self, table, key):
        if key not in table:
            raise TypeException("Type %s is not loaded or supported" % str(key))
        return table[key]

    def get_from_msg(self, key):
        return self._get(ConvertRegistration._from_msg_map, key)

    def get_to_msg(self, key):
        return self._get(ConvertRegistration._to_msg_map, key)

    def get_convert(self, key):
        return self._get(ConvertRegistration._convert_map, key)


def convert(a, b_type):
    c = ConvertRegistration()
    try:
        return c.get_convert((type(a), b_type))(a)
    except TypeException:
        if type(a) == b_type:
            return deepcopy(a)
        return c.get_from_msg(b_type)(c.get_to_msg(type(a))(a))

