"""What real `ros2 node info` / `topic info -v` / `service list` / `action info` read
about labkit's nodes, through the same rclpy graph API ros2cli calls, next to what
they read about an identical real rclpy node.

The same program (a publisher each of a plain, a latched, a best-effort and a
deadline/lifespan/liveliness QoS, two subscriptions, a service, a client, an action
server and an action client) runs twice on one domain: under `labkit exec` as
/lk/twin and under real rclpy (Jazzy, Fast DDS) as /real/twin. A third, real rclpy
process reads both through the graph API and `ros_discovery_info`; everything it reads
about /lk/twin must equal what it reads about /real/twin, except what only Jazzy has
(the get_type_description service). labkit's own `ros2 node info` of the real node
must list what real rclpy lists. test_real_peers.py covers node names and
publishers-by-node; this file covers the rest of what the real verbs print."""
import json
import subprocess
import sys

import pytest

from tests.dds.test_real_peers import (REPO, ROSREF, _domains, _env, finish, labkit,
                                       labkit_ros2, needs_rosref, real)

TWIN = """
from rclpy.action import ActionClient, ActionServer
from rclpy.duration import Duration
from rclpy.qos import QoSProfile, DurabilityPolicy, HistoryPolicy, ReliabilityPolicy, \\
    LivelinessPolicy
from std_msgs.msg import String
from geometry_msgs.msg import Twist
from std_srvs.srv import SetBool, Trigger
SHARE = '__SHARE__'
if SHARE:      # labkit reads test_msgs from its .action file
    from labkit.interfaces.registry import add_share_path
    add_share_path(SHARE)
from test_msgs.action import Fibonacci

rclpy.init(args=[])
node = rclpy.create_node('twin', namespace='__NS__')
node.create_publisher(String, 'chatter', 10)
node.create_publisher(String, 'latched', QoSProfile(
    depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
node.create_publisher(Twist, 'cmd_vel', QoSProfile(
    depth=5, reliability=ReliabilityPolicy.BEST_EFFORT))
node.create_publisher(String, 'timed', QoSProfile(
    depth=3, deadline=Duration(seconds=1), lifespan=Duration(seconds=2),
    liveliness=LivelinessPolicy.AUTOMATIC, liveliness_lease_duration=Duration(seconds=3)))
node.create_subscription(String, 'heard', lambda m: None, 10)
node.create_subscription(Twist, 'everything', lambda m: None,
                         QoSProfile(history=HistoryPolicy.KEEP_ALL))
node.create_service(SetBool, 'set_flag', lambda req, resp: resp)
node.create_client(Trigger, 'trigger')
ActionServer(node, Fibonacci, 'fibonacci', lambda goal: Fibonacci.Result())
ActionClient(node, Fibonacci, 'other_fibonacci')
import json
last = [None]
def own_gids():      # what this process says of its own endpoints, each time it changes
    own = {t: [bytes(i.endpoint_gid).hex() for i in node.get_publishers_info_by_topic(t)
               + node.get_subscriptions_info_by_topic(t)] for t in ('chatter', 'heard')}
    if own != last[0]:
        last[0] = own
        print('own', json.dumps(own), flush=True)
node.create_timer(0.1, own_gids)
spin_until(node, lambda: False, 60)     # the test ends it
"""

