"""One Cyclone DDS participant per labkit process, mirroring the in-process graph.

Local endpoints get a DDS reader or writer each (`rt/`, `rq/`, `rr/` names, the
ROS type names, the same QoS); remote ones, found through DDS discovery and the
peers' `ros_discovery_info`, become ordinary graph entries whose node is a
`RemoteNode`. Nothing above this room knows whether a peer is local or remote.

Threads: one bridge thread waits on a DDS WaitSet (the GIL is free while it
waits), takes what arrived and hands it to local sinks, sends what is left of a fast
publisher's batch (labkit.dds.batching), creates and deletes DDS
entities and changes the remote part of the graph; a graph listener only wakes it.
No Python code runs on Cyclone's own threads (no DDS listeners): a Python callback
there would need the GIL while Cyclone holds its locks.
"""
import itertools
import os
import random
import sys
import threading
import time


from labkit.graph.registry import GRAPH, NodeInfo, Endpoint, PUB, SUB, SRV, CLI
from labkit.dds import batching, config, discovery, sockets, typehash, wire

BARE_NODE = "_CREATED_BY_BARE_DDS_APP_"
FASTDDS_VENDOR = b"\x01\x0f"
FASTDDS_CLIENT_LINE = (
    "[WARN] [labkit.dds]: a Fast DDS client called the labkit service '{name}': Fast DDS "
    "matches replies by the RTPS related-sample-identity, which Cyclone DDS cannot set, so "
    "the reply never reaches it. Start the caller with RMW_IMPLEMENTATION=rmw_cyclonedds_cpp.")


OVERSIZE_LINE = ("[WARN] [labkit.dds]: failed to publish data on '{name}' over DDS: a sample of "
                 "{size} bytes is larger than Cyclone DDS accepts (MaxSampleSize); "
                 "subscribers in this process still get it")


DDS_RETCODE_ERROR = -1
REPLY_MATCH_WAIT_S = 3.0        # how long a reply waits for the client's reply reader
SENDER_WAIT_S = 5.0             # how long a request waits for discovery to name its sender


class RemoteNode(NodeInfo):
    """A node of another process, seen through DDS."""
    __slots__ = ("remote", "participant")

    def __init__(self, name, namespace, domain_id, participant):
        super().__init__(name, namespace, "/", domain_id)
        self.remote = True
        self.participant = participant


def is_remote(node):
    return getattr(node, "remote", False)


def _mask():
    from cyclonedds.core import SampleState, ViewState, InstanceState
    return SampleState.Any | ViewState.Any | InstanceState.Any


def _message_class(type_name, part=None):
    from labkit.interfaces import get_type
    cls = get_type(type_name)
    return getattr(cls, part) if part else cls


