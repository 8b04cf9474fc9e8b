"""Bad input to the rclpy API fails as Humble's rclpy fails (issue 13), and what a learner
sees in a traceback or repr names rclpy's modules, not labkit's files."""
import traceback

import pytest

import labkit


def test_negative_timer_period_is_refused_like_rcl(rclpy):
    from labkit.rclpy.exceptions import RCLError
    node = rclpy.create_node('t')
    with pytest.raises(RCLError) as info:
        node.create_timer(-1.0, lambda: None)
    assert str(info.value) == ('failed to create timer: timer period must be non-negative, '
                               'at ./src/rcl/timer.c:139')
    assert node.timers == [] or len(list(node.timers)) == 0
    node.create_timer(0.0, lambda: None)       # zero is allowed (fires every spin)


def test_subscription_without_callback_fails_when_a_message_arrives(rclpy, msgs):
    node = rclpy.create_node('s')
    node.create_subscription(msgs.String, '/x', None, 10)
    pub = node.create_publisher(msgs.String, '/x', 10)
    pub.publish(msgs.String(data='hi'))
    with pytest.raises(TypeError, match="'NoneType' object is not callable"):
        rclpy.spin_once(node, timeout_sec=0.1)


def test_undeclared_parameter_text_is_humbles(rclpy):
    # Humble's _check_undeclared_parameters consumes the first name with any(): the
    # message shows the names after the first one (for one name: []). Jazzy differs.
    from labkit.rclpy.exceptions import ParameterNotDeclaredException
    from labkit.rclpy.parameter import Parameter
    node = rclpy.create_node('p')
    with pytest.raises(ParameterNotDeclaredException) as one:
        node.set_parameters([Parameter('foo', value=1)])
    assert str(one.value) == "('Invalid access to undeclared parameter(s)', [])"
    with pytest.raises(ParameterNotDeclaredException) as two:
        node.set_parameters_atomically([Parameter('a', value=1), Parameter('b', value=2)])
    assert str(two.value) == "('Invalid access to undeclared parameter(s)', ['b'])"


def test_destroyed_publisher_raises_invalid_handle(rclpy, msgs):
    from labkit.rclpy.exceptions import InvalidHandle
    node = rclpy.create_node('d')
    pub = node.create_publisher(msgs.String, '/y', 10)
    assert pub.get_subscription_count() == 0
    node.destroy_publisher(pub)
    with pytest.raises(InvalidHandle, match='destruction was requested'):
        pub.get_subscription_count()
    with pytest.raises(InvalidHandle):
        pub.topic_name


def test_spin_once_after_shutdown_fails_like_rclpy(rclpy):
    node = rclpy.create_node('z')
    rclpy.spin_once(node, timeout_sec=0)
    rclpy.shutdown()
    # rclpy makes a new global executor on the new (uninitialised) default context:
    # its guard condition's `with context.handle:` meets None
    with pytest.raises(TypeError, match='context manager protocol'):
        rclpy.spin_once(node, timeout_sec=0.1)


def test_qos_event_policy_kind_is_the_rmw_enum(rclpy, msgs, capfd):
    from labkit.rclpy.qos import QoSPolicyKind, qos_policy_name_from_kind, qos_profile_sensor_data
    from labkit.rclpy.qos_event import SubscriptionEventCallbacks
    node = rclpy.create_node('q')
    events = []
    node.create_subscription(msgs.Int32, 'x', lambda m: None, 10, event_callbacks=(
        SubscriptionEventCallbacks(incompatible_qos=events.append)))
    node.create_publisher(msgs.Int32, 'x', qos_profile_sensor_data)
    for _ in range(3):
        rclpy.spin_once(node, timeout_sec=0)
    kind = events[0].last_policy_kind
    assert kind.name == 'RMW_QOS_POLICY_RELIABILITY'
    assert type(kind).__module__ + '.' + type(kind).__name__ == \
        'rclpy._rclpy_pybind11.rmw_qos_policy_kind_t'
    assert str(kind) == 'rmw_qos_policy_kind_t.RMW_QOS_POLICY_RELIABILITY'
    assert int(kind) == 16 and QoSPolicyKind(kind) is QoSPolicyKind.RELIABILITY
    assert qos_policy_name_from_kind(kind) == 'RELIABILITY'
    # the default handler (another node, no user callback) still names the policy as rclpy does
    other = rclpy.create_node('q2')
    other.create_subscription(msgs.Int32, 'x', lambda m: None, 10)
    for _ in range(3):
        rclpy.spin_once(other, timeout_sec=0)
    assert 'Last incompatible policy: RELIABILITY' in capfd.readouterr().err


