"""Under `labkit exec` (DDS on) nothing the bridge creates shows in a local count, list or
match: a publisher's get_subscription_count() counts subscriptions, never its own DDS
writer (which rides along in its matches for remote readers and for TRANSIENT_LOCAL).
Each subscription in another process counts once, as with real rmw."""
from tests.dds.test_real_peers import domain, done, labkit, line_from  # noqa: F401

COUNTS = """
from rclpy.qos import QoSProfile, DurabilityPolicy
from std_msgs.msg import String
from std_srvs.srv import Trigger
rclpy.init()
node = rclpy.create_node('counter')
want_remote = int(os.environ.get('WANT_REMOTE', '0'))
pubs = {}
for dur in (DurabilityPolicy.VOLATILE, DurabilityPolicy.TRANSIENT_LOCAL):
    q = QoSProfile(depth=10, durability=dur)
    topic = 'c_' + dur.name.lower()
    pubs[dur.name] = (topic, node.create_publisher(String, topic, q))
    node.create_subscription(String, topic, lambda m: None, q)
    node.create_subscription(String, topic, lambda m: None, q)
node.create_service(Trigger, 'trig', lambda req, resp: resp)
client = node.create_client(Trigger, 'trig')
spin_until(node, lambda: all(node.count_subscribers(t) >= 2 + want_remote
                             for t, _ in pubs.values()), 10)
spin_until(node, lambda: False, 1.0)   # the bridge's DDS writers are made by now
for name, (topic, pub) in pubs.items():
    print(name, pub.get_subscription_count(), node.count_subscribers(topic),
          len(node.get_subscriptions_info_by_topic(topic)), node.count_publishers(topic),
          len(node.get_publishers_info_by_topic(topic)), flush=True)
print('service', client.service_is_ready(), node.count_services() if hasattr(node, 'count_services') else '-',
      len([n for n, _ in node.get_service_names_and_types() if n == '/trig']), flush=True)
print('nodes', *sorted(node.get_node_names()), flush=True)
"""

REMOTE_SUB = """
from rclpy.qos import QoSProfile, DurabilityPolicy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('far_listener')
for dur in (DurabilityPolicy.VOLATILE, DurabilityPolicy.TRANSIENT_LOCAL):
    for _ in range(2):
        node.create_subscription(String, 'c_' + dur.name.lower(), lambda m: None,
                                 QoSProfile(depth=10, durability=dur))
print('ready', flush=True)
spin_until(node, lambda: os.path.exists(os.environ['STOP_FILE']), 40)
"""


def _rows(out):
    return [line.split() for line in out.splitlines()]


def test_own_dds_writer_is_no_subscriber(tmp_path, domain):
    result = done(labkit(tmp_path, 'counts', COUNTS, domain))
    assert result.returncode == 0, result.stderr
    rows = _rows(result.stdout)
    # subscriptions, count_subscribers, their endpoint info, publishers, their info
    assert rows[:2] == [['VOLATILE', '2', '2', '2', '1', '1'],
                        ['TRANSIENT_LOCAL', '2', '2', '2', '1', '1']], result.stdout
    assert rows[2][0] == 'service' and rows[2][1] == 'True' and rows[2][-1] == '1'
    assert rows[3] == ['nodes', 'counter']


def test_each_remote_subscription_counts_once(tmp_path, domain):
    stop = tmp_path / 'stop'
    far = labkit(tmp_path, 'far', REMOTE_SUB, domain, env_extra={'STOP_FILE': str(stop)})
    try:
        assert 'ready' in line_from(far.stdout, lambda line: 'ready' in line, 20)
        result = done(labkit(tmp_path, 'counts', COUNTS, domain,
                             env_extra={'WANT_REMOTE': '2'}))
    finally:
        stop.write_text('')
        done(far)
    assert result.returncode == 0, result.stderr
    rows = _rows(result.stdout)
    assert rows[:2] == [['VOLATILE', '4', '4', '4', '1', '1'],
                        ['TRANSIENT_LOCAL', '4', '4', '4', '1', '1']], result.stdout
