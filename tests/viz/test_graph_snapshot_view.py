"""The graph view from plain snapshots: content, hiding rules, SVG, determinism."""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

from labkit.viz._graph_filter import ViewOptions, build_view, namespace_path
from labkit.viz._graph_model import GraphSnapshot
from labkit.viz.graph_view import GraphView

SVG_NS = "{http://www.w3.org/2000/svg}"
STD = {"publishers": {"/rosout": "rcl_interfaces/msg/Log",
                      "/parameter_events": "rcl_interfaces/msg/ParameterEvent"}}


def node(**kinds):
    """A node as rclpy makes it: /rosout and /parameter_events publishers, parameter services."""
    spec = {"publishers": dict(STD["publishers"])}
    for kind, entities in kinds.items():
        spec.setdefault(kind, {}).update(entities)
    return spec


def param_services(fqn):
    return {f"{fqn}/{s}": f"rcl_interfaces/srv/{t}" for s, t in (
        ("describe_parameters", "DescribeParameters"), ("get_parameter_types", "GetParameterTypes"),
        ("get_parameters", "GetParameters"), ("list_parameters", "ListParameters"),
        ("set_parameters", "SetParameters"), ("set_parameters_atomically", "SetParametersAtomically"))}


ACTION = "/turtle1/rotate_absolute"
TURTLESIM = {
    "/turtlesim": node(
        publishers={"/turtle1/pose": "turtlesim/msg/Pose", "/turtle1/color_sensor": "turtlesim/msg/Color",
                    f"{ACTION}/_action/feedback": "turtlesim/action/RotateAbsolute_FeedbackMessage",
                    f"{ACTION}/_action/status": "action_msgs/msg/GoalStatusArray"},
        subscribers={"/turtle1/cmd_vel": "geometry_msgs/msg/Twist"},
        services={"/spawn": "turtlesim/srv/Spawn", "/clear": "std_srvs/srv/Empty",
                  f"{ACTION}/_action/send_goal": "turtlesim/action/RotateAbsolute_SendGoal",
                  f"{ACTION}/_action/get_result": "turtlesim/action/RotateAbsolute_GetResult",
                  f"{ACTION}/_action/cancel_goal": "action_msgs/srv/CancelGoal",
                  **param_services("/turtlesim")},
        action_servers={ACTION: "turtlesim/action/RotateAbsolute"}),
    "/teleop_turtle": node(
        publishers={"/turtle1/cmd_vel": "geometry_msgs/msg/Twist"},
        subscribers={f"{ACTION}/_action/feedback": "turtlesim/action/RotateAbsolute_FeedbackMessage",
                     f"{ACTION}/_action/status": "action_msgs/msg/GoalStatusArray"},
        clients={f"{ACTION}/_action/send_goal": "turtlesim/action/RotateAbsolute_SendGoal",
                 f"{ACTION}/_action/get_result": "turtlesim/action/RotateAbsolute_GetResult",
                 f"{ACTION}/_action/cancel_goal": "action_msgs/srv/CancelGoal"},
        action_clients={ACTION: "turtlesim/action/RotateAbsolute"}),
    "/ns/pose_listener": node(subscribers={"/turtle1/pose": "turtlesim/msg/Pose"},
                              clients={"/spawn": "turtlesim/srv/Spawn"}),
    # `ros2 topic echo /turtle1/color_sensor`: a hidden CLI node
    "/_ros2cli_7": node(subscribers={"/turtle1/color_sensor": "turtlesim/msg/Color"}),
}


@pytest.fixture
def snap():
    return GraphSnapshot.from_dict(TURTLESIM)


def test_default_view_is_rqt_graphs(snap):
    view = build_view(snap)
    assert view.names("node") == ["/ns/pose_listener", "/teleop_turtle", "/turtlesim"]
    # color_sensor survives: the hidden echo node counts before "Debug" hides it (rqt order)
    # like rqt_graph, the action's feedback and status topics show: their last token is not hidden
    feedback, status = f"{ACTION}/_action/feedback", f"{ACTION}/_action/status"
    assert view.names("topic") == ["/turtle1/cmd_vel", "/turtle1/color_sensor", "/turtle1/pose",
                                   feedback, status]
    assert view.edges() == [
        ("/teleop_turtle", "/turtle1/cmd_vel"),
        ("/turtle1/cmd_vel", "/turtlesim"),
        ("/turtle1/pose", "/ns/pose_listener"),
        (feedback, "/teleop_turtle"),
        (status, "/teleop_turtle"),
        ("/turtlesim", "/turtle1/color_sensor"),
        ("/turtlesim", "/turtle1/pose"),
        ("/turtlesim", feedback),
        ("/turtlesim", status),
    ]
    assert view.names("service") == [] and view.names("action") == []
    assert view.clusters == {"/ns": "namespace", "/turtle1": "namespace",
                             ACTION: "namespace"}
    assert view.vertex("t_" + feedback).cluster == ("/turtle1", ACTION)
    topic = view.vertex("t_/turtle1/pose")
    assert topic.cluster == ("/turtle1",) and topic.types == ("turtlesim/msg/Pose",)


