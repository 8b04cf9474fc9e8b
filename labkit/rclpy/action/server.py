"""rclpy.action.server: ActionServer and ServerGoalHandle (Humble behaviour).

Built on the public Node API: the three hidden services and two hidden topics
that rcl_action would create (`<action>/_action/{send_goal,cancel_goal,
get_result}`, `<action>/_action/{feedback,status}`), so the graph, `ros2
action` and any ActionClient see exactly what they see in ROS 2. The goal
state machine and the cancel-request rules are rcl_action's.
"""
from enum import Enum, IntEnum
import inspect
import threading
import traceback

from labkit.rclpy.action._common import action_names, call_maybe_coroutine, debug, msg_type

__all__ = ['ActionServer', 'CancelResponse', 'GoalEvent', 'GoalResponse', 'ServerGoalHandle']


class GoalResponse(Enum):
    """Possible goal responses."""

    REJECT = 1
    ACCEPT = 2


class CancelResponse(Enum):
    """Possible cancel responses."""

    REJECT = 1
    ACCEPT = 2


class GoalEvent(IntEnum):
    """rcl_action goal events (rclpy exposes them as _rclpy.GoalEvent)."""

    EXECUTE = 0
    CANCEL_GOAL = 1
    SUCCEED = 2
    ABORT = 3
    CANCELED = 4


try:  # the core may provide rclpy's RCLError; otherwise ours stands in
    from labkit.rclpy.exceptions import RCLError  # type: ignore[attr-defined]
except ImportError:  # pragma: no cover - depends on the core's progress
    class RCLError(RuntimeError):
        """Error raised by the rcl layer."""

# GoalStatus codes (action_msgs/msg/GoalStatus constants).
STATUS_UNKNOWN, STATUS_ACCEPTED, STATUS_EXECUTING, STATUS_CANCELING = 0, 1, 2, 3
STATUS_SUCCEEDED, STATUS_CANCELED, STATUS_ABORTED = 4, 5, 6
_STATE_NAMES = ('UNKNOWN', 'ACCEPTED', 'EXECUTING', 'CANCELING', 'SUCCEEDED', 'CANCELED',
                'ABORTED')
_ACTIVE = (STATUS_ACCEPTED, STATUS_EXECUTING, STATUS_CANCELING)
# rcl_action's goal state machine: (state, event) -> new state.
_TRANSITIONS = {
    (STATUS_ACCEPTED, GoalEvent.EXECUTE): STATUS_EXECUTING,
    (STATUS_ACCEPTED, GoalEvent.CANCEL_GOAL): STATUS_CANCELING,
    (STATUS_EXECUTING, GoalEvent.CANCEL_GOAL): STATUS_CANCELING,
    (STATUS_EXECUTING, GoalEvent.SUCCEED): STATUS_SUCCEEDED,
    (STATUS_EXECUTING, GoalEvent.ABORT): STATUS_ABORTED,
    (STATUS_CANCELING, GoalEvent.SUCCEED): STATUS_SUCCEEDED,
    (STATUS_CANCELING, GoalEvent.ABORT): STATUS_ABORTED,
    (STATUS_CANCELING, GoalEvent.CANCELED): STATUS_CANCELED,
}


def _stamp_ns(stamp):
    return stamp.sec * 1_000_000_000 + stamp.nanosec


