"""The in-process middleware: one registry of nodes and endpoints for every Context.

Endpoints of different ROS domains never see each other. Publishers hold the list
of matched subscription sinks, recomputed only when the graph changes, so publishing
is a plain loop over callables (no serialization, no lookup).
"""
from collections import deque
import itertools
import threading

from labkit.graph import qos_match, world

PUB, SUB, SRV, CLI = "publisher", "subscription", "service", "client"


class NodeInfo:
    __slots__ = ("name", "namespace", "enclave", "domain_id", "owner", "process", "gid")

    def __init__(self, name, namespace, enclave="/", domain_id=0, owner=None, process=None):
        self.name = name
        self.namespace = namespace
        self.enclave = enclave
        self.domain_id = domain_id
        self.owner = owner
        self.process = process
        self.gid = None

    @property
    def fqn(self):
        return (self.namespace if self.namespace != "/" else "") + "/" + self.name


class Endpoint:
    """A publisher, subscription, service server or client as the graph sees it."""

    __slots__ = ("kind", "name", "type_name", "node", "qos", "gid", "sink", "matched",
                 "history", "on_incompatible", "owner", "bridge", "__weakref__")

    def __init__(self, kind, name, type_name, node, qos=None, sink=None, owner=None):
        self.kind = kind
        self.name = name
        self.type_name = type_name
        self.node = node
        self.qos = qos
        self.gid = None
        self.sink = sink              # subscription/service/client: called with each delivery
        self.matched = []             # publisher: matched subscription sinks
        self.history = None           # publisher with TRANSIENT_LOCAL: last `depth` messages
        self.on_incompatible = None   # callable(other_endpoint, policy_kind)
        self.owner = owner
        self.bridge = None            # publisher: its DDS writer's sink (labkit.dds), if connected


def _compatible(pub_qos, sub_qos):
    result, _, kind = qos_match.check_compatible(pub_qos, sub_qos)
    return result != qos_match.ERROR, kind