def test_show_debug_shows_rosout_params_hidden_nodes_and_action_topics(snap):
    view = build_view(snap, ViewOptions(hide_debug=False, hide_dead_sinks=False,
                                        hide_leaf_topics=False))
    assert "/_ros2cli_7" in view.names("node")
    topics = view.names("topic")
    for t in ("/rosout", "/parameter_events", f"{ACTION}/_action/feedback", f"{ACTION}/_action/status"):
        assert t in topics
    assert ("/turtle1/color_sensor", "/_ros2cli_7") in view.edges()


def test_dead_sinks_and_leaf_topics():
    snap = GraphSnapshot.from_dict({
        "/a": node(publishers={"/only_pub": "std_msgs/msg/String", "/shared": "std_msgs/msg/String"},
                   subscribers={"/only_sub": "std_msgs/msg/String"}),
        "/b": node(publishers={"/only_pub": "std_msgs/msg/String"},
                   subscribers={"/shared": "std_msgs/msg/String"}),
    })
    assert build_view(snap).names("topic") == ["/shared"]
    # /only_pub has two publishers (not a leaf) but nobody listens: a dead sink
    assert build_view(snap, ViewOptions(hide_dead_sinks=False)).names("topic") == ["/only_pub", "/shared"]
    # /only_sub has one connection: a leaf topic, but it has a subscriber
    assert build_view(snap, ViewOptions(hide_leaf_topics=False)).names("topic") == ["/only_sub", "/shared"]
    both = build_view(snap, ViewOptions(hide_leaf_topics=False, hide_dead_sinks=False))
    assert both.names("topic") == ["/only_pub", "/only_sub", "/shared"]
    # nodes stay even when all their topics are hidden
    assert build_view(snap).names("node") == ["/a", "/b"]


def test_debug_nodes_by_name():
    snap = GraphSnapshot.from_dict({
        "/talker": node(publishers={"/chatter": "std_msgs/msg/String"}),
        "/listener": node(subscribers={"/chatter": "std_msgs/msg/String"}),
        "/rqt_gui_py_node_123": node(subscribers={"/chatter": "std_msgs/msg/String"}),
        "/rviz2": node(), "/_hidden": node(), "/ns/_private": node(), "/_ns/visible": node(),
        "/transform_listener_impl_1": node(), "/labkit_canvas": node(),
    })
    assert build_view(snap).names("node") == ["/_ns/visible", "/listener", "/talker",
                                              "/transform_listener_impl_1"]
    assert build_view(snap).edges() == [("/chatter", "/listener"), ("/talker", "/chatter")]
    assert len(build_view(snap, ViewOptions(hide_debug=False)).names("node")) == 9


def test_clock_and_hidden_topics_are_debug():
    snap = GraphSnapshot.from_dict({
        "/sim": node(publishers={"/clock": "rosgraph_msgs/msg/Clock", "/_secret": "std_msgs/msg/String",
                                 "/a/_b/c": "std_msgs/msg/String"}),
        "/user": node(subscribers={"/clock": "rosgraph_msgs/msg/Clock", "/_secret": "std_msgs/msg/String",
                                   "/a/_b/c": "std_msgs/msg/String"}),
    })
    # rqt_graph looks at the last token only
    assert build_view(snap).names("topic") == ["/a/_b/c"]
    assert build_view(snap, ViewOptions(hide_debug=False)).names("topic") == ["/_secret", "/a/_b/c", "/clock"]


def test_parameter_events_hidden_in_any_namespace():
    snap = GraphSnapshot.from_dict({
        "/a": node(publishers={"/robot/parameter_events": "rcl_interfaces/msg/ParameterEvent"}),
        "/b": node(subscribers={"/robot/parameter_events": "rcl_interfaces/msg/ParameterEvent",
                                "/parameter_events": "rcl_interfaces/msg/ParameterEvent"}),
    })
    assert build_view(snap).names("topic") == []
    assert build_view(snap, ViewOptions(hide_debug=False)).names("topic") == [
        "/parameter_events", "/robot/parameter_events"]


