"""The graph view on a live labkit graph: queried through the rclpy Node API."""
import threading
import xml.etree.ElementTree as ET

import pytest

rclpy = pytest.importorskip("labkit.rclpy")
if not hasattr(rclpy, "init"):
    pytest.skip("labkit.rclpy core not there yet", allow_module_level=True)

from labkit.interfaces import get_type  # noqa: E402
from labkit.viz import graph_view  # noqa: E402
from labkit.viz.graph_view import GraphView, concept_figure  # noqa: E402

String = get_type("std_msgs/msg/String")


@pytest.fixture
def context():
    ctx = rclpy.context.Context()
    rclpy.init(args=[], context=ctx)
    nodes = []

    def make(name, **kw):
        n = rclpy.create_node(name, context=ctx, **kw)
        nodes.append(n)
        return n
    yield make
    for n in nodes:
        n.destroy_node()
    ctx.try_shutdown()


def all_node_names():
    ctx = rclpy.context.Context()
    rclpy.init(args=[], context=ctx)
    probe = rclpy.create_node("_probe", context=ctx)
    try:
        return sorted(n for n, _ in probe.get_node_names_and_namespaces())
    finally:
        probe.destroy_node()
        ctx.try_shutdown()


def test_talker_listener_graph(context):
    context("talker").create_publisher(String, "chatter", 10)
    context("listener", namespace="/demo").create_subscription(String, "/chatter", lambda m: None, 10)
    context("lonely").create_publisher(String, "nobody_listens", 10)
    gv = GraphView()
    assert gv.edges() == [("/chatter", "/demo/listener"), ("/talker", "/chatter")]
    view = gv.view()
    assert view.names("node") == ["/demo/listener", "/lonely", "/talker"]
    snap = gv.snapshot()
    # every rclpy node publishes /rosout and /parameter_events; the view hides them
    assert ("/rosout", ("rcl_interfaces/msg/Log",)) in snap.node("/talker").publishers
    # the viewer's own hidden node is neither in the picture nor left on the graph
    assert "/_labkit_graph_view" not in snap.node_names()
    assert "_labkit_graph_view" not in all_node_names()
    ET.fromstring(gv.svg().encode())
    loud = GraphView(hide_debug=False, hide_dead_sinks=False, hide_leaf_topics=False)
    assert ("/talker", "/rosout") in loud.edges()
    assert ("/lonely", "/nobody_listens") in loud.edges()


def test_services_and_actions_live(context):
    add_two_ints = get_type("example_interfaces/srv/AddTwoInts")
    server = context("server")
    server.create_service(add_two_ints, "add_two_ints", lambda req, resp: resp)
    context("client").create_client(add_two_ints, "add_two_ints")
    edges = GraphView(services=True).edges()
    assert ("/client", "/add_two_ints") in edges and ("/add_two_ints", "/server") in edges
    # parameter services of every node are debug
    assert not [e for e in edges if "parameters" in e[0] + e[1]]

    from labkit.rclpy.action import ActionClient, ActionServer
    fibonacci = get_type("example_interfaces/action/Fibonacci")
    action_server = ActionServer(context("fib_server"), fibonacci, "fibonacci",
                                 lambda gh: fibonacci.Result())
    action_client = ActionClient(context("fib_client"), fibonacci, "fibonacci")
    try:
        assert GraphView(actions=True).view().names("action") == ["/fibonacci"]
        assert ("/fib_client", "/fibonacci") in GraphView(actions=True).edges()
        expanded = GraphView(actions="expand").edges()
        assert ("/fib_server", "/fibonacci/_action/feedback") in expanded
        assert ("/fibonacci/_action/send_goal", "/fib_server") in expanded
        # without the action switch rqt_graph shows its feedback and status topics
        plain = GraphView(services=True).edges()
        assert ("/fib_server", "/fibonacci/_action/status") in plain
        assert ("/fibonacci/_action/feedback", "/fib_client") in plain
        assert not [e for e in plain if "send_goal" in e[0] + e[1]]   # hidden service
    finally:
        action_client.destroy()
        action_server.destroy()


