"""From a snapshot to what rqt_graph draws in its "Nodes/Topics (all)" view.

The rules follow rqt_graph (humble): publisher -> topic -> subscriber edges;
"Hide" options applied in rqt_graph's order (dead sinks and leaf topics first,
counting every connection, then tf, then "Debug" removes viewer/CLI nodes,
names whose last token starts with '_', /rosout, /clock, /parameter_events ...);
names grouped into nested namespace clusters (rqt_graph's default depth 2).
So, as in rqt_graph, an action's `_action/feedback` and `_action/status` topics
show up unless `actions` folds them into the action. Services and actions
are labkit additions rqt_graph does not draw: services as client -> service ->
server, actions as one box (client -> action -> server) or expanded to the
hidden services and topics rcl_action creates. services="request_response" draws
a service's two messages apart: the request client -> service -> server, and the
response server -> service -> client (not in the "Nodes only" graph).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from labkit.viz._graph_model import ACTION_SERVICES, ACTION_TOPICS, GraphSnapshot

# rqt_graph's QUIET_NAMES: a node or topic whose name contains one of these is debug.
QUIET_NAMES = ("/diag_agg", "/runtime_logger", "/pr2_dashboard", "/rviz", "/rosout",
               "/cpu_monitor", "/monitor", "/hd_monitor", "/rxloggerlevel", "/clock",
               "/rqt", "/statistics")
# Node-name prefixes of labkit's own tools that are not hidden names.
TOOL_NODE_PREFIXES = ("labkit_",)
# The parameter services every rclpy node offers (rcl_interfaces/srv/*).
PARAMETER_SERVICES = ("describe_parameters", "get_parameter_types", "get_parameters",
                      "list_parameters", "set_parameters", "set_parameters_atomically")
TF_TOPICS = ("/tf", "/tf_static")
# In "Nodes only", rqt_graph's "Debug" looks at an arrow's topic by these names only.
QUIET_LABELS = ("/time", "/clock", "/rosout", "/statistics")

_PREFIX = {"node": "n_", "topic": "t_", "service": "s_", "action": "a_", "tf": "g_"}


def is_hidden_name(name: str) -> bool:
    """ROS 2's rule (ros2cli `--include-hidden`, rcl): hidden if any token starts with '_'."""
    return any(token.startswith("_") for token in name.split("/"))


def _quiet(name: str) -> bool:
    """rqt_graph's "Debug" filter: a QUIET_NAMES part, or a last token starting with '_'.
    (Only the last token: so an action's `.../_action/feedback` topic stays visible,
    the "two actions around the periphery" the ROS 2 tutorials mention.)"""
    return any(q in name for q in QUIET_NAMES) or name.rsplit("/", 1)[-1].startswith("_")


def is_debug_node(fully_qualified_name: str) -> bool:
    return _quiet(fully_qualified_name) or \
        fully_qualified_name.rsplit("/", 1)[-1].startswith(TOOL_NODE_PREFIXES)


def is_debug_topic(name: str) -> bool:
    # rqt_graph's "Params" switch (on by default) hides every `.../parameter_events`
    return _quiet(name) or name.rsplit("/", 1)[-1] == "parameter_events"


def is_debug_service(name: str, types=()) -> bool:
    # services are labkit's addition: hidden as `ros2 service list` hides them
    if is_hidden_name(name):
        return True
    base = name.rsplit("/", 1)[-1]
    if base == "get_type_description":   # every node offers it from Iron on
        return all(t.startswith("type_description_interfaces/") for t in types)
    return base in PARAMETER_SERVICES and all(t.startswith("rcl_interfaces/") for t in types)


def namespace_path(name: str, level: int) -> tuple[str, ...]:
    """The nested namespace clusters a name sits in, at most `level` deep
    (rqt_graph's "Group: Namespaces" spin box, default 2)."""
    parts = name.strip("/").split("/")[:-1][:level]
    return tuple("/" + "/".join(parts[: i + 1]) for i in range(len(parts)))


@dataclass(frozen=True)
class ViewOptions:
    services: bool | str = False       # False | True (two-headed) | "request_response"
    actions: bool | str = False        # False | True (one box) | "expand"
    hide_debug: bool = True
    hide_dead_sinks: bool = True
    hide_leaf_topics: bool = True
    hide_tf: bool = False
    group_tf: bool = True
    cluster_level: int = 2
    nodes_only: bool = False           # rqt_graph's "Nodes only": node -> node, labelled

    def __post_init__(self):
        if self.actions not in (False, True, "expand"):
            raise ValueError("actions must be False, True or 'expand'")
        if self.services not in (False, True, "request_response"):
            raise ValueError("services must be False, True or 'request_response'")


