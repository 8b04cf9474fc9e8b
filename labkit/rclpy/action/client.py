"""rclpy.action.client: ActionClient and ClientGoalHandle (Humble behaviour).

Built on the public Node API: three service clients and two subscriptions on
the hidden `<action>/_action/...` names an rcl_action client uses.
"""
import weakref

from labkit.rclpy.action._common import (action_names, call_maybe_coroutine, msg_type,
                                         new_goal_uuid_bytes)

__all__ = ['ActionClient', 'ClientGoalHandle']

_TERMINAL = (4, 5, 6)  # GoalStatus SUCCEEDED, CANCELED, ABORTED


class ClientGoalHandle():
    """Goal handle for working with Action Clients."""

    def __init__(self, action_client, goal_id, goal_response):
        self._action_client = action_client
        self._goal_id = goal_id
        self._goal_response = goal_response
        self._status = 0  # GoalStatus.STATUS_UNKNOWN

    def __eq__(self, other):
        return self._goal_id == other.goal_id

    def __ne__(self, other):
        return self._goal_id != other.goal_id

    __hash__ = object.__hash__

    def __repr__(self):
        return 'ClientGoalHandle <id={0}, accepted={1}, status={2}>'.format(
            self.goal_id.uuid, self.accepted, self.status)

    @property
    def goal_id(self):
        return self._goal_id

    @property
    def stamp(self):
        return self._goal_response.stamp

    @property
    def accepted(self):
        return self._goal_response.accepted

    @property
    def status(self):
        return self._status

    def cancel_goal(self):
        """Send a cancel request and wait for the response (not from a callback)."""
        return self._action_client._cancel_goal(self)

    def cancel_goal_async(self):
        """Future of the action_msgs/srv/CancelGoal response."""
        return self._action_client._cancel_goal_async(self)

    def get_result(self):
        """Request the result and wait for it (not from a callback)."""
        return self._action_client._get_result(self)

    def get_result_async(self):
        """Future of the GetResult response (``.status``, ``.result``)."""
        return self._action_client._get_result_async(self)


