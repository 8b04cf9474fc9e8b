"""rclpy.client.Client: requests go straight to the server's queue; responses come back."""
from collections import deque
import itertools
import threading

from labkit.graph import world
from labkit.graph.registry import GRAPH
from labkit.rclpy._entity import Handle, ReadyEntity
from labkit.rclpy import _msgs
from labkit.rclpy.service import RequestHeader, RequestId
from labkit.rclpy.task import Future


class Client(ReadyEntity):
    _kind = 'client'

    def __init__(self, context, client_impl, srv_type, srv_name, qos_profile, callback_group):
        self.context = context
        self.__client = client_impl
        self._endpoint = client_impl
        self.srv_type = srv_type
        self.srv_name = srv_name
        self.qos_profile = qos_profile
        self._pending_requests = {}
        self.callback_group = callback_group
        self._lock = threading.Lock()
        self._handle = Handle(self)
        self._responses = deque()
        self._sequence = itertools.count(1)
        self._executor_event = False

    # -- the wire ------------------------------------------------------------
    def _send(self, request):
        seq = next(self._sequence)
        node = self._endpoint.node
        server = GRAPH.find_service(self._endpoint.name, node.domain_id)
        if server is not None:         # like DDS: a request with no server is lost
            header = RequestHeader(RequestId(self._endpoint.gid, seq), self._reply,
                                   world.system_ns())
            server.sink((_msgs.copy_message(request), header))
        return seq

    def _reply(self, header, response):
        if self._destroyed:
            return
        self._responses.append((header, response))
        if not self._queued:
            self._signal()

    def _has_work(self):
        return bool(self._responses)

    def _take(self):
        if not self._responses:
            from labkit.rclpy.subscription import _NOTHING
            return _NOTHING
        item = self._responses.popleft()
        if self._responses:
            self._signal()
        return item

    def _complete(self, executor, header_and_response):
        header, response = header_and_response
        try:
            future = self.get_pending_request(header.request_id.sequence_number)
        except KeyError:
            return                      # the request was removed
        future._set_executor(executor)
        future.set_result(response)

    # -- API -----------------------------------------------------------------
    def call(self, request):
        """Make a service request and wait (a world wait point) for the result."""
        if not isinstance(request, self.srv_type.Request):
            raise TypeError()
        future = self.call_async(request)
        if not future.done():
            from labkit.rclpy import _wait
            _wait.wait(future.done)
        exception = future.exception()
        if exception is not None:
            raise exception
        return future.result()

    def remove_pending_request(self, future):
        with self._lock:
            for seq, req_future in list(self._pending_requests.items()):
                if future is req_future:
                    del self._pending_requests[seq]
                    break

    def call_async(self, request):
        if not isinstance(request, self.srv_type.Request):
            raise TypeError()
        with self._lock:
            with self._handle:
                sequence_number = self._send(request)
            if sequence_number in self._pending_requests:
                raise RuntimeError(
                    'Sequence (%r) conflicts with pending request' % sequence_number)
            future = Future()
            self._pending_requests[sequence_number] = future
            future.add_done_callback(self.remove_pending_request)
        return future

    def get_pending_request(self, sequence_number):
        with self._lock:
            return self._pending_requests[sequence_number]

    def service_is_ready(self):
        with self._handle:
            node = self._endpoint.node
            return GRAPH.find_service(self._endpoint.name, node.domain_id) is not None

    def wait_for_service(self, timeout_sec=None):
        # Humble polls every 0.25 s; keep its rhythm (it shows in virtual-time stamps).
        sleep_time = 0.25
        if timeout_sec is None:
            timeout_sec = float('inf')
        while self.context.ok() and not self.service_is_ready() and timeout_sec > 0.0:
            world.wait(lambda: not self.context.ok(), sleep_time)
            timeout_sec -= sleep_time
        return self.service_is_ready()

    @property
    def handle(self):
        return self._handle

    @property
    def service_name(self):
        return self._endpoint.name

    def destroy(self):
        if self._node is not None:
            self._node.destroy_client(self)

    def _destroy(self):
        if not self._destroyed:
            self._destroyed = True
            GRAPH.remove(self._endpoint)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