class Graph:
    def __init__(self):
        self.lock = threading.RLock()
        self.nodes = []
        self.endpoints = {PUB: {}, SUB: {}, SRV: {}, CLI: {}}   # kind -> name -> [Endpoint]
        self._by_node = {}            # NodeInfo -> its endpoints, in the order added
        self.version = 0
        self._gids = itertools.count(1)
        self.listeners = []           # callables run after each graph change

    # ------------------------------------------------------------- changes
    def _changed(self):
        self.version += 1
        for listener in list(self.listeners):
            try:
                listener()
            except Exception:
                pass
        world.notify()

    def _gid(self, pid=0, kind=0):
        # Fast DDS layout: vendor 01.0f, host, pid, entity id + kind; Humble pads to 24 bytes
        n = next(self._gids)
        return (bytes([1, 15, 0x4c, 0x59]) + (pid & 0xFFFFFFFF).to_bytes(4, "little") +
                bytes([1, 0, 0, 0]) + n.to_bytes(3, "big") + bytes([kind]) + bytes(8))

    def add_node(self, info):
        with self.lock:
            info.gid = self._gid(getattr(info.process, "pid", 0), 0xC1)
            self.nodes.append(info)
            self._changed()
        return info

    def remove_node(self, info):
        with self.lock:
            # the node's own endpoints (not a scan of every name); each topic that lost a
            # subscription is matched again once
            topics = {}
            for ep in list(self._by_node.get(info, ())):
                if self._remove(ep, rematch=False):
                    topics[ep.name] = None
            for topic in topics:
                self._rematch(topic)
            self._by_node.pop(info, None)
            if info in self.nodes:
                self.nodes.remove(info)
            self._changed()

    def add(self, ep):
        """Register an endpoint; returns it (publishers get their matched list)."""
        with self.lock:
            kind = {PUB: 0x03, SUB: 0x04, SRV: 0x04, CLI: 0x03}[ep.kind]
            ep.gid = self._gid(getattr(ep.node.process, "pid", 0), kind)
            self.endpoints[ep.kind].setdefault(ep.name, []).append(ep)
            self._by_node.setdefault(ep.node, []).append(ep)
            if ep.kind in (PUB, SUB):
                self._rematch(ep.name, new=ep)
            self._changed()
        return ep

    def remove(self, ep):
        with self.lock:
            self._remove(ep)
            self._changed()

    def _remove(self, ep, rematch=True):
        """Returns True when the topic's matches must be computed again: a subscription
        went (a publisher that goes changes no other publisher's matches)."""
        eps = self.endpoints[ep.kind].get(ep.name)
        if eps and ep in eps:
            eps.remove(ep)
            if not eps:
                del self.endpoints[ep.kind][ep.name]
            own = self._by_node.get(ep.node)
            if own is not None and ep in own:
                own.remove(ep)
                if not own:
                    del self._by_node[ep.node]
            if ep.kind == SUB:
                if rematch:
                    self._rematch(ep.name)
                return True
        return False

    def _rematch(self, topic, new=None):
        pubs = self.endpoints[PUB].get(topic, [])
        subs = self.endpoints[SUB].get(topic, [])
        incompatible = []
        for pub in pubs:
            matched = []
            for sub in subs:
                if sub.node.domain_id != pub.node.domain_id:
                    continue
                ok, kind = _compatible(pub.qos, sub.qos)
                if ok and sub.sink is None:   # remote (labkit.dds): the DDS writer carries it
                    if pub.bridge is not None and pub.bridge not in matched:
                        matched.append(pub.bridge)
                elif ok:
                    matched.append(sub.sink)
                    if new is not None and sub is new and pub.history:
                        self._replay(pub, sub)
                elif new is not None and (new is pub or new is sub):
                    incompatible.append((pub, sub, kind))
            if pub.bridge is not None and pub.history is not None and pub.bridge not in matched:
                matched.append(pub.bridge)   # TRANSIENT_LOCAL: DDS keeps it for late joiners
            pub.matched = matched      # a new list: a publish in progress keeps its old one
        for pub, sub, kind in incompatible:
            for ep, other in ((sub, pub), (pub, sub)):
                if ep.on_incompatible is not None:
                    try:
                        ep.on_incompatible(other, kind)
                    except Exception:
                        pass

    def rematch(self, topic):
        """Recompute a topic's matches (a publisher's DDS writer came or went)."""
        with self.lock:
            self._rematch(topic)

    @staticmethod
    def _replay(pub, sub):
        # TRANSIENT_LOCAL: a late-joining durable subscription gets the stored messages.
        if sub.qos.durability != qos_match.TRANSIENT_LOCAL or sub.sink is None:
            return
        for msg in list(pub.history):
            sub.sink(msg)

    # ------------------------------------------------------------- services
    def find_service(self, name, domain_id):
        for ep in self.endpoints[SRV].get(name, ()):
            if ep.node.domain_id == domain_id:
                return ep
        return None

    # ------------------------------------------------------------- queries
    def node_infos(self, domain_id):
        return [n for n in self.nodes if n.domain_id == domain_id]

    def _eps(self, kind, domain_id, node=None):
        out = []
        for name, eps in self.endpoints[kind].items():
            for ep in eps:
                if ep.node.domain_id == domain_id and (node is None or
                                                       (ep.node.name, ep.node.namespace) == node):
                    out.append(ep)
        return out

    def names_and_types(self, kinds, domain_id, node=None):
        """[(name, [types...])] sorted by name, like rcl's graph queries."""
        acc = {}
        for kind in kinds:
            for ep in self._eps(kind, domain_id, node):
                types = acc.setdefault(ep.name, [])
                if ep.type_name not in types:
                    types.append(ep.type_name)
        return [(name, sorted(types)) for name, types in sorted(acc.items())]

    def endpoints_of(self, kind, name, domain_id):
        return [ep for ep in self.endpoints[kind].get(name, ()) if ep.node.domain_id == domain_id]

    def clear(self):
        with self.lock:
            self.nodes.clear()
            self._by_node.clear()
            for kind in self.endpoints:
                self.endpoints[kind].clear()
            self._changed()


GRAPH = Graph()


def history_deque(depth):
    return deque(maxlen=max(1, depth))