# The real rclpy process that reads both twins the way ros2cli's verbs do.
READER = """
import json
from rclpy.action import graph as action_graph

rclpy.init(args=[])
node = rclpy.create_node('graph_reader')
def hexgid(seq):
    return bytes(seq).hex()

def by_node(ns):
    calls = {
        'publishers': node.get_publisher_names_and_types_by_node,
        'subscribers': node.get_subscriber_names_and_types_by_node,
        'services': node.get_service_names_and_types_by_node,
        'clients': node.get_client_names_and_types_by_node,
        'action_servers': lambda n, s: action_graph.get_action_server_names_and_types_by_node(
            node, n, s),
        'action_clients': lambda n, s: action_graph.get_action_client_names_and_types_by_node(
            node, n, s),
    }
    try:
        return {k: sorted([n, t] for n, t in f('twin', ns)) for k, f in calls.items()}
    except Exception as e:      # the node is not known yet
        return None

def endpoint(info):
    q = info.qos_profile
    return {'node_name': info.node_name, 'node_namespace': info.node_namespace,
            'topic_type': info.topic_type, 'topic_type_hash': str(info.topic_type_hash),
            'endpoint_type': info.endpoint_type.name, 'gid': hexgid(info.endpoint_gid),
            'history': q.history.name, 'depth': q.depth, 'reliability': q.reliability.name,
            'durability': q.durability.name, 'liveliness': q.liveliness.name,
            'deadline': q.deadline.nanoseconds, 'lifespan': q.lifespan.nanoseconds,
            'lease': q.liveliness_lease_duration.nanoseconds}

NS = ('/lk', '/real')
TOPICS = ('chatter', 'latched', 'cmd_vel', 'timed', 'heard', 'everything',
          'fibonacci/_action/feedback', 'fibonacci/_action/status')
def complete():
    for ns in NS:
        lists = by_node(ns)
        if not lists or len(lists['publishers']) < 6 or len(lists['subscribers']) < 2 \\
                or not lists['action_servers'] or not lists['action_clients'] \\
                or not lists['clients'] or len(lists['services']) < 7:
            return False
        if any(node.count_publishers(f'{ns}/{t}') + node.count_subscribers(f'{ns}/{t}') == 0
               for t in TOPICS):
            return False
    return True

seen = spin_until(node, complete, 30)
spin_until(node, lambda: False, 0.5)    # late endpoints of a participant
out = {'complete': seen}
for ns in NS:
    out[ns] = {
        'by_node': by_node(ns),
        'endpoints': {t: [endpoint(i) for i in node.get_publishers_info_by_topic(f'{ns}/{t}')
                          + node.get_subscriptions_info_by_topic(f'{ns}/{t}')]
                      for t in TOPICS},
        'counts': {t: [node.count_publishers(f'{ns}/{t}'), node.count_subscribers(f'{ns}/{t}')]
                   for t in TOPICS},
        'service_types': sorted([n, t] for n, t in node.get_service_names_and_types()
                                if n.startswith(ns + '/')),
        'actions': sorted([n, t] for n, t in action_graph.get_action_names_and_types(node)
                          if n.startswith(ns + '/')),
    }
print(json.dumps(out))
"""

# ros_discovery_info as it is on the wire, read with plain Cyclone (rclpy cannot: it
# would name the DDS topic rt/ros_discovery_info or /ros_discovery_info)
DISCOVERY_INFO = """
import json, sys, time
from cyclonedds.core import SampleState, ViewState, InstanceState
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.qos import Qos, Policy
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds._clayer import ddspy_take
from labkit.dds import config, discovery, wire
domain_id = int(sys.argv[1])
domain = Domain(domain_id, config.cyclone_xml(True))
participant = DomainParticipant(domain_id)
reader = DataReader(participant, Topic(participant, discovery.TOPIC,
                                       wire.raw_type(discovery.DDS_TYPE)),
                    qos=Qos(Policy.Reliability.Reliable(100_000_000),
                            Policy.Durability.TransientLocal, Policy.History.KeepLast(64)))
nodes, end = {}, time.monotonic() + 20
mask = SampleState.Any | ViewState.Any | InstanceState.Any
while time.monotonic() < end and not {'/lk/twin', '/real/twin'} <= set(nodes):
    out = ddspy_take(reader._ref, mask, 64)
    for data, info in ([] if isinstance(out, int) else out):
        if info.valid_data:
            for ns, name, readers, writers in discovery.decode(bytes(data))[1]:
                nodes[ns.rstrip('/') + '/' + name] = [[g.hex() for g in readers],
                                                      [g.hex() for g in writers]]
    time.sleep(0.05)
print(json.dumps(nodes))
"""


def _mask(value, ns):
    """A reading of one twin with its namespace written as /NS (name lists re-sorted)."""
    value = json.loads(json.dumps(value).replace(f'"{ns}/', '"/NS/').replace(f'"{ns}"', '"/NS"'))
    value["by_node"] = {k: sorted(v) for k, v in value["by_node"].items()}
    return value


