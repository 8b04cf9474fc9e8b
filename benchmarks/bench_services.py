"""A service call against two pub/sub hops, one process, one SingleThreadedExecutor.

A call is `client.call_async(request)` then `spin_until_future_complete` (the request
goes to the service's callback, the response back to the client's future); two hops are
a ping published, answered by a pong publisher in the other node's callback, and the pong
received. Prints the CPU time of each per round trip and the ratio call / two hops, on
labkit (live time) and, when the reference venv exists, on real rclpy (target: on labkit a
call costs at most 3x two hops).

    python benchmarks/bench_services.py
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

SECONDS = 1.0


def worker():
    import rclpy
    from std_srvs.srv import SetBool
    from rclpy.executors import SingleThreadedExecutor
    from std_msgs.msg import Int64

    rclpy.init(args=[])
    server_node = rclpy.create_node('bench_server')
    client_node = rclpy.create_node('bench_client')

    def answer(request, response):
        response.success = request.data
        return response

    server_node.create_service(SetBool, 'bench_set', answer)
    client = client_node.create_client(SetBool, 'bench_set')
    pong_pub = server_node.create_publisher(Int64, 'bench_pong', 10)
    server_node.create_subscription(Int64, 'bench_ping', pong_pub.publish, 10)
    got = [0]

    def on_pong(msg):
        got[0] += 1

    ping_pub = client_node.create_publisher(Int64, 'bench_ping', 10)
    client_node.create_subscription(Int64, 'bench_pong', on_pong, 10)
    executor = SingleThreadedExecutor()
    executor.add_node(server_node)
    executor.add_node(client_node)
    client.wait_for_service(timeout_sec=10.0)
    for _ in range(200):  # real DDS needs a moment to match
        if ping_pub.get_subscription_count() and pong_pub.get_subscription_count():
            break
        executor.spin_once(timeout_sec=0.05)
    request = SetBool.Request(data=True)
    ping = Int64(data=7)

    def calls(seconds):
        n, start, cpu = 0, time.perf_counter(), time.process_time()
        while time.perf_counter() - start < seconds:
            future = client.call_async(request)
            executor.spin_until_future_complete(future, timeout_sec=5.0)
            assert future.result().success
            n += 1
        return {'n': n, 'cpu_us': (time.process_time() - cpu) / n * 1e6,
                'wall_us': (time.perf_counter() - start) / n * 1e6}

    def hops(seconds):
        n, start, cpu = 0, time.perf_counter(), time.process_time()
        while time.perf_counter() - start < seconds:
            want = got[0] + 1
            ping_pub.publish(ping)
            while got[0] < want:
                executor.spin_once(timeout_sec=5.0)
            n += 1
        return {'n': n, 'cpu_us': (time.process_time() - cpu) / n * 1e6,
                'wall_us': (time.perf_counter() - start) / n * 1e6}

    calls(0.2)
    hops(0.2)  # warm-up
    figures = {'call': calls(SECONDS), 'hops': hops(SECONDS)}
    figures['call2'] = calls(SECONDS)   # interleaved: a load change hits both
    executor.shutdown()
    server_node.destroy_node()
    client_node.destroy_node()
    rclpy.shutdown()
    from _common import emit
    emit(figures)


def show(label, f):
    call = min(f['call']['cpu_us'], f['call2']['cpu_us'])
    print(f"{label:<20} service call {call:8.1f} us CPU ({f['call']['wall_us']:.1f} us wall)"
          f" | two hops {f['hops']['cpu_us']:8.1f} us CPU"
          f" | call / two hops {call / f['hops']['cpu_us']:.1f}x")
    return call


def main():
    from _common import run_labkit, run_reference
    lab = show('labkit (live time)', run_labkit(__file__, 'live'))
    show('labkit (virtual)', run_labkit(__file__, 'virtual'))
    real = run_reference(__file__)
    if real is None:
        print('real rclpy: reference venv not found (set ROSREF_PYTHON), no ratio')
        return
    ref = show('real rclpy (Jazzy)', real)
    print(f'labkit / real, service call CPU: {lab / ref:.3f} (target: labkit call <= 3x two hops)')


if __name__ == '__main__':
    worker() if '--worker' in sys.argv else main()
