"""rclpy.service.Service: requests queue up; the callback's response goes back to the client."""
from collections import deque
import itertools

from labkit.rclpy._entity import Handle, ReadyEntity
from labkit.rclpy import _msgs


class RequestId:
    """rmw_request_id_t: which client (writer_guid) and which request (sequence_number)."""

    __slots__ = ('writer_guid', 'sequence_number')

    def __init__(self, writer_guid, sequence_number):
        self.writer_guid = writer_guid
        self.sequence_number = sequence_number


class RequestHeader:
    """rmw_service_info_t, as rclpy's service_take_request gives it."""

    __slots__ = ('request_id', 'source_timestamp', 'received_timestamp', '_reply')

    def __init__(self, request_id, reply, stamp=0):
        self.request_id = request_id
        self.source_timestamp = stamp
        self.received_timestamp = stamp
        self._reply = reply


class Service(ReadyEntity):
    _kind = 'service'

    def __init__(self, service_impl, srv_type, srv_name, callback, callback_group, qos_profile):
        self.__service = service_impl
        self._endpoint = service_impl
        self.srv_type = srv_type
        self.srv_name = srv_name
        self.callback = callback
        self.callback_group = callback_group
        self.qos_profile = qos_profile
        self._handle = Handle(self)
        self._requests = deque()
        self._executor_event = False

    def _deliver(self, request_and_header):
        self._requests.append(request_and_header)
        if not self._queued:
            self._signal()

    def _has_work(self):
        return bool(self._requests)

    def _take(self):
        if not self._requests:
            from labkit.rclpy.subscription import _NOTHING
            return _NOTHING
        item = self._requests.popleft()
        if self._requests:
            self._signal()
        return item

    def _callback_and_args(self, request_and_header):
        request, header = request_and_header
        return self.callback, (request, self.srv_type.Response())

    def send_response(self, response, header):
        if not isinstance(response, self.srv_type.Response):
            raise TypeError('Expected {}, got {}'.format(self.srv_type.Response, type(response)))
        with self._handle:
            if header._reply is not None:
                header._reply(header, _msgs.copy_message(response))

    @property
    def handle(self):
        return self._handle

    @property
    def service_name(self):
        return self._endpoint.name

    def destroy(self):
        if self._node is not None:
            self._node.destroy_service(self)

    def _destroy(self):
        if not self._destroyed:
            self._destroyed = True
            self._requests.clear()
            from labkit.graph.registry import GRAPH
            GRAPH.remove(self._endpoint)


_sequence = itertools.count(1)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