@pytest.fixture(scope="module")
def twins(tmp_path_factory):
    """Both twins up; (the reader's findings, labkit's `ros2 node info /real/twin`)."""
    if not ROSREF.exists():
        pytest.skip("no real-ROS reference venv .venv-rosref (real rclpy wheels: Linux x86_64, CPython 3.11/3.12 only; make setup builds it there)")
    tmp_path = tmp_path_factory.mktemp("twins")
    domain = next(_domains) % 200 + 20
    share = tmp_path / "share" / "test_msgs" / "action"
    share.mkdir(parents=True)
    share.joinpath("Fibonacci.action").write_text(
        (ROSREF.parent.parent / "share" / "test_msgs" / "action" / "Fibonacci.action").read_text())
    lk = labkit(tmp_path, "lk_twin", TWIN.replace("__NS__", "/lk").replace(
        "__SHARE__", str(tmp_path / "share")), domain)
    twin_real = real(tmp_path, "real_twin", TWIN.replace("__NS__", "/real").replace(
        "__SHARE__", ""), domain)
    found, info = {}, None
    try:
        out, err = finish(real(tmp_path, "reader", READER, domain), timeout=60)
        assert out.strip(), err
        found.update(json.loads(out.strip().splitlines()[-1]))
        assert found["complete"], out + err
        raw = subprocess.run([sys.executable, "-c", DISCOVERY_INFO, str(domain)],
                             env=_env(domain, PYTHONPATH=str(REPO)), capture_output=True,
                             text=True, timeout=40)
        assert raw.stdout.strip(), raw.stderr
        found["discovery_info"] = json.loads(raw.stdout)
        info = labkit_ros2(domain, "node", "info", "/real/twin", timeout=40)
        found["labkit_service_list"] = labkit_ros2(domain, "service", "list", "-t",
                                                   timeout=40).stdout
    finally:
        for ns, proc in (("/lk", lk), ("/real", twin_real)):
            proc.terminate()
            out, err = finish(proc)
            own = [line for line in out.splitlines() if line.startswith("own ")]
            found.setdefault("own", {})[ns] = json.loads(own[-1][4:]) if own else err
    yield found, info


JAZZY_ONLY = "/NS/twin/get_type_description"   # Jazzy's nodes have it; Humble's do not
PARAMETER_SERVICES = ["describe_parameters", "get_parameter_types", "get_parameters",
                      "list_parameters", "set_parameters", "set_parameters_atomically"]


def _without_gid(endpoints):
    return [{k: v for k, v in e.items() if k != "gid"} for e in endpoints]


@needs_rosref
def test_topic_info_verbose_reads_labkit_endpoints_as_a_real_nodes(twins):
    """get_publishers_info_by_topic / get_subscriptions_info_by_topic (`ros2 topic info
    -v`): node, namespace, type, RIHS01 type hash, endpoint type and every QoS field
    rclpy reports (a remote endpoint's history and depth are UNKNOWN/0 for both) equal
    the real twin's; count_publishers / count_subscribers too."""
    found, _ = twins
    lk, ref = _mask(found["/lk"], "/lk"), _mask(found["/real"], "/real")
    for topic, endpoints in lk["endpoints"].items():
        assert len(endpoints) == 1, (topic, endpoints)
        assert _without_gid(endpoints) == _without_gid(ref["endpoints"][topic]), topic
    assert lk["counts"] == ref["counts"]
    assert lk["counts"]["chatter"] == [1, 0] and lk["counts"]["heard"] == [0, 1]
    ep = {t: e[0] for t, e in lk["endpoints"].items()}
    # what the real verb prints for labkit: a real hash (INVALID without one), the QoS given
    assert ep["chatter"]["topic_type_hash"] == \
        "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"
    for topic in ("cmd_vel", "fibonacci/_action/feedback", "fibonacci/_action/status"):
        assert ep[topic]["topic_type_hash"].startswith("RIHS01_"), topic
    assert ep["fibonacci/_action/status"]["durability"] == "TRANSIENT_LOCAL"
    assert (ep["chatter"]["node_name"], ep["chatter"]["node_namespace"]) == ("twin", "/NS")
    assert [ep[t]["endpoint_type"] for t in ("chatter", "heard")] == ["PUBLISHER", "SUBSCRIPTION"]
    assert (ep["chatter"]["history"], ep["chatter"]["depth"]) == ("UNKNOWN", 0)
    assert ep["latched"]["durability"] == "TRANSIENT_LOCAL"
    assert ep["cmd_vel"]["reliability"] == "BEST_EFFORT"
    assert (ep["timed"]["deadline"], ep["timed"]["lifespan"], ep["timed"]["lease"]) == \
        (10**9, 2 * 10**9, 3 * 10**9)


