"""The plain data behind the graph view: what every node offers on the graph.

A `GraphSnapshot` is what rqt_graph collects before it draws: for each node,
its publishers, subscribers, services, clients, action servers and action
clients, each as (name, types). It is built either from a live graph through
the public rclpy Node API (`query_snapshot`) or from a dict (tests, figures).
Everything is sorted, so equal graphs give equal snapshots.
"""
from __future__ import annotations

from dataclasses import dataclass, field

# (name, (type, ...)) pairs, sorted by name
Entities = tuple[tuple[str, tuple[str, ...]], ...]

KINDS = ("publishers", "subscribers", "services", "clients",
         "action_servers", "action_clients")

# The pieces rcl_action puts on the graph for one action `<name>`.
ACTION_SERVICES = ("send_goal", "cancel_goal", "get_result")
ACTION_TOPICS = ("feedback", "status")


def join_name(namespace: str, name: str) -> str:
    """Fully qualified node name from namespace and base name, as rqt_graph forms it."""
    return namespace + name if namespace.endswith("/") else namespace + "/" + name


def _entities(items) -> Entities:
    """Normalise {name: type | [types]} or [(name, [types])] to sorted tuples."""
    if isinstance(items, dict):
        items = items.items()
    merged: dict[str, set[str]] = {}
    for name, types in items:
        if isinstance(types, str):
            types = [types]
        merged.setdefault(name, set()).update(types or ())
    return tuple((name, tuple(sorted(merged[name]))) for name in sorted(merged))


@dataclass(frozen=True, order=True)
class NodeEntities:
    """One node and everything it has on the graph."""
    namespace: str
    name: str
    publishers: Entities = ()
    subscribers: Entities = ()
    services: Entities = ()
    clients: Entities = ()
    action_servers: Entities = ()
    action_clients: Entities = ()

    @property
    def fully_qualified_name(self) -> str:
        return join_name(self.namespace, self.name)


@dataclass(frozen=True)
class GraphSnapshot:
    """Every node of a graph with its entities, sorted by fully qualified name,
    and the (topic, publisher node, subscription node) triples whose QoS do not
    match (rqt_graph paints those topics red)."""
    nodes: tuple[NodeEntities, ...] = field(default_factory=tuple)
    qos_incompatible: tuple[tuple[str, str, str], ...] = ()

    def __post_init__(self):
        object.__setattr__(self, "nodes", tuple(sorted(self.nodes)))
        object.__setattr__(self, "qos_incompatible", tuple(sorted(set(self.qos_incompatible))))

    def node(self, fully_qualified_name: str) -> NodeEntities:
        for n in self.nodes:
            if n.fully_qualified_name == fully_qualified_name:
                return n
        raise KeyError(fully_qualified_name)

    def node_names(self) -> list[str]:
        return sorted({n.fully_qualified_name for n in self.nodes})

    def signature(self) -> int:
        """A cheap fingerprint: equal graphs give equal signatures."""
        return hash((self.nodes, self.qos_incompatible))

    @classmethod
    def from_dict(cls, spec: dict, qos_incompatible=()) -> "GraphSnapshot":
        """Build from {'/ns/node': {'publishers': {'/topic': 'pkg/msg/T'}, ...}}.

        Missing kinds are empty; a type may be a string or a list of strings.
        qos_incompatible: (topic, publisher node, subscription node) triples.
        """
        nodes = []
        for fqn, kinds in spec.items():
            unknown = set(kinds) - set(KINDS)
            if unknown:
                raise ValueError(f"unknown entity kinds {sorted(unknown)} for {fqn}")
            namespace, _, name = fqn.rpartition("/")
            nodes.append(NodeEntities(namespace or "/", name,
                                      **{k: _entities(kinds.get(k, ())) for k in KINDS}))
        return cls(tuple(nodes), tuple(tuple(t) for t in qos_incompatible))

    def to_dict(self) -> dict:
        return {n.fully_qualified_name: {k: {name: list(types) for name, types in getattr(n, k)}
                                         for k in KINDS if getattr(n, k)}
                for n in self.nodes}


def _action_queries():
    """rclpy.action's per-node action queries, or None while that room is not there."""
    try:
        from labkit.rclpy import action
        return (action.get_action_server_names_and_types_by_node,
                action.get_action_client_names_and_types_by_node)
    except (ImportError, AttributeError):
        return None


def _actions_from_hidden(publishers, subscribers):
    """Derive actions like rcl_action does: servers publish `<name>/_action/feedback`
    (type `pkg/action/X_FeedbackMessage`), clients subscribe to it."""
    def derive(entities):
        found = []
        for name, types in entities:
            if name.endswith("/_action/feedback"):
                action_types = tuple(t[: -len("_FeedbackMessage")] if t.endswith("_FeedbackMessage")
                                     else t for t in types)
                found.append((name[: -len("/_action/feedback")], action_types))
        return _entities(found)
    return derive(publishers), derive(subscribers)


def query_snapshot(node, exclude=()) -> GraphSnapshot:
    """Ask the graph, through `node`'s public API, what rqt_graph asks.

    Nodes whose fully qualified name is in `exclude` (the viewer's own) are left out.
    A node that vanishes between two queries is skipped, as rqt_graph tolerates it.
    """
    actions = _action_queries()
    nodes = []
    for name, namespace in node.get_node_names_and_namespaces():
        if join_name(namespace, name) in exclude:
            continue
        try:
            kinds = {
                "publishers": node.get_publisher_names_and_types_by_node(name, namespace),
                "subscribers": node.get_subscriber_names_and_types_by_node(name, namespace),
                "services": node.get_service_names_and_types_by_node(name, namespace),
                "clients": node.get_client_names_and_types_by_node(name, namespace),
            }
            if actions is not None:
                kinds["action_servers"] = actions[0](node, name, namespace)
                kinds["action_clients"] = actions[1](node, name, namespace)
            else:
                kinds["action_servers"], kinds["action_clients"] = _actions_from_hidden(
                    _entities(kinds["publishers"]), _entities(kinds["subscribers"]))
        except Exception as exc:  # the node left the graph meanwhile
            if type(exc).__name__ in ("NodeNameNonExistentError",):
                continue
            raise
        nodes.append(NodeEntities(namespace, name, **{k: _entities(v) for k, v in kinds.items()}))
    return GraphSnapshot(tuple(nodes), _qos_incompatible(node, nodes))


def _endpoint_node(info) -> str:
    return join_name(info.node_namespace, info.node_name)


def _qos_incompatible(node, nodes):
    """Like rqt_graph: for every topic with publishers and subscriptions, the pairs
    of nodes with an endpoint pair whose QoS cannot match (an ERROR, not a WARNING)."""
    try:
        from labkit.rclpy.qos import QoSCompatibility, qos_check_compatible
    except ImportError:
        return ()
    published = {t for n in nodes for t, _ in n.publishers}
    subscribed = {t for n in nodes for t, _ in n.subscribers}
    found = []
    for topic in sorted(published & subscribed):
        try:
            pubs = node.get_publishers_info_by_topic(topic)
            subs = node.get_subscriptions_info_by_topic(topic)
        except Exception:   # the topic vanished meanwhile
            continue
        for pub in pubs:
            for sub in subs:
                result = qos_check_compatible(pub.qos_profile, sub.qos_profile)[0]
                if result == QoSCompatibility.ERROR:
                    found.append((topic, _endpoint_node(pub), _endpoint_node(sub)))
    return tuple(found)
