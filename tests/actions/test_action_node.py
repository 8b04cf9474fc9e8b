"""ActionServer / ActionClient on real labkit nodes, in virtual time."""
import pytest

import labkit
import labkit.rclpy as rclpy
from labkit.interfaces import get_type
from labkit.rclpy.action import (ActionClient, ActionServer, CancelResponse, GoalResponse,
                                 get_action_client_names_and_types_by_node,
                                 get_action_names_and_types,
                                 get_action_server_names_and_types_by_node)
from labkit.rclpy.executors import SingleThreadedExecutor
from labkit.rclpy.qos import DurabilityPolicy, QoSProfile
from labkit.rclpy.task import Future

Fibonacci = get_type('action_tutorials_interfaces/action/Fibonacci')
GoalStatus = get_type('action_msgs/msg/GoalStatus')
GoalStatusArray = get_type('action_msgs/msg/GoalStatusArray')
CancelGoal = get_type('action_msgs/srv/CancelGoal')


def fibonacci_execute(goal_handle):
    feedback = Fibonacci.Feedback()
    feedback.partial_sequence = [0, 1]
    for i in range(1, goal_handle.request.order):
        feedback.partial_sequence.append(
            feedback.partial_sequence[i] + feedback.partial_sequence[i - 1])
        goal_handle.publish_feedback(feedback)
    goal_handle.succeed()
    return Fibonacci.Result(sequence=feedback.partial_sequence)


@pytest.fixture
def nodes():
    rclpy.init()
    server_node = rclpy.create_node('fibonacci_action_server')
    client_node = rclpy.create_node('fibonacci_action_client')
    executor = SingleThreadedExecutor()
    executor.add_node(server_node)
    executor.add_node(client_node)
    yield server_node, client_node, executor
    executor.shutdown()
    server_node.destroy_node()
    client_node.destroy_node()
    rclpy.shutdown()


def _run(executor, future):
    executor.spin_until_future_complete(future, timeout_sec=10.0)
    assert future.done()
    return future.result()


def _spin_a_while(executor, times=10):
    for _ in range(times):
        executor.spin_once(timeout_sec=0.01)


def test_goal_feedback_result(nodes):
    server_node, client_node, ex = nodes
    ActionServer(server_node, Fibonacci, 'fibonacci', fibonacci_execute)
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    assert client.wait_for_server(timeout_sec=1.0)
    feedback = []
    goal_handle = _run(ex, client.send_goal_async(
        Fibonacci.Goal(order=5), feedback_callback=lambda m: feedback.append(
            list(m.feedback.partial_sequence))))
    assert goal_handle.accepted
    _spin_a_while(ex)  # the goal runs; its feedback arrives
    response = _run(ex, goal_handle.get_result_async())
    assert response.status == GoalStatus.STATUS_SUCCEEDED
    assert list(response.result.sequence) == [0, 1, 1, 2, 3, 5]
    assert feedback[0] == [0, 1, 1] and feedback[-1] == [0, 1, 1, 2, 3, 5]
    assert len(feedback) == 4
    assert goal_handle.status == GoalStatus.STATUS_SUCCEEDED


def test_coroutine_execute_callback(nodes):
    server_node, client_node, ex = nodes

    async def execute(goal_handle):
        goal_handle.succeed()
        return Fibonacci.Result(sequence=[goal_handle.request.order])

    ActionServer(server_node, Fibonacci, 'fib', execute)
    client = ActionClient(client_node, Fibonacci, 'fib')
    goal_handle = _run(ex, client.send_goal_async(Fibonacci.Goal(order=7)))
    response = _run(ex, goal_handle.get_result_async())
    assert list(response.result.sequence) == [7]


def test_goal_rejected(nodes):
    server_node, client_node, ex = nodes
    ActionServer(server_node, Fibonacci, 'fibonacci', fibonacci_execute,
                 goal_callback=lambda goal: (GoalResponse.REJECT if goal.order > 10
                                             else GoalResponse.ACCEPT))
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    assert not _run(ex, client.send_goal_async(Fibonacci.Goal(order=50))).accepted
    assert _run(ex, client.send_goal_async(Fibonacci.Goal(order=3))).accepted


def test_execute_without_terminal_state_aborts(nodes):
    server_node, client_node, ex = nodes
    ActionServer(server_node, Fibonacci, 'fibonacci', lambda gh: Fibonacci.Result())
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    goal_handle = _run(ex, client.send_goal_async(Fibonacci.Goal(order=3)))
    assert _run(ex, goal_handle.get_result_async()).status == GoalStatus.STATUS_ABORTED


