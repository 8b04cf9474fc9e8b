import labkit
from labkit.rclpy.logging import LoggingSeverity


def test_console_format_and_levels(rclpy, capfd):
    from labkit.rclpy.logging import get_logger, get_logger_effective_level, set_logger_level
    log = get_logger('my_logger')
    log.info('hello')
    log.debug('invisible')
    log.warn('careful')
    set_logger_level('my_logger', LoggingSeverity.DEBUG)
    log.debug('visible')
    assert get_logger_effective_level('my_logger.child') == LoggingSeverity.DEBUG
    assert log.get_child('child').name == 'my_logger.child'
    err = capfd.readouterr().err.splitlines()
    assert err == ['[INFO] [1704067200.000000000] [my_logger]: hello',
                   '[WARN] [1704067200.000000000] [my_logger]: careful',
                   '[DEBUG] [1704067200.000000000] [my_logger]: visible']


def test_once_throttle_skip_first(rclpy, capfd):
    from labkit.rclpy.logging import get_logger
    log = get_logger('f')
    for i in range(3):
        log.info(f'once {i}', once=True)
    for i in range(3):
        log.info(f'skip {i}', skip_first=True)
    for i in range(5):
        log.info(f'throttle {i}', throttle_duration_sec=1.0)
        labkit.sleep(0.5)
    lines = [line.split(': ', 1)[1] for line in capfd.readouterr().err.splitlines()]
    assert lines == ['once 0', 'skip 1', 'skip 2', 'throttle 0', 'throttle 2', 'throttle 4']


def test_rosout(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('talker', namespace='/ns')
    node.get_logger().info('before anyone listens')
    got = []
    echo = Node('echo')
    echo.create_subscription(msgs.Log, '/rosout', got.append, 10)   # volatile: no history
    node.get_logger().warning('disk low')
    node.get_logger().get_child('sub').info('child loggers have no /rosout in Humble')
    for _ in range(5):
        rclpy.spin_once(echo, timeout_sec=0)
    assert [(m.name, m.level, m.msg) for m in got] == [('ns.talker', 30, 'disk low')]


def test_duplicate_node_name_warns(rclpy, capfd):
    from labkit.rclpy.node import Node
    Node('twin')
    Node('twin')
    assert ('[WARN] [1704067200.000000000] [rcl.logging_rosout]: Publisher already registered '
            'for provided node name.') in capfd.readouterr().err


def test_rosout_message_fields(rclpy, msgs):
    from labkit.rclpy.node import Node
    from labkit.rclpy.qos import DurabilityPolicy, QoSProfile
    node = Node('talker')
    got = []
    listener = Node('echo')
    listener.create_subscription(msgs.Log, '/rosout', got.append,
                                 QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    labkit.sleep(0.25)
    node.get_logger().error('boom')
    for _ in range(10):
        rclpy.spin_once(listener, timeout_sec=0)
    mine = [m for m in got if m.name == 'talker' and m.msg == 'boom']
    assert len(mine) == 1
    log = mine[0]
    assert log.level == 40
    assert (log.stamp.sec, log.stamp.nanosec) == (1704067200, 250_000_000)
    assert log.function == 'test_rosout_message_fields'
    assert log.file.endswith('test_logging.py') and log.line > 0


def test_logging_after_shutdown_still_prints(rclpy, capfd):
    from labkit.rclpy.node import Node
    node = Node('late')
    rclpy.shutdown()
    node.get_logger().info('bye')
    assert '[late]: bye' in capfd.readouterr().err
