"""labkit.dds without a network: names, type names, QoS mapping, the request header,
ros_discovery_info byte by byte (Humble's 24-byte gids; no Humble wheels exist to
compare against, so the layout is checked against labkit's own CDR of Humble's
rmw_dds_common messages and against hand-written bytes)."""
import pytest

from labkit.dds import config, discovery, wire

GUID_P = bytes(range(1, 13)) + b"\x00\x00\x01\xc1"
GUID_R = bytes(range(1, 13)) + b"\x00\x00\x12\x04"
GUID_W = bytes(range(1, 13)) + b"\x00\x00\x13\x03"


def test_humble_gid_is_the_guid_and_eight_zero_bytes():
    assert discovery.make_gid(GUID_P) == GUID_P + bytes(8)
    assert len(discovery.make_gid(GUID_P)) == 24
    assert discovery.make_gid(GUID_P, discovery.JAZZY_GID) == GUID_P
    assert discovery.gid_size(None) == 24 and discovery.gid_size("humble") == 24
    assert discovery.gid_size("jazzy") == 16


def test_participant_entities_info_humble_bytes():
    data = discovery.encode(GUID_P, [("/", "talker", [GUID_R], [GUID_W])])
    expected = (b"\x00\x01\x00\x00"                       # CDR little endian
                + GUID_P + bytes(8)                        # gid: char[24]
                + b"\x01\x00\x00\x00"                      # one node
                + b"\x02\x00\x00\x00/\x00" + b"\x00\x00"   # namespace "/" + padding
                + b"\x07\x00\x00\x00talker\x00" + b"\x00"  # name "talker" + padding
                + b"\x01\x00\x00\x00" + GUID_R + bytes(8)  # reader_gid_seq
                + b"\x01\x00\x00\x00" + GUID_W + bytes(8))  # writer_gid_seq
    assert data == expected
    assert discovery.decode(data) == (GUID_P, [("/", "talker", [GUID_R], [GUID_W])])


def test_encoding_matches_labkit_cdr_of_humbles_message_definitions():
    from labkit.interfaces import get_type, serialize
    P = get_type("rmw_dds_common/msg/ParticipantEntitiesInfo")
    N = get_type("rmw_dds_common/msg/NodeEntitiesInfo")
    G = get_type("rmw_dds_common/msg/Gid")

    def gid(g):
        return G(data=list(g + bytes(8)))
    msg = P(gid=gid(GUID_P), node_entities_info_seq=[
        N(node_namespace="/ns", node_name="a", reader_gid_seq=[gid(GUID_R)],
          writer_gid_seq=[gid(GUID_W), gid(GUID_W)]),
        N(node_namespace="/", node_name="bb", reader_gid_seq=[], writer_gid_seq=[])])
    ours = discovery.encode(GUID_P, [("/ns", "a", [GUID_R], [GUID_W, GUID_W]),
                                     ("/", "bb", [], [])])
    assert ours == serialize(msg)


def test_jazzy_layout_decodes_too():
    data = discovery.encode(GUID_P, [("/", "n", [GUID_R], [])], discovery.JAZZY_GID)
    assert len(data) == 4 + 16 + 4 + 6 + 2 + 6 + 2 + 4 + 16 + 4
    assert discovery.decode(data) == (GUID_P, [("/", "n", [GUID_R], [])])
    with pytest.raises(discovery.DecodeError):
        discovery.decode(b"\x00\x01\x00\x00" + b"\x01" * 7)


def test_names_and_type_names_on_the_wire():
    assert wire.topic_to_dds("/chatter") == "rt/chatter"
    assert wire.request_topic("/add_two_ints") == "rq/add_two_intsRequest"
    assert wire.reply_topic("/add_two_ints") == "rr/add_two_intsReply"
    assert wire.type_to_dds("std_msgs/msg/String") == "std_msgs::msg::dds_::String_"
    assert (wire.type_to_dds("std_srvs/srv/SetBool", "_Request")
            == "std_srvs::srv::dds_::SetBool_Request_")
    assert wire.type_from_dds("std_srvs::srv::dds_::SetBool_Response_") == (
        "std_srvs/srv/SetBool", "Response")
    assert wire.type_from_dds("example_interfaces::action::dds_::Fibonacci_SendGoal_Request_") \
        == ("example_interfaces/action/Fibonacci_SendGoal", "Request")
    assert wire.type_from_dds("turtlesim::action::dds_::RotateAbsolute_FeedbackMessage_") == (
        "turtlesim/action/RotateAbsolute_FeedbackMessage", None)
    assert wire.type_from_dds("DDS::Anything") == (None, None)
    assert wire.entity_from_dds("rt/turtle1/pose") == ("rt", "/turtle1/pose")
    assert wire.entity_from_dds("rq/spawnRequest") == ("rq", "/spawn")
    assert wire.entity_from_dds("ros_discovery_info") == (None, None)


def test_rmw_cyclonedds_request_header():
    payload = b"\x00\x01\x00\x00" + (42).to_bytes(8, "little")
    framed = wire.frame_request(0x1122334455667788, 7, payload)
    assert framed[:4] == b"\x00\x01\x00\x00"
    assert framed[4:12] == (0x1122334455667788).to_bytes(8, "little")
    assert framed[12:20] == (7).to_bytes(8, "little")
    assert wire.unframe_request(framed) == (0x1122334455667788, 7, payload)