def _deferred_server(node, name, **kwargs):
    """A server whose goals wait (ACCEPTED) until the test executes them."""
    accepted = []
    server = ActionServer(node, Fibonacci, name, fibonacci_execute,
                          handle_accepted_callback=accepted.append, **kwargs)
    return server, accepted


def test_cancel_rejected_by_default(nodes):
    server_node, client_node, ex = nodes
    _, accepted = _deferred_server(server_node, 'fibonacci')
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    goal_handle = _run(ex, client.send_goal_async(Fibonacci.Goal(order=3)))
    _spin_a_while(ex)
    assert len(accepted) == 1
    response = _run(ex, goal_handle.cancel_goal_async())
    assert list(response.goals_canceling) == []
    assert response.return_code == CancelGoal.Response.ERROR_NONE  # Humble does not set REJECTED
    assert accepted[0].status == GoalStatus.STATUS_ACCEPTED


def test_cancel_accepted(nodes):
    server_node, client_node, ex = nodes

    def execute(goal_handle):
        if goal_handle.is_cancel_requested:
            goal_handle.canceled()
            return Fibonacci.Result(sequence=[-1])
        goal_handle.succeed()
        return Fibonacci.Result()

    accepted = []
    ActionServer(server_node, Fibonacci, 'fibonacci', execute,
                 handle_accepted_callback=accepted.append,
                 cancel_callback=lambda gh: CancelResponse.ACCEPT)
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    goal_handle = _run(ex, client.send_goal_async(Fibonacci.Goal(order=3)))
    response = _run(ex, goal_handle.cancel_goal_async())
    assert [bytes(g.goal_id.uuid) for g in response.goals_canceling] == [
        bytes(goal_handle.goal_id.uuid)]
    assert accepted[0].status == GoalStatus.STATUS_CANCELING
    accepted[0].execute()
    result = _run(ex, goal_handle.get_result_async())
    assert result.status == GoalStatus.STATUS_CANCELED
    assert list(result.result.sequence) == [-1]
    # canceling a finished goal
    response = _run(ex, goal_handle.cancel_goal_async())
    assert response.return_code == CancelGoal.Response.ERROR_GOAL_TERMINATED


def test_two_goals_and_status_topic(nodes):
    server_node, client_node, ex = nodes
    _, accepted = _deferred_server(server_node, 'fibonacci')
    statuses = []
    qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    client_node.create_subscription(GoalStatusArray, '/fibonacci/_action/status',
                                    statuses.append, qos)
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    g1 = _run(ex, client.send_goal_async(Fibonacci.Goal(order=2)))
    g2 = _run(ex, client.send_goal_async(Fibonacci.Goal(order=3)))
    _spin_a_while(ex)
    assert g1.goal_id != g2.goal_id and len(accepted) == 2
    accepted[1].execute()
    assert _run(ex, g2.get_result_async()).status == GoalStatus.STATUS_SUCCEEDED
    _spin_a_while(ex)
    last = statuses[-1].status_list
    assert [(bytes(s.goal_info.goal_id.uuid), s.status) for s in last] == [
        (bytes(g1.goal_id.uuid), GoalStatus.STATUS_ACCEPTED),
        (bytes(g2.goal_id.uuid), GoalStatus.STATUS_SUCCEEDED)]
    assert g2.status == GoalStatus.STATUS_SUCCEEDED
    accepted[0].execute()
    assert list(_run(ex, g1.get_result_async()).result.sequence) == [0, 1, 1]


def test_preempt_previous_goal(nodes):
    """The rotate_absolute pattern: a new goal aborts the one still running."""
    server_node, client_node, ex = nodes
    release = {}
    current = []

    async def execute(goal_handle):
        gate = release[goal_handle.request.order] = Future()
        await gate
        if not goal_handle.is_active:  # pre-empted meanwhile
            return Fibonacci.Result()
        goal_handle.succeed()
        return Fibonacci.Result(sequence=[goal_handle.request.order])

    def handle_accepted(goal_handle):
        if current and current[-1].is_active:
            current[-1].abort()
        current.append(goal_handle)
        goal_handle.execute()

    ActionServer(server_node, Fibonacci, 'rotate', execute,
                 handle_accepted_callback=handle_accepted)
    client = ActionClient(client_node, Fibonacci, 'rotate')
    g1 = _run(ex, client.send_goal_async(Fibonacci.Goal(order=1)))
    _spin_a_while(ex)
    g2 = _run(ex, client.send_goal_async(Fibonacci.Goal(order=2)))
    _spin_a_while(ex)
    release[1].set_result(None)
    release[2].set_result(None)
    assert _run(ex, g1.get_result_async()).status == GoalStatus.STATUS_ABORTED
    r2 = _run(ex, g2.get_result_async())
    assert r2.status == GoalStatus.STATUS_SUCCEEDED and list(r2.result.sequence) == [2]