class Bridge:
    def __init__(self, domain_id, localhost=True, distro=None):
        from cyclonedds.domain import Domain, DomainParticipant
        from cyclonedds.core import WaitSet, GuardCondition, ReadCondition
        from cyclonedds.builtin import (BuiltinDataReader, BuiltinTopicDcpsParticipant,
                                        BuiltinTopicDcpsPublication, BuiltinTopicDcpsSubscription)
        from cyclonedds.qos import Qos, Policy
        self.domain_id = domain_id
        self.localhost = localhost
        self.gid_size = discovery.gid_size(distro if distro is not None else config.distro())
        self._distro_given = distro is not None or bool(os.environ.get("ROS_DISTRO"))
        self._mask = _mask()
        self._stop = False
        self._dirty = True
        self.last_discovery = time.monotonic()   # when discovery last brought news
        self._news = threading.Condition()        # notified when it does
        self._lock = threading.RLock()
        before = sockets.open_sockets()
        self._domain = Domain(domain_id, config.with_user_config(config.cyclone_xml(localhost)))
        # rmw puts the security enclave in the participant's user data
        self.participant = DomainParticipant(domain_id, qos=Qos(Policy.Userdata(b"enclave=/;")))
        # Cyclone binds its receive sockets to the wildcard address: on loopback only
        self.loopback_sockets = sockets.confine(before, localhost is not False,
                                                config.LOOPBACK_DEVICE)
        self.guid = self.participant.guid.bytes
        self._topics = {}
        self._mirrors = {}            # local Endpoint -> _Mirror
        self._by_gid = {}             # local client endpoint gid -> _Mirror
        self._nodes_published = None
        self._remote_eps = {}         # DDS GUID -> DcpsEndpoint sample (and kind)
        self._participants = set()
        self._infos = {}              # participant GUID -> [(ns, name, readers, writers)]
        self._graph_nodes = {}        # (participant, ns, name) -> RemoteNode
        self._graph_eps = {}          # DDS GUID -> (signature, Endpoint)
        self._fastdds_warned = set()
        self._warned = set()          # (kind, name) of the one-line warnings already given
        self.client_ids = itertools.count(random.getrandbits(40) << 20)
        self._waitset = WaitSet(self.participant)
        self._guard = GuardCondition(self.participant)
        self._waitset.attach(self._guard)
        self._conditions = {}         # reader -> its ReadCondition on the waitset
        self._ReadCondition = ReadCondition
        self._builtin = [
            BuiltinDataReader(self.participant, BuiltinTopicDcpsParticipant),
            BuiltinDataReader(self.participant, BuiltinTopicDcpsPublication),
            BuiltinDataReader(self.participant, BuiltinTopicDcpsSubscription)]
        for reader in self._builtin:
            self._watch(reader)
        info_qos = Qos(Policy.Reliability.Reliable(100_000_000), Policy.Durability.TransientLocal,
                       Policy.History.KeepLast(1))
        self._info_writer = self._writer(discovery.TOPIC, discovery.DDS_TYPE, info_qos)
        self._info_reader = self._reader(
            discovery.TOPIC, discovery.DDS_TYPE,
            Qos(Policy.Reliability.Reliable(100_000_000), Policy.Durability.TransientLocal,
                Policy.History.KeepLast(64)))
        self._publish_info()
        GRAPH.listeners.append(self._graph_changed)
        self._thread = threading.Thread(target=self._run, name="labkit-dds", daemon=True)
        self._thread.start()

    # ------------------------------------------------------------ DDS helpers
    def _topic(self, name, dds_type):
        from cyclonedds.topic import Topic
        key = (name, dds_type)
        topic = self._topics.get(key)
        if topic is None:
            topic = self._topics[key] = Topic(self.participant, name, wire.raw_type(dds_type))
        return topic

    @staticmethod
    def _ignore_local(qos):
        # a process must not hear its own mirrored writers (it delivers in-process)
        from cyclonedds.qos import Qos, Policy
        return Qos(*qos, Policy.IgnoreLocal.Participant)

    def _writer(self, name, dds_type, qos, batch=False):
        from cyclonedds.pub import DataWriter
        from cyclonedds.qos import Qos
        qos = self._ignore_local(qos)
        if batch:               # a topic's writer: see labkit.dds.batching
            qos = Qos(*qos, batching.POLICY)
        return DataWriter(self.participant, self._topic(name, dds_type), qos=qos)

    def _reader(self, name, dds_type, qos):
        from cyclonedds.sub import DataReader
        reader = DataReader(self.participant, self._topic(name, dds_type),
                            qos=self._ignore_local(qos))
        self._watch(reader)
        return reader

    def _watch(self, reader):
        cond = self._ReadCondition(reader, self._mask)
        self._waitset.attach(cond)
        self._conditions[reader] = cond

    def delete_reader(self, reader):
        cond = self._conditions.pop(reader, None)
        if cond is not None:
            try:
                self._waitset.detach(cond)
                cond.__del__()
            except Exception:
                pass
        reader.__del__()

    def _graph_changed(self):
        self._dirty = True
        self.wake()

    def wake(self):
        try:
            self._guard.set(True)
        except Exception:
            pass

    def take(self, reader):
        """[(bytes, sample_info)] of valid samples (a leaving writer's invalid one is dropped)."""
        from cyclonedds._clayer import ddspy_take
        out = ddspy_take(reader._ref, self._mask, 256)
        if isinstance(out, int):
            return []
        return [(bytes(data), info) for data, info in out if info.valid_data]

    # ------------------------------------------------------------ the thread
    def _run(self):
        waiting = False
        while not self._stop:
            try:
                self._waitset.wait(50_000_000 if waiting else 250_000_000)
                self._guard.set(False)
            except Exception:
                pass
            if self._stop:
                break
            try:
                with self._lock:
                    for mirror in list(self._mirrors.values()):
                        if mirror.reader is not None:
                            mirror.on_data()
                        if mirror.batch is not None:
                            mirror.batch.send()
                    if self._dirty:
                        self._dirty = False
                        self._sync_local()
                    self._sync_remote()
                    waiting = False
                    for mirror in list(self._mirrors.values()):
                        if mirror.waiting:
                            mirror.flush()
                            waiting = waiting or mirror.waiting
            except Exception as exc:        # never let the bridge thread die silently
                if os.environ.get("LABKIT_DDS_DEBUG"):
                    import traceback
                    traceback.print_exc()
                else:
                    print(f"[WARN] [labkit.dds]: {type(exc).__name__}: {exc}", file=sys.stderr)

    def missing_infos(self):
        """Peers with ROS endpoints whose ros_discovery_info has not arrived yet."""
        with self._lock:
            self._sync_remote()
            return [p for p in self._participants if p not in self._infos]

    def sync(self):
        """Bring the DDS mirror up to date now (used before graph queries)."""
        with self._lock:
            self._sync_local()
            self._sync_remote()

    def close(self):
        self._stop = True
        self.wake()
        if self._thread is not threading.current_thread():
            self._thread.join(5)
        try:
            GRAPH.listeners.remove(self._graph_changed)
        except ValueError:
            pass
        with self._lock:
            for ep, mirror in list(self._mirrors.items()):
                mirror.close()
            self._mirrors.clear()
            with GRAPH.lock:
                for _, ep in self._graph_eps.values():
                    GRAPH._remove(ep)
                for node in self._graph_nodes.values():
                    if node in GRAPH.nodes:
                        GRAPH.nodes.remove(node)
                GRAPH._changed()
            self._graph_eps.clear()
            self._graph_nodes.clear()
            for cond in self._conditions.values():
                try:
                    self._waitset.detach(cond)
                except Exception:
                    pass
            self._conditions.clear()
            for entity in [*self._builtin, self._info_writer, self._info_reader, self._guard,
                           self._waitset, *self._topics.values(), self.participant, self._domain]:
                try:
                    entity.__del__()
                except Exception:
                    pass
            self._topics.clear()

    # ------------------------------------------------------------ local -> DDS
    def _local_endpoints(self):
        with GRAPH.lock:
            out = []
            for kind in (PUB, SUB, SRV, CLI):
                for eps in GRAPH.endpoints[kind].values():
                    for ep in eps:
                        if not is_remote(ep.node) and ep.node.domain_id == self.domain_id:
                            out.append(ep)
            nodes = [n for n in GRAPH.nodes
                     if not is_remote(n) and n.domain_id == self.domain_id]
            return out, nodes

    def _sync_local(self):
        eps, nodes = self._local_endpoints()
        alive = set(map(id, eps))
        changed = False
        for ep in list(self._mirrors):
            if id(ep) not in alive:
                self._mirrors.pop(ep).close()
                changed = True
        for ep in eps:
            if ep not in self._mirrors:
                try:
                    mirror = _Mirror(self, ep)
                except LookupError:
                    continue                  # a type labkit cannot load: stays local
                self._mirrors[ep] = mirror
                changed = True
        if changed or self._nodes_published != self._node_signature(nodes):
            self._publish_info(nodes)

    def _node_signature(self, nodes):
        return [(n.namespace, n.name, id(n)) for n in nodes]

    def _publish_info(self, nodes=()):
        by_node = {}
        for ep, mirror in self._mirrors.items():
            entry = by_node.setdefault(id(ep.node), ([], []))
            entry[0].extend(mirror.reader_gids())
            entry[1].extend(mirror.writer_gids())
        listed = [(n.namespace, n.name, *by_node.get(id(n), ([], []))) for n in nodes]
        data = discovery.encode(self.guid, listed, self.gid_size)
        from cyclonedds._clayer import ddspy_write
        ddspy_write(self._info_writer._ref, wire.pad4(data))
        self._nodes_published = self._node_signature(nodes)

    # ------------------------------------------------------------ DDS -> graph
    def _sync_remote(self):
        """Take what discovery brought; rebuild the remote graph entries if anything did."""
        part_reader, pub_reader, sub_reader = self._builtin
        from cyclonedds.core import InstanceState
        changed = False
        for sample in part_reader.take(256):
            changed = True
            key = sample.key.bytes
            if sample.sample_info.instance_state == InstanceState.Alive:
                if key != self.guid:
                    self._participants.add(key)
            else:
                self._participants.discard(key)
                self._infos.pop(key, None)
        for reader, kind in ((pub_reader, "writer"), (sub_reader, "reader")):
            for sample in reader.take(256):
                changed = True
                key = sample.key.bytes
                if sample.sample_info.instance_state == InstanceState.Alive:
                    if sample.participant_key.bytes != self.guid:
                        self._remote_eps[key] = (kind, sample)
                else:
                    self._remote_eps.pop(key, None)
        for data, info in self.take(self._info_reader):
            try:
                participant, nodes = discovery.decode(data, self.gid_size)
            except discovery.DecodeError:
                try:
                    participant, nodes = discovery.decode(data)
                except discovery.DecodeError:
                    continue
                self._follow_peer_layout()
            if participant != self.guid:
                self._infos[participant] = nodes
                changed = True
        if changed:
            self.last_discovery = time.monotonic()
            self._rebuild_remote()
            with self._news:
                self._news.notify_all()

    def wait_news(self, timeout):
        """Block until discovery brings something new, or `timeout` seconds."""
        with self._news:
            self._news.wait(timeout)

    def peers(self):
        """The other DDS participants discovered so far."""
        with self._lock:
            return list(self._participants)

    def _follow_peer_layout(self):
        """A peer speaks the other Gid layout (Humble 24 bytes, Jazzy and later 16): with
        no ROS_DISTRO saying which one we are, speak the peers' so they list our nodes."""
        if self._distro_given:
            return
        self.gid_size = (discovery.JAZZY_GID if self.gid_size == discovery.HUMBLE_GID
                         else discovery.HUMBLE_GID)
        self._distro_given = True        # switch once
        self._dirty = True
        self._nodes_published = None     # republish ros_discovery_info in the new layout

    def _rebuild_remote(self):
        owner = {}
        wanted_nodes = {}
        for participant, nodes in self._infos.items():
            if participant not in self._participants:
                continue
            for namespace, name, readers, writers in nodes:
                key = (participant, namespace, name)
                wanted_nodes[key] = True
                for g in (*readers, *writers):
                    owner[g] = key
        wanted_eps = {}
        for key, (kind, sample) in self._remote_eps.items():
            role, name = wire.entity_from_dds(sample.topic_name)
            if role is None or role == wire.REPLY:
                continue
            type_name, _ = wire.type_from_dds(sample.type_name)
            if type_name is None:
                continue
            if role == wire.TOPIC:
                ep_kind = PUB if kind == "writer" else SUB
            else:
                ep_kind = SRV if kind == "reader" else CLI
            node_key = owner.get(key) or (sample.participant_key.bytes, "/", BARE_NODE)
            wanted_eps[key] = ((ep_kind, name, type_name, node_key), sample)
        with GRAPH.lock:
            changed = False
            for key in list(self._graph_eps):
                signature, ep = self._graph_eps[key]
                if key not in wanted_eps or wanted_eps[key][0] != signature:
                    GRAPH._remove(ep)
                    del self._graph_eps[key]
                    changed = True
            for key in list(self._graph_nodes):
                if key not in wanted_nodes:
                    node = self._graph_nodes.pop(key)
                    if node in GRAPH.nodes:
                        GRAPH.nodes.remove(node)
                    changed = True
            for key in wanted_nodes:
                if key not in self._graph_nodes:
                    node = self._node(key)
                    GRAPH.nodes.append(node)
                    changed = True
            for key, (signature, sample) in wanted_eps.items():
                if key in self._graph_eps:
                    continue
                ep_kind, name, type_name, node_key = signature
                node = self._graph_nodes.get(node_key) or self._node(node_key, listed=False)
                ep = Endpoint(ep_kind, name, type_name, node, wire.qos_from_dds(sample.qos))
                ep.gid = discovery.make_gid(key, self.gid_size)
                if ep_kind == SRV:
                    ep.sink = self._remote_service_sink(ep, sample)
                GRAPH.endpoints[ep_kind].setdefault(name, []).append(ep)
                if ep_kind in (PUB, SUB):
                    GRAPH._rematch(name, new=ep)
                self._graph_eps[key] = (signature, ep)
                changed = True
            if changed:
                GRAPH._changed()

    def _node(self, key, listed=True):
        participant, namespace, name = key
        node = RemoteNode(name, namespace, self.domain_id, participant)
        node.gid = discovery.make_gid(participant, self.gid_size)
        if listed:
            self._graph_nodes[key] = node
        return node

    # ------------------------------------------------------------ services
    def _remote_service_sink(self, server_ep, sample):
        fastdds = sample.participant_key.bytes[:2] == FASTDDS_VENDOR

        def sink(request_and_header):
            request, header = request_and_header
            with self._lock:
                mirror = self._by_gid.get(header.request_id.writer_guid)
                if mirror is None:      # the client is newer than the last sync
                    self._sync_local()
                    mirror = self._by_gid.get(header.request_id.writer_guid)
            if mirror is not None:
                mirror.send_request(request, header, fastdds)
        return sink

    def writer_participant(self, handle):
        """The participant GUID of a remote writer, by its instance handle (discovery)."""
        with self._lock:
            self._sync_remote()
            for kind, sample in self._remote_eps.values():
                if kind == "writer" and sample.sample_info.instance_handle == handle:
                    return sample.participant_key.bytes
        return None

    def warn_once(self, key, line):
        if key not in self._warned:
            self._warned.add(key)
            print(line, file=sys.stderr, flush=True)

    def warn_fastdds_client(self, name):
        if name not in self._fastdds_warned:
            self._fastdds_warned.add(name)
            print(FASTDDS_CLIENT_LINE.format(name=name), file=sys.stderr, flush=True)