class ServerGoalHandle:
    """Goal handle for working with Action Servers."""

    def __init__(self, action_server, goal_info, goal_request):
        self._action_server = action_server
        self._goal_info = goal_info
        self._goal_request = goal_request
        self._state = STATUS_ACCEPTED
        self._destroyed = False
        self._lock = threading.Lock()

    def __eq__(self, other):
        return self.goal_id == other.goal_id

    def __ne__(self, other):
        return self.goal_id != other.goal_id

    __hash__ = object.__hash__

    @property
    def request(self):
        return self._goal_request

    @property
    def goal_id(self):
        return self._goal_info.goal_id

    @property
    def is_active(self):
        with self._lock:
            return not self._destroyed and self._state in _ACTIVE

    @property
    def is_cancel_requested(self):
        return STATUS_CANCELING == self.status

    @property
    def status(self):
        with self._lock:
            return STATUS_UNKNOWN if self._destroyed else self._state

    def _update_state(self, event):
        with self._lock:
            if self._destroyed:  # updates to destroyed handles are ignored
                return
            new_state = _TRANSITIONS.get((self._state, event))
            if new_state is None:
                raise RCLError(
                    'Failed to update goal state: goal_handle attempted invalid transition '
                    f'from state {_STATE_NAMES[self._state]} with event {GoalEvent(event).name}'
                    ', at ./src/rcl_action/goal_handle.c:95')
            self._state = new_state
        self._action_server._publish_status()

    def execute(self, execute_callback=None):
        # A goal canceled before it started stays CANCELING, but the user's
        # execute callback still runs so it can acknowledge the cancel.
        if not self.is_cancel_requested:
            self._update_state(GoalEvent.EXECUTE)
        self._action_server.notify_execute(self, execute_callback)

    def publish_feedback(self, feedback):
        server = self._action_server
        if not isinstance(feedback, server.action_type.Feedback):
            raise TypeError()
        with self._lock:
            if self._destroyed:
                return
        message = server.action_type.Impl.FeedbackMessage()
        message.goal_id = self.goal_id
        message.feedback = feedback
        server._feedback_publisher.publish(message)

    def succeed(self):
        self._update_state(GoalEvent.SUCCEED)

    def abort(self):
        self._update_state(GoalEvent.ABORT)

    def canceled(self):
        self._update_state(GoalEvent.CANCELED)

    def destroy(self):
        with self._lock:
            self._destroyed = True


def default_handle_accepted_callback(goal_handle):
    """Execute the goal."""
    goal_handle.execute()


def default_goal_callback(goal_request):
    """Accept all goals."""
    return GoalResponse.ACCEPT


def default_cancel_callback(cancel_request):
    """No cancellations."""
    return CancelResponse.REJECT


async def _await_or_execute(callback, *args):
    if inspect.iscoroutinefunction(callback):
        return await callback(*args)
    return callback(*args)