def test_tf_grouped_or_hidden():
    snap = GraphSnapshot.from_dict({
        "/broadcaster": node(publishers={"/tf": "tf2_msgs/msg/TFMessage",
                                         "/tf_static": "tf2_msgs/msg/TFMessage"}),
        "/listener": node(subscribers={"/tf": "tf2_msgs/msg/TFMessage",
                                       "/tf_static": "tf2_msgs/msg/TFMessage"}),
    })
    grouped = build_view(snap)
    assert grouped.names("tf") == ["/tf"] and grouped.names("topic") == []
    assert grouped.edges() == [("/broadcaster", "/tf"), ("/tf", "/listener")]
    assert build_view(snap, ViewOptions(group_tf=False)).names("topic") == ["/tf", "/tf_static"]
    assert build_view(snap, ViewOptions(hide_tf=True)).edges() == []


def test_services_client_to_service_to_server(snap):
    view = build_view(snap, ViewOptions(services=True))
    # parameter services and the action's hidden services are debug
    assert view.names("service") == ["/clear", "/spawn"]
    assert ("/ns/pose_listener", "/spawn") in view.edges()
    assert ("/spawn", "/turtlesim") in view.edges()
    assert ("/clear", "/turtlesim") in view.edges()
    jazzy = GraphSnapshot.from_dict({"/n": node(services={
        "/n/get_type_description": "type_description_interfaces/srv/GetTypeDescription",
        "/n/get_parameters": "my_pkg/srv/NotAParameterService"})})
    assert build_view(jazzy, ViewOptions(services=True)).names("service") == ["/n/get_parameters"]
    shown = build_view(snap, ViewOptions(services=True, hide_debug=False)).names("service")
    assert "/turtlesim/get_parameters" in shown and f"{ACTION}/_action/send_goal" in shown


def test_actions_as_one_box(snap):
    view = build_view(snap, ViewOptions(actions=True))
    assert view.names("action") == [ACTION]
    assert view.vertex("a_" + ACTION).types == ("turtlesim/action/RotateAbsolute",)
    assert ("/teleop_turtle", ACTION) in view.edges() and (ACTION, "/turtlesim") in view.edges()
    # the hidden pieces are folded into the box even when debug entities are shown
    loud = build_view(snap, ViewOptions(actions=True, hide_debug=False, hide_leaf_topics=False))
    assert not [t for t in loud.names("topic") if "/_action/" in t]


def test_actions_expanded_to_services_and_topics(snap):
    view = build_view(snap, ViewOptions(actions="expand"))
    parts = f"{ACTION}/_action/"
    assert view.names("service") == [parts + s for s in ("cancel_goal", "get_result", "send_goal")]
    assert {t for t in view.names("topic") if t.startswith(parts)} == {parts + "feedback", parts + "status"}
    edges = view.edges()
    assert ("/teleop_turtle", parts + "send_goal") in edges and (parts + "send_goal", "/turtlesim") in edges
    assert ("/turtlesim", parts + "feedback") in edges and (parts + "feedback", "/teleop_turtle") in edges
    assert view.clusters[ACTION] == "action"
    assert view.vertex("t_" + parts + "status").cluster == ("/turtle1", ACTION)
    assert view.vertex("s_" + parts + "send_goal").types == ("turtlesim/action/RotateAbsolute_SendGoal",)


def test_bad_actions_option():
    with pytest.raises(ValueError):
        ViewOptions(actions="boxes")


def test_namespace_clusters():
    assert namespace_path("/talker", 2) == ()
    assert namespace_path("/turtle1/cmd_vel", 2) == ("/turtle1",)
    assert namespace_path("/a/b/c/d", 2) == ("/a", "/a/b")
    assert namespace_path("/a/b/c/d", 1) == ("/a",)
    assert namespace_path("/a/b/c/d", 0) == ()


def test_snapshot_from_dict_round_trip_and_errors(snap):
    assert GraphSnapshot.from_dict(snap.to_dict()) == snap
    assert snap.node("/ns/pose_listener").namespace == "/ns"
    assert snap.node_names()[0] == "/_ros2cli_7"
    with pytest.raises(ValueError):
        GraphSnapshot.from_dict({"/x": {"publisher": {}}})
    # order of declaration does not matter
    again = GraphSnapshot.from_dict(dict(reversed(list(TURTLESIM.items()))))
    assert again == snap and again.signature() == snap.signature()


