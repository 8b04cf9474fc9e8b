"""A service that has only clients is on the graph: rmw lists every rq/rr DDS topic,
so real `ros2 service list` (Humble and Jazzy alike) shows it and `ros2 service type`
names it; an exercise check that a service exists still wants a server."""
import labkit
from labkit.exercises import Checker
from labkit import process
from labkit.cli.ros2 import run_command


def client_main(args=None):
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    rclpy.init(args=args)
    node = rclpy.create_node('caller')
    node.create_client(get_type('std_srvs/srv/Trigger'), 'trigger')
    try:
        rclpy.spin(node)
    finally:
        rclpy.try_shutdown()


def test_client_only_service_is_listed_but_is_no_server():
    process.start(main=client_main, name='caller')
    try:
        listed = run_command('service list -t')
        assert listed.returncode == 0, listed.stderr
        assert '/trigger [std_srvs/srv/Trigger]\n' in listed.stdout
        assert run_command('service type /trigger').stdout == 'std_srvs/srv/Trigger\n'
        info = run_command('node info /caller').stdout
        assert 'Service Clients:\n    /trigger: std_srvs/srv/Trigger\n' in info
        assert '/trigger' not in info.split('Service Clients:')[0]
        check = Checker('trigger')
        assert not check.service('/trigger')
        assert check.results == [(False, '没有找到服务 /trigger')]
    finally:
        labkit.reset()