class ActionClient:
    """ROS Action client."""

    def __init__(self, node, action_type, action_name, *, callback_group=None,
                 goal_service_qos_profile=None, result_service_qos_profile=None,
                 cancel_service_qos_profile=None, feedback_sub_qos_profile=None,
                 status_sub_qos_profile=None):
        from labkit.rclpy.qos import (QoSProfile, qos_profile_action_status_default,
                                      qos_profile_services_default)
        if not hasattr(action_type, 'Impl'):
            raise TypeError(f'{action_type!r} is not an action type')
        if callback_group is None:
            callback_group = node.default_callback_group
        self.callback_group = callback_group
        self._node = node
        self._action_type = action_type
        self._action_name = action_name
        self._goal_handles = {}        # uuid bytes -> weakref to ClientGoalHandle
        self._feedback_callbacks = {}  # uuid bytes -> callback
        impl = action_type.Impl
        names = action_names(action_name)
        services_qos = qos_profile_services_default
        self._goal_client = node.create_client(
            impl.SendGoalService, names['send_goal'],
            qos_profile=goal_service_qos_profile or services_qos, callback_group=callback_group)
        self._cancel_client = node.create_client(
            impl.CancelGoalService, names['cancel_goal'],
            qos_profile=cancel_service_qos_profile or services_qos,
            callback_group=callback_group)
        self._result_client = node.create_client(
            impl.GetResultService, names['get_result'],
            qos_profile=result_service_qos_profile or services_qos,
            callback_group=callback_group)
        self._feedback_sub = node.create_subscription(
            impl.FeedbackMessage, names['feedback'], self._on_feedback,
            feedback_sub_qos_profile or QoSProfile(depth=10), callback_group=callback_group)
        self._status_sub = node.create_subscription(
            impl.GoalStatusMessage, names['status'], self._on_status,
            status_sub_qos_profile or qos_profile_action_status_default,
            callback_group=callback_group)

    # -------------------------------------------------------------- topics
    def _on_feedback(self, feedback_msg):
        callback = self._feedback_callbacks.get(bytes(feedback_msg.goal_id.uuid))
        if callback is not None:
            call_maybe_coroutine(callback, feedback_msg)

    def _on_status(self, status_array):
        for status_msg in status_array.status_list:
            key = bytes(status_msg.goal_info.goal_id.uuid)
            ref = self._goal_handles.get(key)
            if ref is None:
                continue
            goal_handle = ref()
            if goal_handle is None:
                del self._goal_handles[key]
                continue
            goal_handle._status = status_msg.status
            if status_msg.status in _TERMINAL:  # done goals need no more updates
                del self._goal_handles[key]

    # ---------------------------------------------------------------- goals
    def send_goal_async(self, goal, feedback_callback=None, goal_uuid=None):
        """Send a goal; the Future's result is a ClientGoalHandle (accepted or not)."""
        from labkit.rclpy.task import Future
        if not isinstance(goal, self._action_type.Goal):
            raise TypeError()
        request = self._action_type.Impl.SendGoalService.Request()
        if goal_uuid is None:
            goal_uuid = msg_type('unique_identifier_msgs/msg/UUID')(
                uuid=list(new_goal_uuid_bytes()))
        request.goal_id = goal_uuid
        request.goal = goal
        key = bytes(request.goal_id.uuid)
        if feedback_callback is not None:
            self._feedback_callbacks[key] = feedback_callback
        future = Future(executor=self._node.executor)
        goal_id = request.goal_id

        def on_response(service_future):
            if service_future.cancelled() or future.done():
                return
            if service_future.exception() is not None:
                future.set_exception(service_future.exception())
                return
            goal_handle = ClientGoalHandle(self, goal_id, service_future.result())
            if goal_handle.accepted:
                if key in self._goal_handles:
                    raise RuntimeError(
                        'Two goals were accepted with the same ID ({})'.format(goal_handle))
                self._goal_handles[key] = weakref.ref(goal_handle)
            future.set_result(goal_handle)

        self._goal_client.call_async(request).add_done_callback(on_response)
        return future

    def send_goal(self, goal, **kwargs):
        """Send a goal and wait for its final GetResult response (not from a callback)."""
        if not isinstance(goal, self._action_type.Goal):
            raise TypeError()
        future = self.send_goal_async(goal, **kwargs)
        self._wait(future)
        if future.exception() is not None:
            raise future.exception()
        return self._get_result(future.result())

    def _cancel_goal_async(self, goal_handle):
        from labkit.rclpy.task import Future
        if not isinstance(goal_handle, ClientGoalHandle):
            raise TypeError(
                'Expected type ClientGoalHandle but received {}'.format(type(goal_handle)))
        request = msg_type('action_msgs/srv/CancelGoal').Request()
        request.goal_info.goal_id = goal_handle.goal_id
        return self._forward(self._cancel_client.call_async(request), Future)

    def _cancel_goal(self, goal_handle):
        return self._result_of(self._cancel_goal_async(goal_handle))

    def _get_result_async(self, goal_handle):
        from labkit.rclpy.task import Future
        if not isinstance(goal_handle, ClientGoalHandle):
            raise TypeError(
                'Expected type ClientGoalHandle but received {}'.format(type(goal_handle)))
        request = self._action_type.Impl.GetResultService.Request()
        request.goal_id = goal_handle.goal_id
        key = bytes(goal_handle.goal_id.uuid)

        def forget_feedback(_):
            # The user has the result: no more feedback for this goal.
            self._feedback_callbacks.pop(key, None)

        future = self._forward(self._result_client.call_async(request), Future)
        future.add_done_callback(forget_feedback)
        return future

    def _get_result(self, goal_handle):
        return self._result_of(self._get_result_async(goal_handle))

    def _forward(self, service_future, Future):
        """A fresh Future that completes with the service call's outcome."""
        future = Future(executor=self._node.executor)

        def done(f):
            if future.done():
                return
            if f.cancelled():
                future.cancel()
            elif f.exception() is not None:
                future.set_exception(f.exception())
            else:
                future.set_result(f.result())

        service_future.add_done_callback(done)
        return future

    def _wait(self, future):
        from labkit.graph import world
        world.wait(future.done)

    def _result_of(self, future):
        self._wait(future)
        if future.exception() is not None:
            raise future.exception()
        return future.result()

    # ---------------------------------------------------------------- server
    def server_is_ready(self):
        """True when the three services have a server and both topics a publisher."""
        for client in (self._goal_client, self._cancel_client, self._result_client):
            if not client.service_is_ready():
                return False
        node = self._node
        for sub in (self._feedback_sub, self._status_sub):
            topic = getattr(sub, 'topic_name', None)
            if topic is not None and node.count_publishers(topic) == 0:
                return False
        return True

    def wait_for_server(self, timeout_sec=None):
        """Wait until server_is_ready(); return it (False on timeout)."""
        from labkit.graph import world
        node = self._node
        world.wait(lambda: not node.context.ok() or self.server_is_ready(), timeout_sec)
        return self.server_is_ready()

    def destroy(self):
        """Destroy the hidden clients and subscriptions of this client."""
        node = self._node
        for client in (self._goal_client, self._cancel_client, self._result_client):
            node.destroy_client(client)
        for sub in (self._feedback_sub, self._status_sub):
            node.destroy_subscription(sub)



from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