def parse(svg):
    return ET.fromstring(svg.encode("utf-8"))


def texts(root):
    return [t.text for t in root.iter(SVG_NS + "text")]


def test_svg_is_valid_and_holds_the_view(snap):
    gv = GraphView(services=True, actions=True, snapshot=snap)
    svg = gv.svg()
    root = parse(svg)
    assert root.tag == SVG_NS + "svg"
    view = gv.view()
    groups = [g for g in root.iter(SVG_NS + "g")]
    vertex_groups = [g for g in groups if g.get("class", "").startswith("vertex")]
    edge_groups = [g for g in groups if g.get("class", "").startswith("edge")]
    assert len(vertex_groups) == len(view.vertices) and len(edge_groups) == len(view.links)
    shown = texts(root)
    for name in ["/turtlesim", "/teleop_turtle", "/turtle1/cmd_vel", "/spawn", ACTION, "/turtle1", "/ns"]:
        assert name in shown
    assert "Noto Sans CJK SC" in root.get("font-family")
    # nodes are ellipses, topics boxes
    turtlesim = next(g for g in vertex_groups if g.find(SVG_NS + "text").text == "/turtlesim")
    assert turtlesim.find(SVG_NS + "ellipse") is not None
    pose = next(g for g in vertex_groups if g.find(SVG_NS + "text").text == "/turtle1/pose")
    assert pose.find(SVG_NS + "rect") is not None
    assert "turtlesim/msg/Pose" in pose.find(SVG_NS + "title").text


def test_svg_deterministic(snap):
    a = GraphView(snapshot=snap).svg()
    b = GraphView(snapshot=GraphSnapshot.from_dict(dict(reversed(list(TURTLESIM.items()))))).svg()
    assert a == b
    assert "id=" not in a          # no generated ids at all


def test_chinese_names_render():
    snap = GraphSnapshot.from_dict({
        "/机器人/说话者": node(publishers={"/话题": "std_msgs/msg/String"}),
        "/听众": node(subscribers={"/话题": "std_msgs/msg/String"}),
    })
    root = parse(GraphView(snapshot=snap).svg())
    assert {"/机器人/说话者", "/听众", "/话题", "/机器人"} <= set(texts(root))
    # the CJK label's ellipse is wider than an ASCII label of the same length would need
    widths = {g.find(SVG_NS + "text").text: float(g.find(SVG_NS + "ellipse").get("rx"))
              for g in root.iter(SVG_NS + "g") if g.find(SVG_NS + "ellipse") is not None}
    assert widths["/听众"] > 30


def test_empty_graph_svg():
    root = parse(GraphView(snapshot=GraphSnapshot()).svg())
    assert texts(root) == ["(no nodes)"]


_SUBPROCESS = """
import sys
sys.path.insert(0, {tests!r})
from test_graph_snapshot_view import TURTLESIM
from labkit.viz.graph_view import GraphView
sys.stdout.write(GraphView(services=True, actions="expand", snapshot=TURTLESIM).svg())
sys.stdout.write(GraphView(nodes_only=True, services=True, snapshot=TURTLESIM).svg())
"""


def test_svg_does_not_depend_on_installed_fonts(tmp_path, snap):
    """Another machine has other fonts: the stored SVG must still be byte-identical."""
    conf = tmp_path / "fonts.conf"
    conf.write_text('<?xml version="1.0"?><fontconfig><cachedir>%s</cachedir></fontconfig>' % tmp_path)
    env = dict(os.environ, FONTCONFIG_FILE=str(conf))
    code = _SUBPROCESS.format(tests=os.path.dirname(__file__))
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, check=True)
    assert out.stdout.decode("utf-8") == (
        GraphView(services=True, actions="expand", snapshot=snap).svg()
        + GraphView(nodes_only=True, services=True, snapshot=snap).svg())


def test_graph_view_api_on_a_snapshot(snap):
    gv = GraphView(snapshot=TURTLESIM)
    assert gv.snapshot() == snap
    assert gv.edges() == build_view(snap).edges()
    assert gv._repr_svg_() == gv.svg()
    w = gv.widget()
    assert "<svg" in w.value and "/turtlesim" in w.value
    assert gv.refresh() is False   # same snapshot: nothing to redraw