def test_result_expires_after_result_timeout(nodes):
    server_node, client_node, ex = nodes
    ActionServer(server_node, Fibonacci, 'fibonacci', fibonacci_execute, result_timeout=2)
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    goal_handle = _run(ex, client.send_goal_async(Fibonacci.Goal(order=2)))
    assert _run(ex, goal_handle.get_result_async()).status == GoalStatus.STATUS_SUCCEEDED
    labkit.sleep(1.0)
    assert _run(ex, goal_handle.get_result_async()).status == GoalStatus.STATUS_SUCCEEDED
    labkit.sleep(1.5)
    assert _run(ex, goal_handle.get_result_async()).status == GoalStatus.STATUS_UNKNOWN


def test_graph_names(nodes):
    server_node, client_node, _ = nodes
    ActionServer(server_node, Fibonacci, 'fibonacci', fibonacci_execute)
    client = ActionClient(client_node, Fibonacci, 'fibonacci')
    expected = [('/fibonacci', ['action_tutorials_interfaces/action/Fibonacci'])]
    assert get_action_names_and_types(client_node) == expected
    assert get_action_server_names_and_types_by_node(
        client_node, 'fibonacci_action_server', '/') == expected
    assert get_action_client_names_and_types_by_node(
        client_node, 'fibonacci_action_client', '/') == expected
    assert get_action_server_names_and_types_by_node(
        client_node, 'fibonacci_action_client', '/') == []
    services = dict(client_node.get_service_names_and_types())
    base = '/fibonacci/_action/'
    assert services[base + 'send_goal'] == ['action_tutorials_interfaces/action/Fibonacci_SendGoal']
    assert services[base + 'get_result'] == [
        'action_tutorials_interfaces/action/Fibonacci_GetResult']
    assert services[base + 'cancel_goal'] == ['action_msgs/srv/CancelGoal']
    topics = dict(client_node.get_topic_names_and_types())
    assert topics[base + 'status'] == ['action_msgs/msg/GoalStatusArray']
    client.destroy()
    assert get_action_client_names_and_types_by_node(
        client_node, 'fibonacci_action_client', '/') == []


def test_wait_for_server_times_out_without_server(nodes):
    _, client_node, _ = nodes
    client = ActionClient(client_node, Fibonacci, 'nobody')
    assert not client.server_is_ready()
    assert client.wait_for_server(timeout_sec=0.5) is False


def _server_process_main(args=None):
    """A `ros2 run`-style server: spins until its process is stopped."""
    rclpy.init(args=args)
    node = rclpy.create_node('capture_image')
    ActionServer(node, Fibonacci, 'camera_state', fibonacci_execute)
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


def test_seed_client_pattern_against_server_process():
    """Chapter 14's client: callbacks chained on the futures, server in its own process."""
    from labkit import process
    server = process.start(main=_server_process_main, name='capture_image')
    rclpy.init()
    node = rclpy.create_node('visual_interaction')
    client = ActionClient(node, Fibonacci, 'camera_state')
    assert client.wait_for_server(timeout_sec=1.0)
    log = []

    def on_result(future):
        log.append(('result', list(future.result().result.sequence)))

    def on_goal_response(future):
        goal_handle = future.result()
        log.append(('accepted', goal_handle.accepted))
        goal_handle.get_result_async().add_done_callback(on_result)

    future = client.send_goal_async(Fibonacci.Goal(order=3),
                                    feedback_callback=lambda m: log.append(('feedback',)))
    future.add_done_callback(on_goal_response)
    for _ in range(50):
        rclpy.spin_once(node, timeout_sec=0.1)
        if log and log[-1][0] == 'result':
            break
    assert log[0] == ('accepted', True)
    assert log[-1] == ('result', [0, 1, 1, 2])
    names = [n for n, _ in node.get_node_names_and_namespaces()]
    assert 'capture_image' in names
    assert get_action_server_names_and_types_by_node(node, 'capture_image', '/') == [
        ('/camera_state', ['action_tutorials_interfaces/action/Fibonacci'])]
    node.destroy_node()
    rclpy.shutdown()
    server.stop()
    assert not server.running