@dataclass(frozen=True, order=True)
class Vertex:
    kind: str                      # node | topic | service | action | tf
    name: str
    types: tuple[str, ...] = ()
    cluster: tuple[str, ...] = ()  # nested cluster keys, outermost first
    # topics: (publisher node, (subscription nodes...)) whose QoS do not match
    qos_incompatible: tuple[tuple[str, tuple[str, ...]], ...] = ()

    @property
    def id(self) -> str:
        return _PREFIX[self.kind] + self.name


@dataclass(frozen=True, order=True)
class Link:
    start: str                     # vertex ids
    end: str
    kind: str                      # topic | service | action | request | response
    label: str = ""                # "Nodes only": the topic (service, action) it stands for


@dataclass
class ViewGraph:
    vertices: tuple[Vertex, ...] = ()
    links: tuple[Link, ...] = ()
    # cluster key -> "namespace" | "action"
    clusters: dict[str, str] = field(default_factory=dict)

    def vertex(self, vertex_id: str) -> Vertex:
        return self._by_id()[vertex_id]

    def _by_id(self):
        return {v.id: v for v in self.vertices}

    def names(self, kind: str) -> list[str]:
        return sorted(v.name for v in self.vertices if v.kind == kind)

    def edges(self, labels: bool = False) -> list[tuple[str, ...]]:
        """(start, end) ROS names of every arrow, sorted; with labels=True
        (start, label, end), the label naming the topic of a "Nodes only" arrow."""
        by_id = self._by_id()
        if labels:
            return sorted({(by_id[l.start].name, l.label, by_id[l.end].name) for l in self.links})
        return sorted({(by_id[l.start].name, by_id[l.end].name) for l in self.links})


