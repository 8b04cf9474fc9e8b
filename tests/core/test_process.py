import labkit
from labkit import process


def talker_main(args=None):
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    from labkit.rclpy.node import Node
    String = get_type('std_msgs/msg/String')
    rclpy.init(args=args)
    node = Node('talker')
    pub = node.create_publisher(String, 'chatter', 10)
    count = [0]

    def tick():
        msg = String(data=f'Hello World: {count[0]}')
        node.get_logger().info(f'Publishing: "{msg.data}"')
        pub.publish(msg)
        count[0] += 1
    node.create_timer(0.5, tick)
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


def crasher_main(args=None):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init(args=args)
    node = Node('crasher')
    node.create_timer(0.3, lambda: 1 / 0)
    rclpy.spin(node)


def test_start_stop_output_and_graph(virtual):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    proc = process.start(main=talker_main, name='talker', args=['talker'])
    assert proc.running and proc.pid > 0
    assert process.current() is process.MAIN
    rclpy.init()
    observer = Node('observer')
    assert sorted(observer.get_node_names()) == ['observer', 'talker']
    labkit.sleep(1.0)
    assert proc.output == ['[INFO] [1704067200.500000000] [talker]: Publishing: "Hello World: 0"',
                           '[INFO] [1704067201.000000000] [talker]: Publishing: "Hello World: 1"']
    proc.stop()
    assert proc.returncode == 0 and not proc.running
    assert observer.get_node_names() == ['observer']
    assert proc not in process.processes()


def test_crash_is_isolated(virtual):
    good = process.start(main=talker_main, name='talker')
    bad = process.start(main=crasher_main, name='crasher')
    labkit.sleep(1.0)
    assert bad.returncode == 1 and not bad.running
    assert any('ZeroDivisionError: division by zero' in line for line in bad.output)
    assert good.running
    assert len(good.output) == 2
    import labkit.rclpy as rclpy
    rclpy.init()
    from labkit.rclpy.node import Node
    assert Node('probe').get_node_names() == ['talker', 'probe']


def test_processes_have_their_own_rclpy_globals(virtual):
    import labkit.rclpy as rclpy
    rclpy.init()
    main_ctx = rclpy.get_default_context()
    seen = {}

    def main(args=None):
        seen['ctx_before'] = rclpy.get_default_context().ok()
        rclpy.init(args=args)
        seen['ctx'] = rclpy.get_default_context()
        seen['executor'] = rclpy.get_global_executor()

    proc = process.start(main=main, name='p')
    assert seen['ctx_before'] is False
    assert seen['ctx'] is not main_ctx and proc.returncode == 0
    assert seen['executor'] is not rclpy.get_global_executor()
    assert main_ctx.ok()


def test_reset_clears_everything(virtual):
    process.start(main=talker_main, name='a')
    process.start(main=talker_main, name='b')
    import labkit.rclpy as rclpy
    rclpy.init()
    from labkit.graph.registry import GRAPH
    from labkit.rclpy.node import Node
    Node('mine')
    assert len(GRAPH.nodes) == 3
    labkit.sleep(1.0)
    labkit.reset()
    assert GRAPH.nodes == []
    assert process.processes() == []
    assert virtual.steady_ns() == 0        # virtual time starts over
    assert not rclpy.ok()
    rclpy.init()            # the main process can start over
    assert rclpy.ok()


def test_pids_are_deterministic(virtual):
    a = process.start(main=lambda args=None: None, name='x')
    b = process.start(main=lambda args=None: None, name='y')
    assert b.pid == a.pid + 1


def test_start_resolves_ros2_run_argv(virtual, monkeypatch):
    from labkit import executables
    seen = {}

    def fake_main(args=None):
        seen['args'] = args
    import sys
    import types
    mod = types.ModuleType('labkit_fake_exe')
    mod.main = fake_main
    monkeypatch.setitem(sys.modules, 'labkit_fake_exe', mod)
    executables.register('demo_pkg', 'demo_exe', 'labkit_fake_exe:main')
    try:
        proc = process.start(['demo_pkg', 'demo_exe', '--ros-args', '-r', '__node:=x'])
    finally:
        executables.unregister_package('demo_pkg')
    assert proc.name == 'demo_exe'
    assert seen['args'] == ['/opt/ros/humble/lib/demo_pkg/demo_exe', '--ros-args', '-r',
                            '__node:=x']
    import pytest
    with pytest.raises(LookupError):
        process.start(['no_such_pkg', 'nothing'])


def test_print_goes_to_the_process_output(virtual):
    def main(args=None):
        print('hello from the process')
        import sys
        print('to stderr', file=sys.stderr)
    proc = process.start(main=main, name='printer', echo=False)
    assert proc.output == ['hello from the process', 'to stderr']


def test_time_sleep_in_a_process_is_virtual(virtual):
    stamps = []

    def main(args=None):
        import time
        import labkit.rclpy as rclpy
        from labkit.rclpy.node import Node
        rclpy.init(args=args)
        node = Node('sleeper')
        try:
            while True:
                stamps.append(node.get_clock().now().nanoseconds)
                time.sleep(1.0)
        except KeyboardInterrupt:
            stamps.append('interrupted')

    proc = process.start(main=main, name='sleeper')
    labkit.sleep(3.5)
    assert len(stamps) == 4 and stamps[-1] - stamps[0] == 3 * 10**9
    proc.stop()
    assert stamps[-1] == 'interrupted' and proc.returncode == 0


def test_main_without_args_sees_its_argv(virtual, monkeypatch):
    import sys
    import types
    from labkit import executables
    seen = {}

    def main():
        import labkit.rclpy as rclpy
        from labkit.rclpy.node import Node
        rclpy.init()                       # no args: the process's own argv, like sys.argv
        seen['name'] = Node('orig').get_name()
        seen['rest'] = rclpy.utilities.remove_ros_args()
    mod = types.ModuleType('labkit_fake_noargs')
    mod.main = main
    monkeypatch.setitem(sys.modules, 'labkit_fake_noargs', mod)
    executables.register('demo_pkg', 'noargs', 'labkit_fake_noargs:main')
    try:
        process.start(['demo_pkg', 'noargs', 'extra', '--ros-args', '-r', '__node:=renamed'])
    finally:
        executables.unregister_package('demo_pkg')
    assert seen == {'name': 'renamed', 'rest': ['/opt/ros/humble/lib/demo_pkg/noargs', 'extra']}
