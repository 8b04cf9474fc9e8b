import labkit
from labkit import process
from test_process import talker_main


def listener_main(args=None):
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    from labkit.rclpy.node import Node
    rclpy.init(args=args)
    node = Node('listener')
    node.create_subscription(get_type('std_msgs/msg/String'), 'chatter',
                             lambda m: node.get_logger().info(f'I heard: "{m.data}"'), 10)
    rclpy.spin(node)


def scenario():
    from labkit.graph import world
    labkit.reset()
    world.set_mode('virtual')
    t = process.start(main=talker_main, name='talker')
    listener = process.start(main=listener_main, name='listener')
    labkit.sleep(3.0)
    out = list(t.output) + list(listener.output)
    labkit.reset()
    return out


def test_same_scenario_same_output(virtual):
    first = scenario()
    second = scenario()
    assert len(first) == 12
    assert first == second
    assert first[6] == '[INFO] [1704067200.500000000] [listener]: I heard: "Hello World: 0"'