def test_qos_incompatibility_found_through_the_node_api(context):
    from labkit.rclpy.qos import QoSProfile, ReliabilityPolicy
    best_effort = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    context("camera").create_publisher(String, "image", best_effort)
    context("viewer").create_subscription(String, "image", lambda m: None, 10)   # reliable
    context("logger").create_subscription(String, "image", lambda m: None, best_effort)
    snap = GraphView().snapshot()
    assert snap.qos_incompatible == (("/image", "/camera", "/viewer"),)
    assert GraphView().view().vertex("t_/image").qos_incompatible == (("/camera", ("/viewer",)),)
    assert 'stroke="red"' in GraphView().svg()


def test_same_graph_same_svg(context):
    context("talker").create_publisher(String, "chatter", 10)
    context("listener").create_subscription(String, "chatter", lambda m: None, 10)
    assert GraphView().svg() == GraphView().svg()


@pytest.mark.parametrize("kind, expected", [
    ("topic", [("/chatter", "/listener_1"), ("/chatter", "/listener_2"),
               ("/talker_1", "/chatter"), ("/talker_2", "/chatter")]),
    ("service", [("/add_two_ints", "/add_two_ints_server"),
                 ("/add_two_ints_client_1", "/add_two_ints"),
                 ("/add_two_ints_client_2", "/add_two_ints")]),
])
def test_concept_figures(kind, expected):
    before = all_node_names()
    fig = concept_figure(kind)
    assert fig.edges() == expected
    assert all_node_names() == before          # everything was torn down
    ET.fromstring(fig.svg().encode())
    assert fig.svg() == concept_figure(kind).svg()


def test_concept_action_figure():
    fig = concept_figure("action")
    parts = "/fibonacci/_action/"
    edges = fig.edges()
    for service in ("send_goal", "get_result", "cancel_goal"):
        assert ("/fibonacci_action_client", parts + service) in edges
        assert (parts + service, "/fibonacci_action_server") in edges
    for topic in ("feedback", "status"):
        assert ("/fibonacci_action_server", parts + topic) in edges
        assert (parts + topic, "/fibonacci_action_client") in edges
    assert len(edges) == 10
    with pytest.raises(ValueError):
        concept_figure("parameter")


def test_concept_figure_ignores_the_readers_graph(context):
    context("talker_1").create_publisher(String, "other", 10)
    context("someone").create_subscription(String, "other", lambda m: None, 10)
    assert ("/talker_1", "/other") not in concept_figure("topic").edges()


def test_live_widget_follows_the_graph(context, monkeypatch):
    monkeypatch.setattr(graph_view, "POLL_PERIOD_S", 0.01)
    gv = GraphView()
    w = gv.widget()
    assert "/talker" not in w.value
    updated = threading.Event()
    w.observe(lambda change: updated.set(), "value")
    gv.start()
    try:
        assert gv.live
        context("talker").create_publisher(String, "chatter", 10)
        context("listener").create_subscription(String, "chatter", lambda m: None, 10)
        assert updated.wait(10.0)
        assert "/talker" in w.value and "/chatter" in w.value
    finally:
        gv.stop()
    assert not gv.live
    assert "_labkit_graph_view" not in all_node_names()


def test_rqt_graph_executable(context):
    from labkit import executables, process
    executables.register("rqt_graph", "rqt_graph", "labkit.viz.graph_view:main")
    try:
        context("talker").create_publisher(String, "chatter", 10)
        context("listener").create_subscription(String, "chatter", lambda m: None, 10)
        p = process.start(["rqt_graph", "rqt_graph"])
        names = all_node_names()
        rqt = [n for n in names if n.startswith("rqt_gui_py_node_")]
        assert len(rqt) == 1
        # rqt_graph does not draw itself
        assert GraphView().edges() == [("/chatter", "/listener"), ("/talker", "/chatter")]
        assert ("/" + rqt[0]) in GraphView(hide_debug=False).view().names("node")
        # it follows the graph in live time only (a poller must not stall virtual time)
        from labkit.graph import world
        pollers = [t for t in threading.enumerate() if t.name == "labkit-graph-view"]
        assert len(pollers) == (1 if world.mode() == "live" else 0)
        p.stop()
        assert not [t for t in threading.enumerate() if t.name == "labkit-graph-view"]
        assert not [n for n in all_node_names() if n.startswith("rqt_gui_py_node_")]
    finally:
        executables.unregister_package("rqt_graph")