class _Mirror:
    """The DDS reader/writer(s) of one local endpoint."""

    def __init__(self, bridge, ep):
        self.bridge = bridge
        self.ep = ep
        self.reader = self.writer = self.batch = None
        self.waiting = False
        self.unsure = []          # requests whose sender discovery has not named yet
        self.outbox = []
        kind = ep.kind
        if kind in (PUB, SUB):
            self.cls = _message_class(ep.type_name)
            dds_type = wire.type_to_dds(ep.type_name)
            name = wire.topic_to_dds(ep.name)
            # Jazzy: the RIHS01 hash in the user data
            ud = typehash.user_data(ep.type_name) if bridge.gid_size == discovery.JAZZY_GID else b""
            if kind == PUB:
                self.writer = bridge._writer(name, dds_type, wire.qos_to_dds(ep.qos, user_data=ud),
                                             batch=True)
                keep_all = int(ep.qos.history) == 2
                self.batch = batching.Batch(self.writer._ref, bridge.wake,
                                            batching.MAX_PENDING if keep_all
                                            else int(ep.qos.depth or 10))
                for msg in list(ep.history or ()):   # latched before the writer existed
                    self._publish(msg)
                ep.bridge = self._publish
                GRAPH.rematch(ep.name)
            else:
                self.reader = bridge._reader(name, dds_type,
                                             wire.qos_to_dds(ep.qos, reader=True, user_data=ud))
                self.on_data = self._on_message
            # its gid is now its DDS GUID, as peers and ros_discovery_info name it
            ep.gid = discovery.make_gid((self.writer or self.reader).guid.bytes, bridge.gid_size)
            return
        srv = _message_class(ep.type_name)
        self.request_cls, self.response_cls = srv.Request, srv.Response
        req_type = wire.type_to_dds(ep.type_name, "_Request")
        rep_type = wire.type_to_dds(ep.type_name, "_Response")
        qos = wire.qos_to_dds(ep.qos)
        if kind == SRV:
            self.reader = bridge._reader(wire.request_topic(ep.name), req_type, qos)
            self.on_data = self._on_request
            self.writer = bridge._writer(wire.reply_topic(ep.name), rep_type, qos)
            self._senders = {}
        else:
            self.writer = bridge._writer(wire.request_topic(ep.name), req_type, qos)
            self.reader = bridge._reader(wire.reply_topic(ep.name), rep_type, qos)
            self.on_data = self._on_reply
            self.client_id = next(bridge.client_ids)
            self.pending = {}         # sequence -> local header
            self.fifo = []            # Fast DDS servers: replies carry no header
            self.outbox = []
            bridge._by_gid[ep.gid] = self

    def reader_gids(self):
        return [self.reader.guid.bytes] if self.reader is not None else []

    def writer_gids(self):
        return [self.writer.guid.bytes] if self.writer is not None else []

    def close(self):
        if self.ep.kind == PUB:
            self.ep.bridge = None
            GRAPH.rematch(self.ep.name)
        if self.ep.kind == CLI:
            self.bridge._by_gid.pop(self.ep.gid, None)
        reader, writer = self.reader, self.writer
        self.reader = self.writer = None
        try:
            if reader is not None:
                self.bridge.delete_reader(reader)
            if writer is not None:
                writer.__del__()
        except Exception:
            pass

    # -- topics
    def _publish(self, msg):
        from labkit.interfaces import rmw_serialize
        from cyclonedds._clayer import ddspy_write
        writer = self.writer
        if writer is not None:
            data = wire.pad4(rmw_serialize(msg))
            # DDS_RETCODE_ERROR: Cyclone refused the sample (a timeout is another code)
            if ddspy_write(writer._ref, data) == DDS_RETCODE_ERROR:
                self.bridge.warn_once(("size", self.ep.name),
                                      OVERSIZE_LINE.format(name=self.ep.name, size=len(data)))
            self.batch.wrote(len(data))

    def _on_message(self):
        from labkit.interfaces import deserialize
        sink = self.ep.sink
        for data, _ in self.bridge.take(self.reader):
            try:
                msg = deserialize(data, self.cls)
            except Exception:
                continue
            if sink is not None:
                sink(msg)

    # -- a local service answering remote clients
    def _on_request(self):
        for data, info in self.bridge.take(self.reader):
            self._request(data, info.publication_handle, info.source_timestamp,
                          time.monotonic() + SENDER_WAIT_S)

    def _request(self, data, handle, stamp, deadline):
        from labkit.interfaces import deserialize
        caller = self._caller(self.reader, handle)
        if caller is None and time.monotonic() < deadline:
            # a request can arrive before discovery tells whose writer sent it; a
            # reliable writer never sends it again, so keep it and look again (flush)
            self.unsure.append((data, handle, stamp, deadline))
            self.waiting = True
            return
        if caller is not None and caller[:2] == FASTDDS_VENDOR:
            self.bridge.warn_fastdds_client(self.ep.name)
            return
        try:
            client_id, seq, body = wire.unframe_request(data)
            request = deserialize(body, self.request_cls)
        except Exception:
            return
        # rclpy's own request header (imported late: rclpy sits above this room)
        from labkit.rclpy.service import RequestHeader, RequestId
        header = RequestHeader(RequestId(client_id.to_bytes(8, "little") + bytes(8), seq),
                               self._make_reply(client_id, seq, caller), stamp)
        if self.ep.sink is not None:
            self.ep.sink((request, header))

    def _caller(self, reader, handle):
        """The participant GUID of the client that wrote a request (None: not known yet)."""
        known = self._senders.get(handle)
        if known is None:
            try:
                known = reader.get_matched_publication_data(handle).participant_key.bytes
            except Exception:         # no match data (yet): DDS discovery knows the writer
                known = self.bridge.writer_participant(handle)
                if known is None:
                    return None       # ask again with its next request
            self._senders[handle] = known
        return known

    def _reply_reader_matched(self, participant):
        writer = self.writer
        try:
            for handle in writer.get_matched_subscriptions():
                if writer.get_matched_subscription_data(handle).participant_key.bytes == participant:
                    return True
        except Exception:
            return True               # cannot tell: send
        return False

    def _make_reply(self, client_id, seq, caller):
        def reply(header, response):
            from labkit.interfaces import rmw_serialize
            from cyclonedds._clayer import ddspy_write
            # the client may have found our request reader before our reply writer has
            # found its reply reader: a volatile reply written now would be lost and the
            # caller would wait forever: wait for it, bounded (rmw_cyclonedds_cpp guards
            # against the same race before it sends a response).
            end = time.monotonic() + REPLY_MATCH_WAIT_S
            while (caller is not None and self.writer is not None
                   and not self._reply_reader_matched(caller) and time.monotonic() < end):
                time.sleep(0.01)
            writer = self.writer
            if writer is not None:
                ddspy_write(writer._ref, wire.frame_request(client_id, seq,
                                                            rmw_serialize(response)))
        return reply

    # -- a local client calling a remote service
    def send_request(self, request, header, fastdds):
        from labkit.interfaces import rmw_serialize
        payload = rmw_serialize(request)
        seq = header.request_id.sequence_number
        with self.bridge._lock:
            if fastdds:
                self.fifo.append(header)
                data = wire.pad4(payload)
            else:
                self.pending[seq] = header
                data = wire.frame_request(self.client_id, seq, payload)
            self.outbox.append(data)
            self.waiting = True
            self.flush()
            if self.waiting:
                self.bridge.wake()

    def flush(self):
        """Look again at requests from senders not yet known; send queued requests once
        the server's reader and writer are matched."""
        from cyclonedds._clayer import ddspy_write
        if self.unsure:
            pending, self.unsure = self.unsure, []
            for item in pending:
                self._request(*item)
        writer, reader = self.writer, self.reader
        if writer is None:
            self.outbox.clear()
            self.waiting = bool(self.unsure)
            return
        if not self.outbox:
            self.waiting = bool(self.unsure)
            return
        try:
            ready = (writer.get_matched_subscriptions() and reader.get_matched_publications())
        except Exception:
            ready = True
        if not ready:
            return
        for data in self.outbox:
            ddspy_write(writer._ref, data)
        self.outbox.clear()
        self.waiting = bool(self.unsure)

    def _on_reply(self):
        from labkit.interfaces import deserialize
        for data, _ in self.bridge.take(self.reader):
            header = None
            body = data
            if self.pending and len(data) >= 4 + wire.HEADER.size:
                client_id, seq, rest = wire.unframe_request(data)
                if client_id == self.client_id:
                    header = self.pending.pop(seq, None)
                    body = rest
                elif not self.fifo:
                    continue              # another client's reply
            if header is None:
                if not self.fifo:
                    continue
                header = self.fifo.pop(0)
            try:
                response = deserialize(body, self.response_cls)
            except Exception:
                continue
            reply = header._reply
            if reply is not None:
                reply(header, response)


