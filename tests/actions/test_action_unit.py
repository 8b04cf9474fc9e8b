"""Goal state machine, cancel-request rules and graph derivation, without an executor."""
import pytest

from labkit.interfaces import get_type
from labkit.rclpy.action import graph
from labkit.rclpy.action.server import ActionServer, GoalEvent, RCLError, ServerGoalHandle

GoalInfo = get_type('action_msgs/msg/GoalInfo')
GoalStatus = get_type('action_msgs/msg/GoalStatus')
CancelGoal = get_type('action_msgs/srv/CancelGoal')
UUID = get_type('unique_identifier_msgs/msg/UUID')
Time = get_type('builtin_interfaces/msg/Time')


class _StubServer:
    """Only what a ServerGoalHandle calls back into."""

    def __init__(self):
        self.published = 0

    def _publish_status(self):
        self.published += 1


def _info(n, sec):
    return GoalInfo(goal_id=UUID(uuid=[n] * 16), stamp=Time(sec=sec))


def _handle(n=1, sec=10, server=None):
    return ServerGoalHandle(server or _StubServer(), _info(n, sec), None)


def test_goal_state_machine():
    server = _StubServer()
    h = _handle(server=server)
    assert h.status == GoalStatus.STATUS_ACCEPTED and h.is_active
    h._update_state(GoalEvent.EXECUTE)
    assert h.status == GoalStatus.STATUS_EXECUTING
    h._update_state(GoalEvent.CANCEL_GOAL)
    assert h.is_cancel_requested
    h.canceled()
    assert h.status == GoalStatus.STATUS_CANCELED and not h.is_active
    assert server.published == 3
    with pytest.raises(RCLError) as e:
        h.succeed()
    assert str(e.value).startswith(
        'Failed to update goal state: goal_handle attempted invalid transition from state '
        'CANCELED with event SUCCEED')
    h.destroy()
    assert h.status == GoalStatus.STATUS_UNKNOWN
    h.abort()  # ignored once destroyed


def test_accepted_goal_cannot_succeed_directly():
    h = _handle()
    with pytest.raises(RCLError, match='from state ACCEPTED with event SUCCEED'):
        h.succeed()


def _server_with(*handles):
    server = object.__new__(ActionServer)
    server._goal_handles = {bytes(h.goal_id.uuid): h for h in handles}
    return server


def _cancel(server, n=0, sec=0):
    request = CancelGoal.Request()
    request.goal_info = GoalInfo(goal_id=UUID(uuid=[n] * 16), stamp=Time(sec=sec))
    response = CancelGoal.Response()
    server._process_cancel_request(request, response)
    return response.return_code, [g.goal_id.uuid[0] for g in response.goals_canceling]


def test_cancel_request_rules():
    a, b, c = _handle(1, 10), _handle(2, 20), _handle(3, 30)
    c._update_state(GoalEvent.EXECUTE)
    c.succeed()
    server = _server_with(a, b, c)
    assert _cancel(server) == (CancelGoal.Response.ERROR_NONE, [1, 2])          # all
    assert _cancel(server, 2) == (CancelGoal.Response.ERROR_NONE, [2])          # one
    assert _cancel(server, 9) == (CancelGoal.Response.ERROR_UNKNOWN_GOAL_ID, [])
    assert _cancel(server, 3) == (CancelGoal.Response.ERROR_GOAL_TERMINATED, [])
    assert _cancel(server, 0, 15) == (CancelGoal.Response.ERROR_NONE, [1])      # by stamp
    assert _cancel(server, 2, 15) == (CancelGoal.Response.ERROR_NONE, [1, 2])   # both


class _GraphNode:
    def get_topic_names_and_types(self):
        return [('/chatter', ['std_msgs/msg/String']),
                ('/fibonacci/_action/feedback',
                 ['action_tutorials_interfaces/action/Fibonacci_FeedbackMessage']),
                ('/fibonacci/_action/status', ['action_msgs/msg/GoalStatusArray'])]

    def get_publisher_names_and_types_by_node(self, name, ns):
        return self.get_topic_names_and_types() if name == 'server' else []

    def get_subscriber_names_and_types_by_node(self, name, ns):
        return self.get_topic_names_and_types() if name == 'client' else []


def test_graph_names_from_feedback_topics():
    node = _GraphNode()
    expected = [('/fibonacci', ['action_tutorials_interfaces/action/Fibonacci'])]
    assert graph.get_action_names_and_types(node) == expected
    assert graph.get_action_server_names_and_types_by_node(node, 'server', '/') == expected
    assert graph.get_action_server_names_and_types_by_node(node, 'client', '/') == []
    assert graph.get_action_client_names_and_types_by_node(node, 'client', '/') == expected


def test_virtual_goal_ids_are_reproducible_uuid4():
    import uuid
    from labkit.rclpy.action import _common
    _common.reset_virtual_uuids()
    first = [_common.new_goal_uuid_bytes() for _ in range(3)]
    _common.reset_virtual_uuids()
    assert [_common.new_goal_uuid_bytes() for _ in range(3)] == first
    assert len(set(first)) == 3
    assert all(uuid.UUID(bytes=b).version == 4 for b in first)