@needs_rosref
def test_endpoint_gids_are_the_ones_labkits_ros_discovery_info_names(twins):
    """Each gid real rclpy reports for a labkit endpoint is a writer (publisher) or reader
    (subscription) gid of /lk/twin in labkit's ros_discovery_info, as for the real twin,
    and the one labkit's own get_publishers_info_by_topic names (its DDS GUID); the node owns one reader and one writer fewer than the real one (the request reader
    and reply writer of get_type_description, which Humble does not have)."""
    found, _ = twins
    info = found["discovery_info"]
    for ns in ("/lk", "/real"):
        readers, writers = info[ns + "/twin"]
        for topic, endpoints in found[ns]["endpoints"].items():
            for e in endpoints:
                assert len(e["gid"]) == 32, e          # Jazzy's 16-byte gid
                owned = writers if e["endpoint_type"] == "PUBLISHER" else readers
                assert e["gid"] in owned, (ns, topic, e["gid"])
    for ns in ("/lk", "/real"):      # the process itself names the same gids
        for topic, gids in found["own"][ns].items():
            assert gids == [e["gid"] for e in found[ns]["endpoints"][topic]], (ns, topic)
    lk_readers, lk_writers = info["/lk/twin"]
    real_readers, real_writers = info["/real/twin"]
    assert (len(lk_readers), len(lk_writers)) == (len(real_readers) - 1, len(real_writers) - 1)
    assert len(set(lk_readers + lk_writers)) == len(lk_readers) + len(lk_writers)


@needs_rosref
def test_node_info_lists_of_a_labkit_node_equal_a_real_nodes(twins):
    """What `ros2 node info` reads (publishers, subscribers, service servers and clients,
    action servers and clients by node) and what `ros2 service list -t` / `action list
    -t` read: the same for /lk/twin as for /real/twin, except get_type_description."""
    found, _ = twins
    lk, ref = _mask(found["/lk"], "/lk"), _mask(found["/real"], "/real")
    services = [s for s in ref["by_node"]["services"] if s[0] != JAZZY_ONLY]
    assert len(services) == len(ref["by_node"]["services"]) - 1
    assert lk["by_node"] == dict(ref["by_node"], services=services)
    for name in PARAMETER_SERVICES:
        assert ["/NS/twin/" + name, ["rcl_interfaces/srv/" + "".join(
            w.capitalize() for w in name.split("_"))]] in lk["by_node"]["services"]
    assert lk["by_node"]["action_servers"] == [["/NS/fibonacci", ["test_msgs/action/Fibonacci"]]]
    assert lk["by_node"]["action_clients"] == [["/NS/other_fibonacci",
                                                ["test_msgs/action/Fibonacci"]]]
    assert ["/NS/trigger", ["std_srvs/srv/Trigger"]] in lk["by_node"]["clients"]
    assert lk["service_types"] == [s for s in ref["service_types"] if s[0] != JAZZY_ONLY]
    assert lk["actions"] == ref["actions"]


def _sections(text):
    """`ros2 node info` output as {section: [(name, type)]}."""
    sections, current = {}, None
    for line in text.splitlines():
        if line.startswith("  ") and not line.startswith("    "):
            current = sections.setdefault(line.strip().rstrip(":"), [])
        elif line.startswith("    ") and current is not None:
            name, _, types = line.strip().partition(": ")
            current.append([name, types.split(", ")])
    return sections


@needs_rosref
def test_labkit_node_info_of_the_real_node_lists_what_real_rclpy_lists(twins):
    """labkit's `ros2 node info /real/twin` (another terminal) lists, section by section,
    what real rclpy's graph API gives for the real node (get_type_description included:
    it is there on the graph)."""
    found, info = twins
    assert info.returncode == 0, info.stderr
    assert info.stdout.startswith("/real/twin\n")
    got = _sections(info.stdout)
    ref = found["/real"]["by_node"]
    for section, key in (("Subscribers", "subscribers"), ("Publishers", "publishers"),
                         ("Service Servers", "services"), ("Service Clients", "clients"),
                         ("Action Servers", "action_servers"),
                         ("Action Clients", "action_clients")):
        expected = [e for e in ref[key] if "/_action/" not in e[0]]   # node info hides them
        assert got.get(section, []) == expected, section
    assert ["/real/twin/get_type_description",
            ["type_description_interfaces/srv/GetTypeDescription"]] in got["Service Servers"]


@needs_rosref
def test_labkit_service_list_of_the_real_node_lists_what_real_rclpy_lists(twins):
    """labkit's `ros2 service list -t` names the real node's services as real rclpy's
    get_service_names_and_types does: its client-only /real/trigger included (rmw lists
    every rq/rr topic), and the action's hidden services left out."""
    found, _ = twins
    got = [line for line in found["labkit_service_list"].splitlines()
           if line.startswith("/real/")]
    expected = [f"{name} [{', '.join(types)}]" for name, types in found["/real"]["service_types"]
                if "/_action/" not in name]
    assert got == expected
    assert "/real/trigger [std_srvs/srv/Trigger]" in got