class StubNode:
    """The slice of rclpy.node.Node that rqt_graph (and the view) queries."""

    def __init__(self, spec):
        self.snap = GraphSnapshot.from_dict(spec)

    def get_node_names_and_namespaces(self):
        return [(n.name, n.namespace) for n in reversed(self.snap.nodes)]

    def _by_node(kind):
        def query(self, name, namespace):
            node = next(n for n in self.snap.nodes if (n.name, n.namespace) == (name, namespace))
            return [(t, list(types)) for t, types in getattr(node, kind)]
        return query

    get_publisher_names_and_types_by_node = _by_node("publishers")
    get_subscriber_names_and_types_by_node = _by_node("subscribers")
    get_service_names_and_types_by_node = _by_node("services")
    get_client_names_and_types_by_node = _by_node("clients")


def test_query_snapshot_through_the_node_api(snap):
    from labkit.viz import _graph_model
    spec = dict(TURTLESIM)
    spec["/_labkit_graph_view"] = node()
    got = _graph_model.query_snapshot(StubNode(spec), exclude={"/_labkit_graph_view"})
    # actions come from the hidden feedback topics, as rcl_action finds them
    assert got == snap
    assert got.node("/turtlesim").action_servers == ((ACTION, ("turtlesim/action/RotateAbsolute",)),)
    assert got.node("/teleop_turtle").action_clients == ((ACTION, ("turtlesim/action/RotateAbsolute",)),)


def test_actions_derived_without_rclpy_action(monkeypatch, snap):
    from labkit.viz import _graph_model
    monkeypatch.setattr(_graph_model, "_action_queries", lambda: None)
    assert _graph_model.query_snapshot(StubNode(TURTLESIM)) == snap


def test_nodes_only_view(snap):
    view = build_view(snap, ViewOptions(nodes_only=True))
    feedback, status = f"{ACTION}/_action/feedback", f"{ACTION}/_action/status"
    assert view.names("node") == ["/ns/pose_listener", "/teleop_turtle", "/turtlesim"]
    assert view.names("topic") == []
    assert view.edges(labels=True) == [
        ("/teleop_turtle", "/turtle1/cmd_vel", "/turtlesim"),
        ("/turtlesim", "/turtle1/pose", "/ns/pose_listener"),
        ("/turtlesim", feedback, "/teleop_turtle"),
        ("/turtlesim", status, "/teleop_turtle"),
    ]
    # two topics between the same pair of nodes are two arrows, as rqt_graph draws them
    root = parse(GraphView(nodes_only=True, snapshot=snap).svg())
    edges = [g for g in root.iter(SVG_NS + "g") if g.get("class", "").startswith("edge")]
    assert len(edges) == 4
    assert {feedback, status, "/turtle1/cmd_vel", "/turtle1/pose"} <= set(texts(root))
    services = build_view(snap, ViewOptions(nodes_only=True, services=True, actions=True))
    assert ("/ns/pose_listener", "/spawn", "/turtlesim") in services.edges(labels=True)
    assert ("/teleop_turtle", ACTION, "/turtlesim") in services.edges(labels=True)


def test_qos_incompatible_topic_is_red():
    spec = {"/camera": node(publishers={"/image": "sensor_msgs/msg/Image"}),
            "/viewer": node(subscribers={"/image": "sensor_msgs/msg/Image"}),
            "/logger": node(subscribers={"/image": "sensor_msgs/msg/Image"})}
    snap = GraphSnapshot.from_dict(spec, qos_incompatible=[("/image", "/camera", "/viewer")])
    assert snap != GraphSnapshot.from_dict(spec)
    assert snap.signature() != GraphSnapshot.from_dict(spec).signature()
    image = build_view(snap).vertex("t_/image")
    assert image.qos_incompatible == (("/camera", ("/viewer",)),)
    root = parse(GraphView(snapshot=snap).svg())
    group = next(g for g in root.iter(SVG_NS + "g") if g.get("class") == "vertex topic qos-incompatible")
    assert group.find(SVG_NS + "rect").get("stroke") == "red"
    tip = group.find(SVG_NS + "title").text
    assert "Publisher of node `/camera` incompatible with subscriptions of nodes `/viewer`" in tip
    assert "ros2 topic info -v /image" in tip
    fine = parse(GraphView(snapshot=spec).svg())
    assert "red" not in ET.tostring(fine, encoding="unicode")


def test_rendering_writes_nothing_to_stderr(capfd):
    """Jupyter shows (and nbval compares) what Graphviz or fontconfig print on fd 2."""
    for kw in ({}, {"nodes_only": True, "services": True}, {"actions": "expand", "services": True}):
        GraphView(snapshot=TURTLESIM, **kw).svg()
    captured = capfd.readouterr()
    assert captured.err == ""
