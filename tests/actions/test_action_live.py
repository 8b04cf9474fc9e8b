"""Live mode smoke test (real threads, real time), run in a fresh interpreter."""
import os
import subprocess
import sys
import textwrap

SCRIPT = textwrap.dedent('''
    import labkit.rclpy as rclpy
    from labkit import process
    from labkit.interfaces import get_type
    from labkit.rclpy.action import ActionClient, ActionServer
    from labkit.rclpy.parameter import Parameter

    Fibonacci = get_type('action_tutorials_interfaces/action/Fibonacci')

    def execute(goal_handle):
        feedback = Fibonacci.Feedback(partial_sequence=[0, 1])
        goal_handle.publish_feedback(feedback)
        goal_handle.succeed()
        return Fibonacci.Result(sequence=[0, 1, 1])

    def server_main(args=None):
        rclpy.init(args=args)
        node = rclpy.create_node('server')
        node.declare_parameter('gain', 2.0)
        ActionServer(node, Fibonacci, 'fib', execute)
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
            rclpy.try_shutdown()

    server = process.start(main=server_main, name='server')
    rclpy.init()
    node = rclpy.create_node('client')
    client = ActionClient(node, Fibonacci, 'fib')
    assert client.wait_for_server(timeout_sec=5.0)
    future = client.send_goal_async(Fibonacci.Goal(order=2))
    rclpy.spin_until_future_complete(node, future, timeout_sec=5.0)
    result = future.result().get_result_async()
    rclpy.spin_until_future_complete(node, result, timeout_sec=5.0)
    assert list(result.result().result.sequence) == [0, 1, 1], result.result()
    get = node.create_client(get_type('rcl_interfaces/srv/GetParameters'), '/server/get_parameters')
    assert get.wait_for_service(timeout_sec=5.0)
    reply = get.call_async(get_type('rcl_interfaces/srv/GetParameters').Request(names=['gain']))
    rclpy.spin_until_future_complete(node, reply, timeout_sec=5.0)
    assert reply.result().values[0].double_value == 2.0
    node.destroy_node()
    rclpy.shutdown()
    server.stop()
    print('LIVE OK')
''')


def test_live_mode_goal_and_parameter_service():
    env = dict(os.environ, LABKIT_TIME='live')
    out = subprocess.run([sys.executable, '-c', SCRIPT], env=env, capture_output=True,
                         text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert 'LIVE OK' in out.stdout