def test_tracebacks_and_reprs_name_rclpy_modules(rclpy, msgs):
    from labkit.rclpy import executors, qos
    from labkit.rclpy.exceptions import InvalidHandle, ParameterNotDeclaredException
    node = rclpy.create_node('r')
    try:
        node.get_parameter('nope')
    except ParameterNotDeclaredException:
        text = traceback.format_exc()
    assert text.splitlines()[-1].startswith('rclpy.exceptions.ParameterNotDeclaredException: ')
    assert 'labkit.rclpy' not in text.splitlines()[-1]
    assert repr(executors.SingleThreadedExecutor) == \
        "<class 'rclpy.executors.SingleThreadedExecutor'>"
    assert qos.QoSProfile.__module__ == 'rclpy.qos'
    assert type(node).__module__ == 'rclpy.node'
    assert InvalidHandle.__module__ == 'rclpy._rclpy_pybind11'
    assert repr(node.create_publisher(msgs.String, 'z', 10)).startswith(
        '<rclpy.publisher.Publisher object at ')
    from labkit.rclpy.clock import ClockType
    assert ClockType.__module__ == 'rclpy.clock'


def test_rclpy_shutdown_after_labkit_reset_does_not_raise(virtual):
    import labkit.rclpy as rclpy
    rclpy.init(args=[])
    rclpy.create_node('before_reset')
    labkit.reset()
    rclpy.shutdown()               # the notebook's last cell, after a reset: nothing to do
    # a shutdown with nothing initialised since is still refused as rclpy refuses it
    with pytest.raises(RuntimeError, match='must be initialized'):
        rclpy.shutdown()
    rclpy.init(args=[])            # and a new init/shutdown cycle is ordinary
    rclpy.shutdown()


def test_keep_all_queue_is_bounded_by_resource_limits(rclpy, msgs):
    """99,067 messages queued in 10 s behind a slow subscriber (issue 13): KEEP_ALL now
    stops at DDS's max_samples (Fast DDS's default, 5000), and publish never blocks."""
    from labkit.rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
    from labkit.rclpy.subscription import KEEP_ALL_MAX_SAMPLES
    assert KEEP_ALL_MAX_SAMPLES == 5000
    node = rclpy.create_node('slow')
    got = []
    keep_all = QoSProfile(history=HistoryPolicy.KEEP_ALL)
    sub = node.create_subscription(msgs.Int32, '/flood', lambda m: got.append(m.data), keep_all)
    pub = node.create_publisher(msgs.Int32, '/flood', keep_all)
    for i in range(KEEP_ALL_MAX_SAMPLES + 700):
        pub.publish(msgs.Int32(data=i))          # returns at once, every time
    assert len(sub._queue) == KEEP_ALL_MAX_SAMPLES and sub.rejected == 700
    while len(got) < KEEP_ALL_MAX_SAMPLES:
        rclpy.spin_once(node, timeout_sec=0)
    assert got == list(range(KEEP_ALL_MAX_SAMPLES))   # the oldest kept, in order
    pub.publish(msgs.Int32(data=-1))                  # room again
    rclpy.spin_once(node, timeout_sec=0)
    assert got[-1] == -1
    # a KEEP_ALL transient-local publisher keeps a bounded history for late joiners
    latched = QoSProfile(history=HistoryPolicy.KEEP_ALL,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)
    pub2 = node.create_publisher(msgs.Int32, '/latched', latched)
    for i in range(KEEP_ALL_MAX_SAMPLES + 10):
        pub2.publish(msgs.Int32(data=i))
    assert len(pub2._endpoint.history) == KEEP_ALL_MAX_SAMPLES
