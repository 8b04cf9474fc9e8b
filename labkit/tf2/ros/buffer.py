"""tf2_ros.Buffer: the core plus waiting (timeouts), futures and the tf2_frames service."""
import threading

from labkit.graph import world
from labkit.interfaces import get_type
from labkit.rclpy.duration import Duration
from labkit.rclpy.task import Future
from labkit.tf2.core import BufferCore, duration_ns

from .buffer_interface import BufferInterface

__all__ = ["Buffer"]


class Buffer(BufferCore, BufferInterface):
    """Stores known frames; with `node=` also answers the "tf2_frames" service."""

    def __init__(self, cache_time=None, node=None):
        BufferCore.__init__(self, cache_time)
        BufferInterface.__init__(self)
        self._new_data_callbacks = []
        self._callbacks_to_remove = []
        self._callbacks_lock = threading.RLock()
        if node is not None:
            FrameGraph = get_type("tf2_msgs/srv/FrameGraph")
            self.srv = node.create_service(FrameGraph, "tf2_frames", self._get_frames)

    def _get_frames(self, req, res):
        res.frame_yaml = self.all_frames_as_yaml()
        return res

    def set_transform(self, transform, authority):
        super().set_transform(transform, authority)
        self._call_new_data_callbacks()

    def set_transform_static(self, transform, authority):
        super().set_transform_static(transform, authority)
        self._call_new_data_callbacks()

    def _call_new_data_callbacks(self):
        with self._callbacks_lock:
            for callback in self._new_data_callbacks:
                callback()
            for callback in self._callbacks_to_remove:
                self._new_data_callbacks.remove(callback)
            self._callbacks_to_remove.clear()
        world.notify()          # a thread waiting in can_transform(timeout=...) looks again

    def _remove_callback(self, callback):
        with self._callbacks_lock:
            self._callbacks_to_remove.append(callback)

    # -- blocking API
    def lookup_transform(self, target_frame, source_frame, time, timeout=Duration()):
        """Transform that takes data from source_frame into target_frame (time 0: latest)."""
        if duration_ns(timeout):
            self.can_transform(target_frame, source_frame, time, timeout)
        # without a timeout ROS's can_transform only computes an answer it discards
        return self.lookup_transform_core(target_frame, source_frame, time)

    def lookup_transform_full(self, target_frame, target_time, source_frame, source_time,
                              fixed_frame, timeout=Duration()):
        """Time travel: source_frame at source_time into target_frame at target_time."""
        query = (target_frame, target_time, source_frame, source_time, fixed_frame)
        if duration_ns(timeout):
            self.can_transform_full(*query, timeout)
        return self.lookup_transform_full_core(*query)

    def can_transform(self, target_frame, source_frame, time, timeout=Duration(),
                      return_debug_tuple=False):
        def check():
            return self.can_transform_core(target_frame, source_frame, time)
        return self._wait(check, timeout, return_debug_tuple)

    def can_transform_full(self, target_frame, target_time, source_frame, source_time,
                           fixed_frame, timeout=Duration(), return_debug_tuple=False):
        def check():
            return self.can_transform_full_core(target_frame, target_time, source_frame,
                                                source_time, fixed_frame)
        return self._wait(check, timeout, return_debug_tuple)

    def _wait(self, check, timeout, return_debug_tuple):
        timeout_ns = duration_ns(timeout)
        if timeout_ns > 0:
            # ROS polls every 20 ms on the system clock; one world wait is the same
            # without the polling (other threads, e.g. a spin thread, keep running)
            world.wait(lambda: check()[0], timeout_ns=timeout_ns)
        result = check()
        return result if return_debug_tuple else result[0]

    # -- async API
    async def lookup_transform_async(self, target_frame, source_frame, time):
        await self.wait_for_transform_async(target_frame, source_frame, time)
        return self.lookup_transform_core(target_frame, source_frame, time)

    async def lookup_transform_full_async(self, target_frame, target_time, source_frame,
                                          source_time, fixed_frame):
        query = (target_frame, target_time, source_frame, source_time, fixed_frame)
        await self.wait_for_transform_full_async(*query)
        return self.lookup_transform_full_core(*query)

    def wait_for_transform_async(self, target_frame, source_frame, time):
        return self._future_when(
            lambda: self.can_transform_core(target_frame, source_frame, time)[0])

    def wait_for_transform_full_async(self, target_frame, target_time, source_frame,
                                      source_time, fixed_frame):
        return self._future_when(lambda: self.can_transform_full_core(
            target_frame, target_time, source_frame, source_time, fixed_frame)[0])

    def _future_when(self, ready):
        fut = Future()
        if ready():
            fut.set_result(True)
            return fut

        def on_new_data():
            try:
                if ready() and not fut.done():
                    fut.set_result(True)
            except BaseException as exc:
                fut.set_exception(exc)

        self._new_data_callbacks.append(on_new_data)
        fut.add_done_callback(lambda _: self._remove_callback(on_new_data))
        return fut