def test_qos_is_mapped_one_to_one():
    from cyclonedds.qos import Policy
    from labkit.rclpy.qos import QoSProfile, DurabilityPolicy, ReliabilityPolicy
    from labkit.rclpy.duration import Duration
    q = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                   reliability=ReliabilityPolicy.BEST_EFFORT, deadline=Duration(seconds=2))
    dds = wire.qos_to_dds(q)
    assert dds[Policy.Durability] == Policy.Durability.TransientLocal
    assert dds[Policy.Reliability] == Policy.Reliability.BestEffort
    assert dds[Policy.History] == Policy.History.KeepLast(1)
    assert dds[Policy.Deadline] == Policy.Deadline(2_000_000_000)
    back = wire.qos_from_dds(dds)
    assert (back.durability, back.reliability, back.depth) == (
        DurabilityPolicy.TRANSIENT_LOCAL, ReliabilityPolicy.BEST_EFFORT, 1)
    assert back.deadline.nanoseconds == 2_000_000_000


@pytest.mark.parametrize("value,line", [
    ("abc", "failed to get default domain id: ROS_DOMAIN_ID is not an integral number"),
    ("-3", "failed to get default domain id: ROS_DOMAIN_ID is not an integral number"),
    ("300", "Domain id 300 is out of range: it must be from 0 to 232"),
])
def test_bad_domain_id_is_one_line(monkeypatch, value, line):
    monkeypatch.setenv("ROS_DOMAIN_ID", value)
    with pytest.raises(config.ConfigError) as e:
        config.domain_id()
    assert str(e.value) == line


def test_discovery_reach_from_the_environment(monkeypatch):
    for var in ("ROS_LOCALHOST_ONLY", "ROS_AUTOMATIC_DISCOVERY_RANGE"):
        monkeypatch.delenv(var, raising=False)
    assert config.localhost_only() is True                  # labkit's default
    monkeypatch.setenv("ROS_LOCALHOST_ONLY", "0")
    assert config.localhost_only() is False
    monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    assert config.localhost_only() is True
    monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "SUBNET")
    assert config.localhost_only() is False
    assert config.localhost_only(True) is True
    xml = config.cyclone_xml(True)
    assert '<NetworkInterface address="127.0.0.1"/>' in xml and "<AllowMulticast>false" in xml
    assert '<Peer address="127.0.0.1"/>' in xml


def test_loopback_sends_a_large_sample_in_bursts_a_default_socket_buffer_holds():
    """On loopback Cyclone sends at most 2/3 of Linux's default receive buffer of a
    sample at once (then what the reader asks for); on a LAN its defaults stay."""
    import re
    xml = config.cyclone_xml(True)
    burst = int(re.search(r"<MaxRexmit>(\d+)B</MaxRexmit>", xml).group(1))
    assert burst == 212992 * 2 // 3
    assert "<MaxInitTransmit>0</MaxInitTransmit>" in xml
    fragment = int(re.search(r"<FragmentSize>(\d+)B", xml).group(1))
    # whole fragments go out: the burst rounded up to fragments must still fit the buffer
    assert -(-burst // fragment) * fragment < 212992
    assert "BurstSize" not in config.cyclone_xml(False)


def test_connect_refuses_virtual_time_in_one_line():
    import labkit
    from labkit import dds
    assert labkit.time_mode() == "virtual"
    with pytest.raises(dds.ConnectError, match="virtual time stays in-process"):
        labkit.connect()
    assert not dds.is_connected()
    r = labkit.ros2("connect")
    assert r.returncode == 1 and r.stderr.count("\n") == 1


def test_graph_view_draws_remote_nodes_distinctly():
    """A node the bridge discovered (a RemoteNode) is an ordinary graph entry: rclpy's
    graph queries list it, and the graph view paints it green with class 'remote'."""
    import labkit
    from labkit.dds.bridge import RemoteNode
    from labkit.graph.registry import GRAPH, Endpoint, PUB
    from labkit.rclpy.qos import QoSProfile
    from labkit.viz.graph_view import GraphView
    from labkit import rclpy
    from labkit.interfaces import get_type
    String = get_type("std_msgs/msg/String")
    labkit.reset()
    rclpy.init()
    local = rclpy.create_node("local_listener")
    local.create_subscription(String, "chatter", lambda m: None, 10)
    remote = RemoteNode("robot_talker", "/", 0, bytes(16))
    with GRAPH.lock:
        GRAPH.nodes.append(remote)
        GRAPH.endpoints[PUB].setdefault("/chatter", []).append(
            Endpoint(PUB, "/chatter", "std_msgs/msg/String", remote, QoSProfile(depth=10)))
        GRAPH._rematch("/chatter")
        GRAPH._changed()
    assert ("robot_talker", "/") in local.get_node_names_and_namespaces()
    assert local.count_publishers("/chatter") == 1
    svg = GraphView().svg()
    assert '<g class="vertex node remote"><title>/robot_talker\n(remote: over DDS)' in svg
    assert '<g class="vertex node"><title>/local_listener' in svg
    labkit.reset()
    assert remote not in GRAPH.nodes
