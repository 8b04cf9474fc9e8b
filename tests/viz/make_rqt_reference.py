"""Record what rqt_graph (humble) itself draws for rqt_scenarios.SCENARIOS.

Not a test: run it by hand under a real rclpy, with rqt_graph's humble sources:

    git --git-dir=<rqt_graph mirror> archive humble src/rqt_graph | tar -x -C /tmp/rqtref
    LD_LIBRARY_PATH=<venv>/lib <venv>/bin/python tests/viz/make_rqt_reference.py /tmp/rqtref/src

It feeds each scenario to rqt_graph's Graph and RosGraphDotcodeGenerator through a
stand-in node (the rclpy graph queries rqt_graph makes) and a recording dot factory,
and writes tests/viz/data/rqt_graph_reference.json.
"""
import json
import os
import sys
import types

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from rqt_scenarios import OPTION_SETS, SCENARIOS  # noqa: E402

# rqt_graph logs through Qt; it needs nothing else from it here
qt = types.ModuleType("python_qt_binding")
qt.QtCore = types.ModuleType("python_qt_binding.QtCore")
qt.QtCore.qDebug = qt.QtCore.qWarning = lambda *a, **k: None
sys.modules["python_qt_binding"] = qt
sys.modules["python_qt_binding.QtCore"] = qt.QtCore
sys.modules.setdefault("pydot", types.ModuleType("pydot"))
sys.path.insert(0, sys.argv[1])

from rqt_graph import dotcode, rosgraph2_impl  # noqa: E402


class StandInNode:
    def __init__(self, spec):
        self.spec = spec

    def get_node_names_and_namespaces(self):
        out = []
        for fqn in self.spec:
            ns, _, name = fqn.rpartition("/")
            out.append((name, ns or "/"))
        return out

    def _by_node(kind):
        def query(self, name, namespace):
            fqn = (namespace.rstrip("/") + "/" + name)
            return [(t, [ty]) for t, ty in self.spec[fqn].get(kind, {}).items()]
        return query

    get_publisher_names_and_types_by_node = _by_node("publishers")
    get_subscriber_names_and_types_by_node = _by_node("subscribers")
    get_service_names_and_types_by_node = _by_node("services")

    def _info_by_topic(kind):
        def query(self, topic):
            from rclpy.qos import QoSProfile
            out = []
            for fqn, kinds in self.spec.items():
                if topic in kinds.get(kind, {}):
                    ns, _, name = fqn.rpartition("/")
                    out.append(types.SimpleNamespace(node_name=name, node_namespace=ns or "/",
                                                     qos_profile=QoSProfile(depth=10)))
            return out
        return query

    get_publishers_info_by_topic = _info_by_topic("publishers")
    get_subscriptions_info_by_topic = _info_by_topic("subscribers")


class RecordingFactory:
    """The slice of qt_dotgraph's factories that RosGraphDotcodeGenerator calls."""

    def __init__(self):
        self.nodes, self.edges, self.clusters = {}, [], []

    def get_graph(self, **kw):
        return "root"

    def add_subgraph_to_graph(self, graph, name, **kw):
        self.clusters.append(name)
        return name

    def add_node_to_graph(self, graph, nodename, nodelabel=None, shape="box", **kw):
        self.nodes[nodename] = (nodelabel, shape)

    def add_edge_to_graph(self, graph, start, end, label=None, **kw):
        self.edges.append((start, end, label or ""))

    def create_dot(self, graph):
        return ""


def draw(spec, rqt_options):
    graph = rosgraph2_impl.Graph(StandInNode(spec))
    graph._graph_refresh()
    factory = RecordingFactory()
    opts = dict(graph_mode=dotcode.NODE_TOPIC_ALL_GRAPH, hide_single_connection_topics=True,
                hide_dead_end_topics=True, cluster_namespaces_level=2, accumulate_actions=True,
                quiet=True, unreachable=True, hide_tf_nodes=False, group_tf_nodes=True,
                group_image_nodes=True, hide_dynamic_reconfigure=True)
    opts.update(rqt_options)
    dotcode.RosGraphDotcodeGenerator(None).generate_dotgraph(
        rosgraphinst=graph, ns_filter="/", topic_filter="/", dotcode_factory=factory, **opts)
    label = {name: lab for name, (lab, _) in factory.nodes.items()}
    return {
        "vertices": sorted([lab, shape] for lab, shape in factory.nodes.values()),
        "edges": sorted({(label.get(a, a), lab, label.get(b, b)) for a, b, lab in factory.edges}),
        "clusters": sorted(set(factory.clusters)),
    }


if __name__ == "__main__":
    reference = {name: {opt: draw(spec, rqt) for opt, (rqt, _) in OPTION_SETS.items()}
                 for name, spec in SCENARIOS.items()}
    out = os.path.join(HERE, "data", "rqt_graph_reference.json")
    with open(out, "w") as f:
        json.dump(reference, f, indent=1, sort_keys=True)
    print("wrote", out)