class ActionServer:
    """ROS Action server."""

    def __init__(self, node, action_type, action_name, execute_callback, *,
                 callback_group=None,
                 goal_callback=default_goal_callback,
                 handle_accepted_callback=default_handle_accepted_callback,
                 cancel_callback=default_cancel_callback,
                 goal_service_qos_profile=None,
                 result_service_qos_profile=None,
                 cancel_service_qos_profile=None,
                 feedback_pub_qos_profile=None,
                 status_pub_qos_profile=None,
                 result_timeout=900):
        from labkit.rclpy.callback_groups import ReentrantCallbackGroup
        from labkit.rclpy.qos import (QoSProfile, qos_profile_action_status_default,
                                      qos_profile_services_default)
        if not hasattr(action_type, 'Impl'):
            raise TypeError(f'{action_type!r} is not an action type')
        if callback_group is None:
            callback_group = node.default_callback_group
        self.callback_group = callback_group
        self._lock = threading.Lock()
        self.register_handle_accepted_callback(handle_accepted_callback)
        self.register_goal_callback(goal_callback)
        self.register_cancel_callback(cancel_callback)
        self.register_execute_callback(execute_callback)
        self._node = node
        self._action_type = action_type
        self._action_name = action_name
        self._result_timeout_ns = int(result_timeout * 1_000_000_000)
        self._goal_handles = {}     # uuid bytes -> ServerGoalHandle, in acceptance order
        self._result_futures = {}   # uuid bytes -> Future of GetResultService.Response
        impl = action_type.Impl
        names = action_names(action_name)
        services_qos = qos_profile_services_default
        self._goal_service = node.create_service(
            impl.SendGoalService, names['send_goal'], self._on_send_goal,
            qos_profile=goal_service_qos_profile or services_qos,
            callback_group=callback_group)
        self._cancel_service = node.create_service(
            impl.CancelGoalService, names['cancel_goal'], self._on_cancel_goal,
            qos_profile=cancel_service_qos_profile or services_qos,
            callback_group=callback_group)
        # A result request waits (as a coroutine) for its goal to finish, so it
        # must not hold a mutually exclusive group: it gets its own reentrant one.
        self._result_group = ReentrantCallbackGroup()
        self._result_service = node.create_service(
            impl.GetResultService, names['get_result'], self._on_get_result,
            qos_profile=result_service_qos_profile or services_qos,
            callback_group=self._result_group)
        self._feedback_publisher = node.create_publisher(
            impl.FeedbackMessage, names['feedback'],
            feedback_pub_qos_profile or QoSProfile(depth=10))
        self._status_publisher = node.create_publisher(
            impl.GoalStatusMessage, names['status'],
            status_pub_qos_profile or qos_profile_action_status_default)

    @property
    def action_type(self):
        return self._action_type

    # ------------------------------------------------------------ requests
    def _on_send_goal(self, request, response):
        self._expire_goals()
        goal_info = msg_type('action_msgs/msg/GoalInfo')()
        goal_info.goal_id = request.goal_id
        key = bytes(request.goal_id.uuid)
        logger = self._node.get_logger()
        debug(logger, lambda: f'New goal request with ID: {request.goal_id.uuid}')
        accepted = False
        if key not in self._goal_handles:
            answer = call_maybe_coroutine(self._goal_callback, request.goal)
            if not isinstance(answer, GoalResponse):
                logger.warning(
                    'Goal request callback did not return a GoalResponse type. Rejecting goal.')
            else:
                accepted = answer == GoalResponse.ACCEPT
        goal_handle = None
        if accepted:
            from labkit.rclpy.task import Future
            goal_info.stamp = self._node.get_clock().now().to_msg()
            goal_handle = ServerGoalHandle(self, goal_info, request.goal)
            self._goal_handles[key] = goal_handle
            self._result_futures[key] = Future(executor=self._node.executor)
        response.accepted = accepted
        response.stamp = goal_info.stamp
        if not accepted:
            debug(logger, lambda: f'New goal rejected: {request.goal_id.uuid}')
            return response
        debug(logger, lambda: f'New goal accepted: {request.goal_id.uuid}')
        # rclpy hands the goal to the user after the response is sent.
        self._node.executor.create_task(
            _await_or_execute, self._handle_accepted_callback, goal_handle)
        return response

    def _on_cancel_goal(self, request, response):
        self._expire_goals()
        logger = self._node.get_logger()
        debug(logger, lambda: f'Cancel request received: {request}')
        self._process_cancel_request(request, response)
        # Like rclpy Humble, drop refused goals from the very list being walked
        # (a refused goal makes the walk skip the one after it).
        for goal_info in response.goals_canceling:
            goal_handle = self._goal_handles.get(bytes(goal_info.goal_id.uuid))
            if goal_handle is None:
                response.goals_canceling.remove(goal_info)
                continue
            answer = call_maybe_coroutine(self._cancel_callback, goal_handle)
            if CancelResponse.ACCEPT == answer:
                try:
                    goal_handle._update_state(GoalEvent.CANCEL_GOAL)
                except RCLError as ex:
                    debug(logger, lambda: f'Failed to cancel goal in cancel callback: {ex}')
                    response.goals_canceling.remove(goal_info)
            else:
                response.goals_canceling.remove(goal_info)
        return response

    def _process_cancel_request(self, request, response):
        """rcl_action_process_cancel_request: which goals a cancel request names."""
        CancelGoal = msg_type('action_msgs/srv/CancelGoal')
        want_id = bytes(request.goal_info.goal_id.uuid)
        want_ns = _stamp_ns(request.goal_info.stamp)
        zero_id = not any(want_id)
        chosen = []
        if not zero_id and want_ns == 0:
            response.return_code = CancelGoal.Response.ERROR_UNKNOWN_GOAL_ID
            goal_handle = self._goal_handles.get(want_id)
            if goal_handle is not None:
                if goal_handle.status in (STATUS_ACCEPTED, STATUS_EXECUTING):
                    chosen.append(goal_handle)
                    response.return_code = CancelGoal.Response.ERROR_NONE
                else:
                    response.return_code = CancelGoal.Response.ERROR_GOAL_TERMINATED
        else:
            response.return_code = CancelGoal.Response.ERROR_NONE
            if zero_id and want_ns == 0:
                want_ns = 2 ** 63 - 1  # cancel everything
            for key, goal_handle in self._goal_handles.items():
                cancelable = goal_handle.status in (STATUS_ACCEPTED, STATUS_EXECUTING)
                stamp_ns = _stamp_ns(goal_handle._goal_info.stamp)
                if cancelable and (stamp_ns <= want_ns or key == want_id):
                    chosen.append(goal_handle)
        response.goals_canceling = [_copy_goal_info(g._goal_info) for g in chosen]

    async def _on_get_result(self, request, response):
        self._expire_goals()
        key = bytes(request.goal_id.uuid)
        debug(self._node.get_logger(),
              lambda: f'Result request received for goal with ID: {request.goal_id.uuid}')
        future = self._result_futures.get(key)
        if future is None:
            response.status = STATUS_UNKNOWN
            return response
        return await future

    # ----------------------------------------------------------- execution
    def notify_execute(self, goal_handle, execute_callback):
        if execute_callback is None:
            if self._execute_callback is None:
                return
            execute_callback = self._execute_callback
        self._node.executor.create_task(self._execute_goal, execute_callback, goal_handle)

    async def _execute_goal(self, execute_callback, goal_handle):
        goal_uuid = goal_handle.goal_id.uuid
        logger = self._node.get_logger()
        debug(logger, lambda: f'Executing goal with ID {goal_uuid}')
        try:
            execute_result = await _await_or_execute(execute_callback, goal_handle)
        except Exception as ex:
            # An empty result still answers the clients waiting for one.
            execute_result = self._action_type.Result()
            logger.error(f'Error raised in execute callback: {ex}')
            traceback.print_exc()
        if goal_handle.is_active:
            logger.warning(f'Goal state not set, assuming aborted. Goal ID: {goal_uuid}')
            goal_handle.abort()
        debug(logger, lambda: f'Goal with ID {goal_uuid} finished with state {goal_handle.status}')
        result_response = self._action_type.Impl.GetResultService.Response()
        result_response.status = goal_handle.status
        result_response.result = execute_result
        future = self._result_futures.get(bytes(goal_uuid))
        if future is not None and not future.done():
            future.set_result(result_response)

    def notify_goal_done(self):
        """Kept for API compatibility: expiry is checked lazily on each request."""

    # ---------------------------------------------------------------- status
    def _publish_status(self):
        self._expire_goals()
        GoalStatus = msg_type('action_msgs/msg/GoalStatus')
        array = msg_type('action_msgs/msg/GoalStatusArray')()
        status_list = []
        for goal_handle in list(self._goal_handles.values()):
            status = GoalStatus()
            # A goal's GoalInfo never changes after acceptance: share it.
            status.goal_info = goal_handle._goal_info
            status.status = goal_handle.status
            status_list.append(status)
        array.status_list = status_list
        self._status_publisher.publish(array)

    def _expire_goals(self):
        """Forget finished goals accepted more than result_timeout ago (rcl_action's rule)."""
        if not self._goal_handles:
            return
        now = self._node.get_clock().now().nanoseconds
        for key, goal_handle in list(self._goal_handles.items()):
            if goal_handle.is_active:
                continue
            if now - _stamp_ns(goal_handle._goal_info.stamp) > self._result_timeout_ns:
                goal_handle.destroy()
                del self._goal_handles[key]
                self._result_futures.pop(key, None)

    # ------------------------------------------------------------ callbacks
    def register_handle_accepted_callback(self, handle_accepted_callback):
        if handle_accepted_callback is None:
            handle_accepted_callback = default_handle_accepted_callback
        self._handle_accepted_callback = handle_accepted_callback

    def register_goal_callback(self, goal_callback):
        if goal_callback is None:
            goal_callback = default_goal_callback
        self._goal_callback = goal_callback

    def register_cancel_callback(self, cancel_callback):
        if cancel_callback is None:
            cancel_callback = default_cancel_callback
        self._cancel_callback = cancel_callback

    def register_execute_callback(self, execute_callback):
        if not callable(execute_callback):
            raise TypeError('Failed to register goal execution callback: not callable')
        self._execute_callback = execute_callback

    def destroy(self):
        """Destroy the hidden services and topics of this server."""
        for goal_handle in self._goal_handles.values():
            goal_handle.destroy()
        node = self._node
        for service in (self._goal_service, self._cancel_service, self._result_service):
            node.destroy_service(service)
        for publisher in (self._feedback_publisher, self._status_publisher):
            node.destroy_publisher(publisher)


def _copy_goal_info(info):
    GoalInfo = msg_type('action_msgs/msg/GoalInfo')
    UUID = msg_type('unique_identifier_msgs/msg/UUID')
    Time = msg_type('builtin_interfaces/msg/Time')
    return GoalInfo(goal_id=UUID(uuid=info.goal_id.uuid),
                    stamp=Time(sec=info.stamp.sec, nanosec=info.stamp.nanosec))


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
