"""Conformance: actions (goals, feedback, results, goal rejection, cancel accepted and
rejected by the default cancel callback, abort, hidden services and topics).

Plain rclpy: runs unchanged on ROS 2 Humble (example_interfaces/action/Fibonacci).
Reference note: Jazzy has no example_interfaces wheel; the reference run maps it to
test_msgs/action/Fibonacci (same definition), so only field values are printed.
"""
import threading
import time

import rclpy
from action_msgs.msg import GoalStatus
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor

STATUS = {GoalStatus.STATUS_UNKNOWN: 'UNKNOWN', GoalStatus.STATUS_ACCEPTED: 'ACCEPTED',
          GoalStatus.STATUS_EXECUTING: 'EXECUTING', GoalStatus.STATUS_CANCELING: 'CANCELING',
          GoalStatus.STATUS_SUCCEEDED: 'SUCCEEDED', GoalStatus.STATUS_CANCELED: 'CANCELED',
          GoalStatus.STATUS_ABORTED: 'ABORTED'}


def fibonacci_steps(goal_handle, pause):
    """Shared body: build the sequence, publish feedback, honour cancel requests."""
    feedback = Fibonacci.Feedback()
    feedback.sequence = [0, 1]
    for i in range(1, goal_handle.request.order):
        if goal_handle.is_cancel_requested:
            goal_handle.canceled()
            return Fibonacci.Result(sequence=feedback.sequence)
        feedback.sequence.append(feedback.sequence[i] + feedback.sequence[i - 1])
        goal_handle.publish_feedback(feedback)
        time.sleep(pause)
    goal_handle.succeed()
    return Fibonacci.Result(sequence=feedback.sequence)


def execute_plain(goal_handle):
    if goal_handle.request.order < 0:
        goal_handle.abort()
        return Fibonacci.Result()
    if goal_handle.request.order == 0:
        return Fibonacci.Result()  # state never set: the server aborts it
    return fibonacci_steps(goal_handle, 0.05)


def execute_slow(goal_handle):
    return fibonacci_steps(goal_handle, 0.1)


def main():
    rclpy.init()
    server_node = rclpy.create_node('fibonacci_server')
    group = ReentrantCallbackGroup()
    # default callbacks: every goal accepted, every cancel request rejected
    ActionServer(server_node, Fibonacci, 'fibonacci', execute_plain, callback_group=group)
    ActionServer(server_node, Fibonacci, 'fibonacci_slow', execute_slow, callback_group=group)
    ActionServer(server_node, Fibonacci, 'fibonacci_picky', execute_slow, callback_group=group,
                 goal_callback=lambda goal: (GoalResponse.REJECT if goal.order > 10
                                             else GoalResponse.ACCEPT),
                 cancel_callback=lambda goal_handle: CancelResponse.ACCEPT)
    server_executor = MultiThreadedExecutor(num_threads=4)
    server_executor.add_node(server_node)
    server_thread = threading.Thread(target=server_executor.spin, daemon=True)
    server_thread.start()

    client_node = rclpy.create_node('fibonacci_client')
    executor = SingleThreadedExecutor()
    executor.add_node(client_node)

    def wait(future):
        executor.spin_until_future_complete(future, timeout_sec=10.0)
        return future.result()

    def run_goal(client, order, feedback_log):
        goal_handle = wait(client.send_goal_async(
            Fibonacci.Goal(order=order),
            feedback_callback=lambda fb: feedback_log.append(list(fb.feedback.sequence))))
        return goal_handle

    plain = ActionClient(client_node, Fibonacci, 'fibonacci')
    print('wait_for_server:', plain.wait_for_server(timeout_sec=5.0))
    print('server_is_ready:', plain.server_is_ready())
    missing = ActionClient(client_node, Fibonacci, 'no_such_action')
    print('wait_for_missing_server:', missing.wait_for_server(timeout_sec=0.5))

    # 1. a goal that succeeds, with feedback
    feedback = []
    goal_handle = run_goal(plain, 5, feedback)
    print('goal accepted:', goal_handle.accepted)
    result = wait(goal_handle.get_result_async())
    print('result status:', STATUS[result.status])
    print('result sequence:', list(result.result.sequence))
    for _ in range(4):  # feedback may still be on its way
        executor.spin_once(timeout_sec=0.05)
    print('feedback:', feedback)
    print('client goal handle status:', STATUS[goal_handle.status])

    # 2. aborted by the server, and the state never set (the server aborts it)
    for order in (-1, 0):
        goal_handle = run_goal(plain, order, [])
        result = wait(goal_handle.get_result_async())
        print(f'order {order}: accepted {goal_handle.accepted}, status',
              STATUS[result.status], list(result.result.sequence))

    # 3. goal rejected by the goal callback
    picky = ActionClient(client_node, Fibonacci, 'fibonacci_picky')
    picky.wait_for_server(timeout_sec=5.0)
    goal_handle = run_goal(picky, 20, [])
    print('picky order 20 accepted:', goal_handle.accepted)

    # 4. cancel rejected by the default cancel callback: the goal goes on
    slow = ActionClient(client_node, Fibonacci, 'fibonacci_slow')
    slow.wait_for_server(timeout_sec=5.0)
    feedback = []
    goal_handle = run_goal(slow, 5, feedback)
    for _ in range(100):
        if feedback:
            break
        executor.spin_once(timeout_sec=0.05)
    cancel = wait(goal_handle.cancel_goal_async())
    print('default cancel: return_code', cancel.return_code,
          'goals_canceling', len(cancel.goals_canceling))
    result = wait(goal_handle.get_result_async())
    print('default cancel: result status', STATUS[result.status], list(result.result.sequence))

    # 5. cancel accepted: the execute callback sees is_cancel_requested
    feedback = []
    goal_handle = run_goal(picky, 10, feedback)
    for _ in range(100):
        if feedback:
            break
        executor.spin_once(timeout_sec=0.05)
    cancel = wait(goal_handle.cancel_goal_async())
    print('accepted cancel: return_code', cancel.return_code,
          'goals_canceling', len(cancel.goals_canceling),
          'same goal id', cancel.goals_canceling[0].goal_id == goal_handle.goal_id)
    result = wait(goal_handle.get_result_async())
    print('accepted cancel: result status', STATUS[result.status])
    print('CancelGoal return codes:', cancel.ERROR_NONE, cancel.ERROR_REJECTED,
          cancel.ERROR_UNKNOWN_GOAL_ID, cancel.ERROR_GOAL_TERMINATED)

    # 6. hidden services and topics of an action
    services = [n for n, _ in client_node.get_service_names_and_types()
                if n.startswith('/fibonacci/')]
    topics = [(n, t) for n, t in client_node.get_topic_names_and_types()
              if n.startswith('/fibonacci/')]
    print('action services:', sorted(services))
    print('action topics:', sorted(n for n, _ in topics))
    print('status topic type:', dict(topics)['/fibonacci/_action/status'])

    server_executor.shutdown()
    server_thread.join(timeout=5.0)
    executor.shutdown()
    client_node.destroy_node()
    server_node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