def build_view(snapshot: GraphSnapshot, options: ViewOptions = ViewOptions()) -> ViewGraph:
    """Apply rqt_graph's rules (and labkit's service/action additions) to a snapshot."""
    o = options
    nodes = sorted({n.fully_qualified_name for n in snapshot.nodes})

    # actions: {name: (types, servers, clients)}; their hidden pieces leave the topic lists
    actions: dict[str, tuple[set, set, set]] = {}
    for n in snapshot.nodes:
        for side, entities in ((1, n.action_servers), (2, n.action_clients)):
            for name, types in entities:
                entry = actions.setdefault(name, (set(), set(), set()))
                entry[0].update(types)
                entry[side].add(n.fully_qualified_name)
    action_parts = set()
    if o.actions:
        action_parts = {f"{a}/_action/{p}" for a in actions for p in ACTION_SERVICES + ACTION_TOPICS}
    part_types: dict[str, set[str]] = {}

    # topic edges as rqt_graph builds them: (start, end) with topics marked
    topic_types: dict[str, set[str]] = {}
    topic_edges: set[tuple[str, str, str]] = set()   # (node, topic, 'pub'|'sub')
    for n in snapshot.nodes:
        fqn = n.fully_qualified_name
        for direction, entities in (("pub", n.publishers), ("sub", n.subscribers)):
            for topic, types in entities:
                if topic in action_parts:
                    part_types.setdefault(topic, set()).update(types)
                    continue
                topic_types.setdefault(topic, set()).update(types)
                topic_edges.add((fqn, topic, direction))

    # Hide: dead sinks / leaf topics, counted over every connection (debug ones too)
    def connections(topic):
        return [e for e in topic_edges if e[1] == topic]
    removed = set()
    for topic in sorted(topic_types):
        conns = connections(topic)
        if o.hide_leaf_topics and len(conns) < 2:
            removed.add(topic)
        if o.hide_dead_sinks and not any(d == "sub" for _, _, d in conns):
            removed.add(topic)
    if o.hide_tf:
        removed.update(t for t in TF_TOPICS if t in topic_types)
    topic_edges = {e for e in topic_edges if e[1] not in removed}
    topics = sorted({t for _, t, _ in topic_edges})

    vertices: dict[str, Vertex] = {}
    links: set[Link] = set()
    clusters: dict[str, str] = {}
    level = max(0, int(o.cluster_level))

    def add(kind, name, types=(), cluster=None):
        path = namespace_path(name, level) if cluster is None else cluster
        for key in path:
            clusters.setdefault(key, "namespace")
        v = Vertex(kind, name, tuple(sorted(types)), path)
        vertices[v.id] = v
        return v.id

    for name in nodes:
        add("node", name)

    bad_qos: dict[str, dict[str, set[str]]] = {}
    for topic, pub, sub in snapshot.qos_incompatible:
        bad_qos.setdefault(topic, {}).setdefault(pub, set()).add(sub)

    grouped_tf = o.group_tf and not o.hide_tf and not o.nodes_only and \
        any(t in TF_TOPICS for t in topics)
    topic_ids = {}
    for topic in topics:
        if grouped_tf and topic in TF_TOPICS:
            types = set().union(*(topic_types[t] for t in TF_TOPICS if t in topic_types))
            topic_ids[topic] = add("tf", "/tf", types)
        else:
            topic_ids[topic] = add("topic", topic, topic_types[topic])
            if topic in bad_qos:
                v = vertices[topic_ids[topic]]
                pairs = tuple((pub, tuple(sorted(subs))) for pub, subs in sorted(bad_qos[topic].items()))
                vertices[v.id] = Vertex(v.kind, v.name, v.types, v.cluster, pairs)
    for node, topic, direction in topic_edges:
        t, n = topic_ids[topic], "n_" + node
        links.add(Link(n, t, "topic") if direction == "pub" else Link(t, n, "topic"))

    if o.services:
        for n in snapshot.nodes:
            fqn = n.fully_qualified_name
            for role, entities in (("server", n.services), ("client", n.clients)):
                for name, types in entities:
                    if name in action_parts:
                        part_types.setdefault(name, set()).update(types)
                        continue
                    if o.hide_debug and is_debug_service(name, types):
                        continue
                    s = add("service", name, types)
                    if o.services == "request_response" and not o.nodes_only:
                        # the request there (client -> service -> server), the response back
                        there = ("n_" + fqn, s) if role == "client" else (s, "n_" + fqn)
                        links.add(Link(*there, "request"))
                        links.add(Link(*reversed(there), "response"))
                        continue
                    links.add(Link(s, "n_" + fqn, "service") if role == "server"
                              else Link("n_" + fqn, s, "service"))
    elif o.actions == "expand":
        for n in snapshot.nodes:
            for name, types in n.services + n.clients:
                if name in action_parts:
                    part_types.setdefault(name, set()).update(types)

    if o.actions:
        for a in sorted(actions):
            types, servers, clients = actions[a]
            if o.hide_debug and is_hidden_name(a):
                continue
            if o.actions is True:
                v = add("action", a, types)
                links.update(Link(v, "n_" + s, "action") for s in servers)
                links.update(Link("n_" + c, v, "action") for c in clients)
                continue
            path = namespace_path(a, level) + (a,)
            clusters[a] = "action"
            for p in ACTION_SERVICES:
                name = f"{a}/_action/{p}"
                v = add("service", name, part_types.get(name, ()), path)
                links.update(Link(v, "n_" + s, "service") for s in servers)
                links.update(Link("n_" + c, v, "service") for c in clients)
            for p in ACTION_TOPICS:
                name = f"{a}/_action/{p}"
                v = add("topic", name, part_types.get(name, ()), path)
                links.update(Link("n_" + s, v, "topic") for s in servers)
                links.update(Link(v, "n_" + c, "topic") for c in clients)

    if o.hide_debug:   # rqt_graph's "Debug" (quiet) filter comes last
        def debug_topic(name):
            if o.nodes_only:
                return name in QUIET_LABELS or name.rsplit("/", 1)[-1] == "parameter_events"
            return name not in action_parts and is_debug_topic(name)
        for vid, v in list(vertices.items()):
            if (v.kind == "node" and is_debug_node(v.name)) or \
                    (v.kind == "topic" and debug_topic(v.name)):
                del vertices[vid]
        links = {l for l in links if l.start in vertices and l.end in vertices}
        # a service or action left with nobody around it is noise
        linked = {l.start for l in links} | {l.end for l in links}
        for vid, v in list(vertices.items()):
            if v.kind in ("service", "action") and vid not in linked:
                del vertices[vid]
    if o.nodes_only:
        vertices, links = _nodes_only(vertices, links)
    used = {key for v in vertices.values() for key in v.cluster}
    return ViewGraph(tuple(sorted(vertices.values())), tuple(sorted(links)),
                     {k: clusters[k] for k in sorted(used)})


def _nodes_only(vertices, links):
    """rqt_graph's "Nodes only": every topic (service, action) between two nodes
    becomes arrows from each of its publishers to each of its subscribers,
    labelled with its name."""
    collapsed = {}
    for vid, v in vertices.items():
        if v.kind == "node":
            continue
        ins = [l.start for l in links if l.end == vid]
        outs = [l.end for l in links if l.start == vid]
        kind = next((l.kind for l in links if vid in (l.start, l.end)), "topic")
        for a in ins:
            for b in outs:
                collapsed[(a, b, v.name)] = Link(a, b, kind, v.name)
    nodes = {vid: v for vid, v in vertices.items() if v.kind == "node"}
    return nodes, set(collapsed.values())
