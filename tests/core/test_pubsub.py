import pytest

from labkit.rclpy.qos import (DurabilityPolicy, LivelinessPolicy, QoSCompatibility, QoSProfile, ReliabilityPolicy,
                              qos_check_compatible, qos_profile_sensor_data)


def spin_all(rclpy, node):
    for _ in range(100):
        rclpy.spin_once(node, timeout_sec=0)


def test_publish_subscribe(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    got = []
    node.create_subscription(msgs.String, 'chatter', lambda m: got.append(m.data), 10)
    pub = node.create_publisher(msgs.String, 'chatter', 10)
    msg = msgs.String(data='a')
    pub.publish(msg)
    msg.data = 'changed after publish'
    rclpy.spin_once(node, timeout_sec=0)
    assert got == ['a']
    assert pub.get_subscription_count() == 1
    assert node.count_publishers('chatter') == 1
    assert node.count_subscribers('/chatter') == 1


def test_spin_once_runs_at_most_one_callback(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    got = []
    node.create_subscription(msgs.Int32, 'x', lambda m: got.append(m.data), 10)
    pub = node.create_publisher(msgs.Int32, 'x', 10)
    for i in range(3):
        pub.publish(msgs.Int32(data=i))
    rclpy.spin_once(node, timeout_sec=0)
    assert got == [0]
    rclpy.spin_once(node, timeout_sec=0)
    rclpy.spin_once(node, timeout_sec=0)
    assert got == [0, 1, 2]


def test_wrong_type_raises_type_error(rclpy, msgs):
    from labkit.rclpy.node import Node
    pub = Node('n').create_publisher(msgs.String, 'chatter', 10)
    with pytest.raises(TypeError) as exc:
        pub.publish(msgs.Int32(data=1))
    assert str(exc.value).startswith('Expected ')
    with pytest.raises(TypeError):
        pub.publish('plain string')


def test_keep_last_drops_oldest(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    got = []
    node.create_subscription(msgs.Int32, 'x', lambda m: got.append(m.data), 3)
    pub = node.create_publisher(msgs.Int32, 'x', 10)
    for i in range(10):
        pub.publish(msgs.Int32(data=i))
    spin_all(rclpy, node)
    assert got == [7, 8, 9]


def test_transient_local_latching(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    latched = QoSProfile(depth=2, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    pub = node.create_publisher(msgs.Int32, 'map', latched)
    for i in range(3):
        pub.publish(msgs.Int32(data=i))
    late, volatile = [], []
    node.create_subscription(msgs.Int32, 'map', lambda m: late.append(m.data), latched)
    node.create_subscription(msgs.Int32, 'map', lambda m: volatile.append(m.data), 10)
    spin_all(rclpy, node)
    assert late == [1, 2]
    assert volatile == []


def test_incompatible_qos_does_not_match_and_warns(rclpy, msgs, capfd):
    from labkit.rclpy.node import Node
    node = Node('n')
    got = []
    node.create_subscription(msgs.Int32, 'x', lambda m: got.append(m.data), 10)  # reliable
    pub = node.create_publisher(msgs.Int32, 'x', qos_profile_sensor_data)      # best effort
    pub.publish(msgs.Int32(data=1))
    spin_all(rclpy, node)
    assert got == []
    assert pub.get_subscription_count() == 0
    err = capfd.readouterr().err.splitlines()
    assert err == [
        "[WARN] [1704067200.000000000] [n]: New publisher discovered on topic 'x', offering "
        "incompatible QoS. No messages will be received from it. Last incompatible policy: "
        "RELIABILITY",
        "[WARN] [1704067200.000000000] [n]: New subscription discovered on topic 'x', "
        "requesting incompatible QoS. No messages will be sent to it. Last incompatible "
        "policy: RELIABILITY"]
    # best effort subscription takes from a reliable publisher
    be = []
    node.create_subscription(msgs.Int32, 'y', lambda m: be.append(m.data), qos_profile_sensor_data)
    node.create_publisher(msgs.Int32, 'y', 10).publish(msgs.Int32(data=5))
    spin_all(rclpy, node)
    assert be == [5]


def test_qos_profiles_and_compatibility():
    assert str(qos_profile_sensor_data).startswith(
        'QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=5, '
        'reliability=ReliabilityPolicy.BEST_EFFORT')
    ok = QoSProfile(depth=10)
    # Humble (rmw_dds_common) warns: QoSProfile's liveliness is SYSTEM_DEFAULT
    assert qos_check_compatible(ok, ok) == (
        QoSCompatibility.WARNING,
        'WARNING: Publisher liveliness is system_default and subscription liveliness '
        'is system_default;')
    sure = QoSProfile(depth=10, liveliness=LivelinessPolicy.AUTOMATIC)
    assert qos_check_compatible(sure, sure) == (QoSCompatibility.OK, '')
    volatile, durable = QoSProfile(depth=1), QoSProfile(
        depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    assert qos_check_compatible(volatile, durable)[0] == QoSCompatibility.ERROR
    assert qos_check_compatible(durable, volatile)[0] != QoSCompatibility.ERROR
    be = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
    assert qos_check_compatible(be, ok) == (
        QoSCompatibility.ERROR, 'ERROR: Best effort publisher and reliable subscription;')
    with pytest.raises(Exception):
        QoSProfile()


def test_depth_shorthand_and_errors(rclpy, msgs):
    from labkit.rclpy.node import Node
    node = Node('n')
    assert node.create_publisher(msgs.String, 'a', 7).qos_profile.depth == 7
    with pytest.raises(ValueError):
        node.create_publisher(msgs.String, 'a', -1)
    with pytest.raises(TypeError):
        node.create_publisher(msgs.String, 'a', 'ten')


def test_graph_queries(rclpy, msgs):
    from labkit.rclpy.node import Node
    a = Node('a', namespace='/ns')
    b = Node('b')
    a.create_publisher(msgs.String, 'chatter', 10)
    b.create_subscription(msgs.String, '/ns/chatter', lambda m: None, 10)
    b.create_service(msgs.AddTwoInts, 'add', lambda q, r: r)
    a.create_client(msgs.AddTwoInts, '/add')
    assert sorted(b.get_node_names_and_namespaces()) == [('a', '/ns'), ('b', '/')]
    assert b.get_node_names_and_namespaces_with_enclaves()[0] == ('a', '/ns', '/')
    topics = dict(b.get_topic_names_and_types())
    assert topics['/ns/chatter'] == ['std_msgs/msg/String']
    assert '/rosout' in topics and '/parameter_events' in topics
    services = dict(b.get_service_names_and_types())
    assert services['/add'] == ['example_interfaces/srv/AddTwoInts']
    assert '/b/get_parameters' in services
    pubs = dict(b.get_publisher_names_and_types_by_node('a', '/ns'))
    assert pubs['/ns/chatter'] == ['std_msgs/msg/String']
    assert dict(b.get_subscriber_names_and_types_by_node('b', '/')) == {
        '/ns/chatter': ['std_msgs/msg/String']}
    assert dict(b.get_client_names_and_types_by_node('a', '/ns'))['/add'] == [
        'example_interfaces/srv/AddTwoInts']
    assert '/add' in dict(b.get_service_names_and_types_by_node('b', '/'))
    from labkit.rclpy.node import NodeNameNonExistentError
    with pytest.raises(NodeNameNonExistentError):
        b.get_publisher_names_and_types_by_node('ghost', '/')
    info = b.get_publishers_info_by_topic('/ns/chatter')
    assert len(info) == 1 and info[0].node_name == 'a' and info[0].node_namespace == '/ns'
    text = str(info[0]).splitlines()
    assert text[:4] == ['Node name: a', 'Node namespace: /ns', 'Topic type: std_msgs/msg/String',
                        'Endpoint type: PUBLISHER']
    assert text[4].startswith('GID: 01.0f.') and len(text[4]) == len('GID: ') + 24 * 3 - 1
    assert text[5:] == ['QoS profile:', '  Reliability: RELIABLE', '  History (Depth): UNKNOWN',
                        '  Durability: VOLATILE', '  Lifespan: Infinite', '  Deadline: Infinite',
                        '  Liveliness: AUTOMATIC', '  Liveliness lease duration: Infinite']
    assert len(b.get_subscriptions_info_by_topic('/ns/chatter')) == 1
    a.destroy_node()
    assert b.get_node_names() == ['b']
    assert b.count_publishers('/ns/chatter') == 0


def test_domains_are_separate(virtual, msgs):
    import labkit.rclpy as rclpy
    from labkit.rclpy.context import Context
    from labkit.rclpy.node import Node
    c0, c7 = Context(), Context()
    c0.init([])
    c7.init([], domain_id=7)
    a, b = Node('a', context=c0), Node('b', context=c7)
    assert a.get_node_names() == ['a']
    got = []
    b.create_subscription(msgs.String, 'x', lambda m: got.append(m), 10)
    a.create_publisher(msgs.String, 'x', 10).publish(msgs.String())
    rclpy.spin_once(b, executor=rclpy.executors.SingleThreadedExecutor(context=c7), timeout_sec=0)
    assert got == []
    c0.shutdown()
    c7.shutdown()


def test_raw_subscription_gets_cdr(rclpy, msgs):
    from labkit.interfaces import serialize
    from labkit.rclpy.node import Node
    node = Node('n')
    got = []
    node.create_subscription(msgs.String, 'x', got.append, 10, raw=True)
    node.create_publisher(msgs.String, 'x', 10).publish(msgs.String(data='hi'))
    rclpy.spin_once(node, timeout_sec=0)
    assert got == [serialize(msgs.String(data='hi'))]


def test_type_checks_and_serialization(rclpy, msgs):
    from labkit.rclpy.node import Node
    from labkit.rclpy.serialization import deserialize_message, serialize_message
    from labkit.rclpy.wait_for_message import wait_for_message
    node = Node('n')
    with pytest.raises(RuntimeError) as exc:
        node.create_publisher(msgs.AddTwoInts, 'x', 10)
    assert 'this might be a service or action' in str(exc.value)
    with pytest.raises(RuntimeError):
        node.create_service(msgs.String, 'x', lambda q, r: r)
    with pytest.raises(AttributeError):
        node.create_subscription(str, 'x', print, 10)
    from labkit.interfaces import rmw_serialize
    data = serialize_message(msgs.String(data='hello'))
    # the interfaces layer owns the exact bytes (Humble's trailing padding included)
    assert data == rmw_serialize(msgs.String(data='hello'))
    assert data.startswith(b'\x00\x01\x00\x00\x06\x00\x00\x00hello\x00')
    assert deserialize_message(data, msgs.String).data == 'hello'
    ok, msg = wait_for_message(msgs.String, node, 'nothing', time_to_wait=0.5)
    assert (ok, msg) == (False, None)


def test_incompatible_qos_event_callback(rclpy, msgs, capfd):
    from labkit.rclpy.node import Node
    from labkit.rclpy.qos import QoSPolicyKind
    from labkit.rclpy.qos_event import SubscriptionEventCallbacks
    node = Node('n')
    events = []
    node.create_subscription(msgs.Int32, 'x', lambda m: None, 10, event_callbacks=(
        SubscriptionEventCallbacks(incompatible_qos=events.append)))
    node.create_publisher(msgs.Int32, 'x', qos_profile_sensor_data)
    assert events == []                 # handled when the node spins, as in rclpy
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0)
    assert len(events) == 1 and events[0].last_policy_kind == QoSPolicyKind.RELIABILITY
    err = capfd.readouterr().err
    assert 'offering incompatible QoS' not in err
    assert 'requesting incompatible QoS' in err
