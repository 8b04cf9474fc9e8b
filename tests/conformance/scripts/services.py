"""Conformance: services (call_async + spin_until_future_complete, sync call from a
second thread, wait_for_service, service graph queries).

Plain rclpy: runs unchanged on ROS 2 Humble.
Humble/Jazzy: Jazzy nodes also offer `~/get_type_description`
(type_description_interfaces/srv/GetTypeDescription); Humble has no such service,
so that line is removed from the expected file.
"""
import threading

import rclpy
from rclpy.executors import SingleThreadedExecutor
from std_srvs.srv import SetBool, Trigger


class FlagServer:
    def __init__(self, node):
        self.flag = False
        self.calls = 0
        node.create_service(SetBool, 'set_flag', self.on_set_flag)
        node.create_service(Trigger, 'status', self.on_status)

    def on_set_flag(self, request, response):
        self.calls += 1
        previous = self.flag
        self.flag = request.data
        response.success = previous != request.data
        response.message = f'flag was {previous}, now {self.flag}'
        return response

    def on_status(self, request, response):
        response.success = True
        response.message = f'{self.calls} calls so far'
        return response


def main():
    rclpy.init()
    server_node = rclpy.create_node('flag_server')
    client_node = rclpy.create_node('flag_client')
    server = FlagServer(server_node)

    client = client_node.create_client(SetBool, 'set_flag')
    print('client service name:', client.srv_name)
    print('wait_for_service:', client.wait_for_service(timeout_sec=5.0))
    print('service_is_ready:', client.service_is_ready())
    missing = client_node.create_client(Trigger, 'no_such_service')
    print('wait_for_missing_service:', missing.wait_for_service(timeout_sec=0.5))

    # call_async + spin_until_future_complete (the server spins in the same executor)
    executor = SingleThreadedExecutor()
    executor.add_node(server_node)
    executor.add_node(client_node)
    future = client.call_async(SetBool.Request(data=True))
    print('future done before spin:', future.done())
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    print('future done:', future.done())
    print('response:', future.result())

    # rclpy.spin_until_future_complete: one node that both serves and calls
    combo = rclpy.create_node('combo')
    combo.create_service(Trigger, 'combo_trigger',
                         lambda req, resp: Trigger.Response(success=True, message='combo'))
    combo_client = combo.create_client(Trigger, 'combo_trigger')
    combo_client.wait_for_service(timeout_sec=5.0)
    future = combo_client.call_async(Trigger.Request())
    rclpy.spin_until_future_complete(combo, future, timeout_sec=5.0)
    print('combo response:', future.result())
    combo.destroy_node()

    # sync call from the main thread while a second thread spins both nodes
    executor.shutdown()
    spinning = SingleThreadedExecutor()
    spinning.add_node(server_node)
    spinning.add_node(client_node)
    spinner = threading.Thread(target=spinning.spin, daemon=True)
    spinner.start()
    response = client.call(SetBool.Request(data=False))
    print('sync call response:', response)
    status = client_node.create_client(Trigger, 'status')
    status.wait_for_service(timeout_sec=5.0)
    print('sync status:', status.call(Trigger.Request()).message)

    names = server_node.get_service_names_and_types_by_node('flag_server', '/')
    for name, types in sorted(names):
        print('service', name, types)
    names = client_node.get_service_names_and_types()
    print('set_flag listed:', ('/set_flag', ['std_srvs/srv/SetBool']) in
          [(n, t) for n, t in names])
    print('client names by node:',
          client_node.get_client_names_and_types_by_node('flag_client', '/'))

    spinning.shutdown()
    spinner.join(timeout=5.0)
    client_node.destroy_node()
    server_node.destroy_node()
    rclpy.shutdown()
    print('done')


if __name__ == '__main__':
    main()
