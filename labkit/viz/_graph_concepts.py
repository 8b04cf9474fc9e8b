"""Concept figures: tiny graphs started for the picture, drawn, then torn down.

    concept_figure("topic")    # 2 publishers and 2 subscriptions on one topic
    concept_figure("service")  # one server, 2 clients
    concept_figure("action")   # an action expanded to its services and topics

The nodes live in a context of their own on a ROS domain of their own, so the
reader's running graph neither shows up in the figure nor sees these nodes.
"""
from __future__ import annotations

from labkit.viz._graph_model import GraphSnapshot, join_name, query_snapshot

# A domain nobody else uses (232 is the largest valid ROS_DOMAIN_ID).
CONCEPT_DOMAIN_ID = 232

# kind -> the view options that show the concept
CONCEPTS = {
    "topic": dict(),
    "service": dict(services=True),
    "action": dict(services=True, actions="expand"),
}


def _build(kind, make_node):
    from labkit.interfaces import get_type
    if kind == "topic":
        string = get_type("std_msgs/msg/String")
        for i in (1, 2):
            make_node(f"talker_{i}").create_publisher(string, "chatter", 10)
        for i in (1, 2):
            make_node(f"listener_{i}").create_subscription(string, "chatter", lambda msg: None, 10)
    elif kind == "service":
        add_two_ints = get_type("example_interfaces/srv/AddTwoInts")
        make_node("add_two_ints_server").create_service(
            add_two_ints, "add_two_ints", lambda request, response: response)
        for i in (1, 2):
            make_node(f"add_two_ints_client_{i}").create_client(add_two_ints, "add_two_ints")
    elif kind == "action":
        from labkit.rclpy.action import ActionClient, ActionServer
        fibonacci = get_type("example_interfaces/action/Fibonacci")
        server = ActionServer(make_node("fibonacci_action_server"), fibonacci, "fibonacci",
                              lambda goal_handle: fibonacci.Result())
        client = ActionClient(make_node("fibonacci_action_client"), fibonacci, "fibonacci")
        return [server, client]
    else:
        raise ValueError(f"unknown concept {kind!r}: choose one of {sorted(CONCEPTS)}")
    return []


def concept_snapshot(kind: str) -> GraphSnapshot:
    """Start the concept's nodes, take the snapshot, destroy everything again."""
    if kind not in CONCEPTS:
        raise ValueError(f"unknown concept {kind!r}: choose one of {sorted(CONCEPTS)}")
    from labkit import rclpy
    context = rclpy.context.Context()
    rclpy.init(args=[], context=context, domain_id=CONCEPT_DOMAIN_ID)
    nodes, extras = [], []
    try:
        def make_node(name):
            node = rclpy.create_node(name, context=context)
            nodes.append(node)
            return node
        extras = _build(kind, make_node)
        ours = {join_name(n.get_namespace(), n.get_name()) for n in nodes}
        query = make_node("_labkit_graph_view")
        snap = query_snapshot(query, exclude={"/_labkit_graph_view"})
        return GraphSnapshot(tuple(n for n in snap.nodes if n.fully_qualified_name in ours))
    finally:
        for thing in extras:
            try:
                thing.destroy()
            except Exception:
                pass
        for node in reversed(nodes):
            node.destroy_node()
        context.try_shutdown()


def concept_figure(kind: str):
    """A GraphView of the concept graph: display it, or take `.svg()` / `.edges()`."""
    from labkit.viz.graph_view import GraphView
    return GraphView(snapshot=concept_snapshot(kind), **CONCEPTS[kind])
