"""rclpy.node.Node: names, entities, graph queries (parameters come from ParameterMixin)."""
import weakref

from labkit.graph import arguments as _arguments
from labkit.graph import names as _names
from labkit.graph.registry import GRAPH, NodeInfo, Endpoint, PUB, SUB, SRV, CLI, history_deque
from labkit.rclpy._entity import bump as _entity_bump
from labkit.rclpy._msgs import msg_class, type_name as _type_name
from labkit.rclpy.callback_groups import CallbackGroup  # noqa: F401 (rclpy.node has it)
from labkit.rclpy.callback_groups import (MutuallyExclusiveCallbackGroup,
                                          ReentrantCallbackGroup)
from labkit.rclpy.client import Client
from labkit.rclpy.clock import Clock, ROSClock  # noqa: F401
from labkit.rclpy.constants import S_TO_NS
from labkit.rclpy.context import Context  # noqa: F401
from labkit.rclpy.exceptions import InvalidTopicNameException  # noqa: F401
from labkit.rclpy.exceptions import (InvalidHandle, NotInitializedException, RCLError,
                                     UnknownROSArgsError)
from labkit.rclpy.expand_topic_name import expand_topic_name
from labkit.rclpy.guard_condition import GuardCondition
from labkit.rclpy.logging import get_logger
from labkit.rclpy.publisher import Publisher
from labkit.rclpy.qos import (DurabilityPolicy, HistoryPolicy, QoSProfile,
                              qos_profile_parameter_events, qos_profile_rosout_default,
                              qos_profile_services_default)
from labkit.rclpy.qos_event import PublisherEventCallbacks, SubscriptionEventCallbacks
from labkit.rclpy.service import Service
from labkit.rclpy.subscription import Subscription
from labkit.rclpy.timer import Rate, Timer
from labkit.rclpy.topic_endpoint_info import TopicEndpointInfo, TopicEndpointTypeEnum
from labkit.rclpy.utilities import get_default_context
from labkit.rclpy.validate_full_topic_name import validate_full_topic_name
from labkit.rclpy.validate_namespace import validate_namespace
from labkit.rclpy.validate_node_name import validate_node_name
from labkit.rclpy.validate_topic_name import validate_topic_name

try:   # written by the params helper; a bare stand-in keeps nodes usable without it
    from labkit.rclpy._node_parameters import ParameterMixin
except ImportError:  # pragma: no cover
    class ParameterMixin:
        def _init_parameters(self, *args, **kwargs):
            self._parameters = {}

try:
    from labkit.rclpy.parameter_service import ParameterService
except ImportError:  # pragma: no cover
    ParameterService = None


class NodeNameNonExistentError(RCLError):
    pass


NodeNameNonExistentError.__module__ = 'rclpy._rclpy_pybind11'


class _NodeHandle:
    """What rclpy's `node.handle` offers that tools use (a context manager)."""

    def __init__(self, node):
        self._node = weakref.ref(node)
        self.pointer = id(node)

    def __enter__(self):
        node = self._node()
        if node is None or node._destroyed:
            raise InvalidHandle('cannot use Destroyable because destruction was requested')
        return self

    def __exit__(self, *exc):
        return False

    def get_node_name(self):
        return self._node()._info.name

    def get_namespace(self):
        return self._node()._info.namespace

    def get_fully_qualified_name(self):
        return self._node()._info.fqn

    def logger_name(self):
        return self._node()._logger_name


def _logger_name(namespace, name):
    if namespace == '/':
        return name
    return namespace.strip('/').replace('/', '.') + '.' + name


class Node(ParameterMixin):
    PARAM_REL_TOL = 1e-6

    def __init__(self, node_name, *, context=None, cli_args=None, namespace=None,
                 use_global_arguments=True, enable_rosout=True, start_parameter_services=True,
                 parameter_overrides=None, allow_undeclared_parameters=False,
                 automatically_declare_parameters_from_overrides=False):
        self._destroyed = False
        self._context = get_default_context() if context is None else context
        self._publishers = []
        self._subscriptions = []
        self._clients = []
        self._services = []
        self._timers = []
        self._guards = []
        self.__waitables = []
        self._default_callback_group = MutuallyExclusiveCallbackGroup()
        self._rate_group = ReentrantCallbackGroup()
        self._executor_obj = None          # the executor, for the O(1) ready push
        self.__executor_weakref = None
        self._unclaimed = []               # entities with work while in no executor
        self._rosout_sink = None
        namespace = namespace or ''
        if not self._context.ok():
            raise NotInitializedException('cannot create node')

        # -- arguments: local (cli_args, implicitly --ros-args) and the context's global ones
        local = None
        if cli_args is not None:
            argv = ['--ros-args'] + list(cli_args)
            try:
                local = _arguments.parse(argv)
            except _arguments.ArgumentError as exc:
                raise RCLError(f'failed to parse arguments: {exc}') from None
            if local.unparsed_ros_args:
                raise UnknownROSArgsError(repr([argv[i] for i in local.unparsed_ros_args]))
        glob = self._context.arguments if use_global_arguments else None
        self._local_arguments = local
        self._global_arguments = glob
        self._rule_sets = [a.remaps for a in (local, glob) if a is not None]

        # -- names: validate like rcl_node_init, then apply __node/__ns remaps
        validate_node_name(node_name)
        namespace = _names.normalize_namespace(namespace)
        validate_namespace(namespace)
        node_name = _arguments.remap_node_name(self._rule_sets, node_name)
        namespace = _names.normalize_namespace(
            _arguments.remap_namespace(self._rule_sets, node_name, namespace))

        _refuse_unmappable_domain(self._context.get_domain_id())
        from labkit import process
        self._process = process.current()
        enclave = (glob.enclave if glob is not None and glob.enclave else '/')
        self._info = NodeInfo(node_name, namespace, enclave, self._context.get_domain_id(),
                              owner=self, process=self._process)
        GRAPH.add_node(self._info)
        self._process.rclpy.nodes.append(self)
        self.__node = _NodeHandle(self)
        self._logger_name = _logger_name(namespace, node_name)
        self._logger = get_logger(self._logger_name)

        from labkit.rclpy.impl import rcutils_logger
        if enable_rosout and rcutils_logger._config().rosout_logs:
            self._init_rosout()
        self._parameter_event_publisher = self.create_publisher(
            msg_class('rcl_interfaces/msg/ParameterEvent'), '/parameter_events',
            qos_profile_parameter_events)
        self._init_parameters(parameter_overrides, allow_undeclared_parameters,
                              automatically_declare_parameters_from_overrides)
        self._clock = ROSClock()
        from labkit.rclpy.time_source import TimeSource
        self._time_source = TimeSource(node=self)
        self._time_source.attach_clock(self._clock)
        if start_parameter_services and ParameterService is not None:
            self._parameter_service = ParameterService(self)

    # ------------------------------------------------------------ /rosout
    def _init_rosout(self):
        from labkit.rclpy.impl import rcutils_logger
        cfg = rcutils_logger._config()
        log_cls = msg_class('rcl_interfaces/msg/Log')
        ep = Endpoint(PUB, '/rosout', 'rcl_interfaces/msg/Log', self._info,
                      qos_profile_rosout_default)
        ep.history = history_deque(qos_profile_rosout_default.depth)
        pub = Publisher(ep, log_cls, '/rosout', qos_profile_rosout_default)
        pub._node = self
        pub._context = self._context
        GRAPH.add(ep)
        self._rosout_publisher = pub
        time_cls = msg_class('builtin_interfaces/msg/Time')

        def sink(level, name, msg, func, file, line, stamp_ns):
            if not pub._context._ok or pub._destroyed:
                return                  # rcl drops /rosout output once the context is gone
            sec, nsec = divmod(stamp_ns, S_TO_NS)
            pub.publish(log_cls(stamp=time_cls(sec=sec, nanosec=nsec), level=level, name=name,
                                msg=msg, file=file, function=func, line=line))

        sinks = cfg.rosout.setdefault(self._logger_name, [])
        if sinks:
            get_logger('rcl.logging_rosout').warning(
                'Publisher already registered for provided node name. If this is due to multiple '
                'nodes with the same name then all logs for that logger name will go out over '
                'the existing publisher. As soon as any node with that name is destructed it '
                'will unregister the publisher, preventing any further logs for that name from '
                'being published on the rosout topic.')
        else:
            sinks.append(sink)
        self._rosout_sink = (cfg, sink)

    # ------------------------------------------------------------ arguments
    def _parameter_overrides_from_args(self):
        """{name: value} from --params-file and -p rules for this node (global, then local)."""
        chain = [a for a in (self._global_arguments, self._local_arguments) if a is not None]
        return _arguments.parameter_overrides(chain, self._info.fqn)

    # ------------------------------------------------------------ entity lists
    @property
    def publishers(self):
        yield from self._publishers

    @property
    def subscriptions(self):
        yield from self._subscriptions

    @property
    def clients(self):
        yield from self._clients

    @property
    def services(self):
        yield from self._services

    @property
    def timers(self):
        yield from self._timers

    @property
    def guards(self):
        yield from self._guards

    @property
    def waitables(self):
        yield from self.__waitables

    @property
    def executor(self):
        if self.__executor_weakref:
            return self.__executor_weakref()
        return None

    @executor.setter
    def executor(self, new_executor):
        current_executor = self.executor
        if current_executor == new_executor:
            return
        if current_executor is not None:
            current_executor.remove_node(self)
        if new_executor is None:
            self.__executor_weakref = None
            self._executor_obj = None
        else:
            new_executor.add_node(self)
            self.__executor_weakref = weakref.ref(new_executor)

    def _wake_executor(self):
        executor = self.executor
        if executor:
            executor.wake()

    @property
    def context(self):
        return self._context

    @property
    def default_callback_group(self):
        return self._default_callback_group

    @property
    def handle(self):
        return self.__node

    @handle.setter
    def handle(self, value):
        raise AttributeError('handle cannot be modified after node creation')

    def get_name(self):
        with self.handle:
            return self._info.name

    def get_namespace(self):
        with self.handle:
            return self._info.namespace

    def get_fully_qualified_name(self):
        with self.handle:
            return self._info.fqn

    def get_clock(self):
        return self._clock

    def get_logger(self):
        return self._logger

    # ------------------------------------------------------------ names
    def _validate_topic_or_service_name(self, topic_or_service_name, *, is_service=False):
        name = self.get_name()
        namespace = self.get_namespace()
        validate_node_name(name)
        validate_namespace(namespace)
        validate_topic_name(topic_or_service_name, is_service=is_service)
        expanded = expand_topic_name(topic_or_service_name, name, namespace)
        validate_full_topic_name(expanded, is_service=is_service)

    def _validate_qos_or_depth_parameter(self, qos_or_depth):
        if isinstance(qos_or_depth, QoSProfile):
            return qos_or_depth
        elif isinstance(qos_or_depth, int):
            if qos_or_depth < 0:
                raise ValueError('history depth must be greater than or equal to zero')
            return QoSProfile(depth=qos_or_depth)
        raise TypeError(
            'Expected QoSProfile or int, but received {!r}'.format(type(qos_or_depth)))

    def _resolve(self, name, only_expand, is_service):
        """Expand, validate and remap a topic/service name like rcl_node_resolve_name."""
        try:
            self._validate_topic_or_service_name(name, is_service=is_service)
        except _names.ExpansionError as exc:
            kind = 'service' if is_service else 'topic'
            raise ValueError(f"{kind} name '{name}' is invalid: {exc}") from None
        expanded = _names.expand_topic_name(name, self._info.name, self._info.namespace)
        if only_expand:
            return expanded
        kind = _arguments.SERVICE if is_service else _arguments.TOPIC
        remapped = _arguments.remap_name(self._rule_sets, kind, expanded, self._info.name,
                                         self._info.namespace)
        if remapped != expanded:
            validate_full_topic_name(remapped, is_service=is_service)
        return remapped

    def resolve_topic_name(self, topic, *, only_expand=False):
        with self.handle:
            return self._resolve(topic, only_expand, False)

    def resolve_service_name(self, service, *, only_expand=False):
        with self.handle:
            return self._resolve(service, only_expand, True)

    # ------------------------------------------------------------ waitables
    def add_waitable(self, waitable):
        self.__waitables.append(waitable)
        waitable._node = self
        _entity_bump()
        self._wake_executor()

    def remove_waitable(self, waitable):
        self.__waitables.remove(waitable)
        _entity_bump()
        self._wake_executor()

    # ------------------------------------------------------------ create
    def _check_msg_type(self, msg_type):
        from labkit.rclpy.type_support import check_is_valid_msg_type
        check_is_valid_msg_type(msg_type)

    def create_publisher(self, msg_type, topic, qos_profile, *, callback_group=None,
                         event_callbacks=None, qos_overriding_options=None,
                         publisher_class=Publisher):
        qos_profile = self._validate_qos_or_depth_parameter(qos_profile)
        callback_group = callback_group or self.default_callback_group
        final_topic = self.resolve_topic_name(topic)
        self._check_msg_type(msg_type)
        ep = Endpoint(PUB, final_topic, _type_name(msg_type), self._info, qos_profile._copy())
        if qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL:
            if qos_profile.history == HistoryPolicy.KEEP_ALL:      # bounded as readers are
                from labkit.rclpy.subscription import KEEP_ALL_MAX_SAMPLES
                ep.history = history_deque(KEEP_ALL_MAX_SAMPLES)
            else:
                ep.history = history_deque(qos_profile.depth)
        publisher = publisher_class(
            ep, msg_type, topic, qos_profile,
            event_callbacks=event_callbacks or PublisherEventCallbacks(),
            callback_group=callback_group)
        publisher._node = self
        publisher._context = self._context
        ep.owner = publisher
        ep.on_incompatible = self._incompatible_warning(publisher, True)
        GRAPH.add(ep)
        self._publishers.append(publisher)
        self._wake_executor()
        return publisher

    def _incompatible_warning(self, entity, is_publisher):
        """The incompatible-QoS event: like rclpy, it is handled when the node spins."""
        from labkit.rclpy.qos_event import QoSEventHandler
        handler = QoSEventHandler(self, entity, is_publisher)
        entity.event_handlers.append(handler)
        return handler.occurred

    def create_subscription(self, msg_type, topic, callback, qos_profile, *, callback_group=None,
                            event_callbacks=None, qos_overriding_options=None, raw=False):
        qos_profile = self._validate_qos_or_depth_parameter(qos_profile)
        callback_group = callback_group or self.default_callback_group
        final_topic = self.resolve_topic_name(topic)
        self._check_msg_type(msg_type)
        ep = Endpoint(SUB, final_topic, _type_name(msg_type), self._info, qos_profile._copy())
        subscription = Subscription(
            ep, msg_type, topic, callback, callback_group, qos_profile, raw,
            event_callbacks=event_callbacks or SubscriptionEventCallbacks())
        subscription._node = self
        ep.owner = subscription
        ep.sink = subscription._deliver
        ep.on_incompatible = self._incompatible_warning(subscription, False)
        callback_group.add_entity(subscription)
        self._subscriptions.append(subscription)
        GRAPH.add(ep)
        self._wake_executor()
        return subscription

    def create_client(self, srv_type, srv_name, *, qos_profile=qos_profile_services_default,
                      callback_group=None):
        if callback_group is None:
            callback_group = self.default_callback_group
        from labkit.rclpy.type_support import check_is_valid_srv_type
        check_is_valid_srv_type(srv_type)
        final = self.resolve_service_name(srv_name)
        ep = Endpoint(CLI, final, _type_name(srv_type), self._info, qos_profile)
        client = Client(self.context, ep, srv_type, srv_name, qos_profile, callback_group)
        client._node = self
        ep.owner = client
        callback_group.add_entity(client)
        self._clients.append(client)
        GRAPH.add(ep)
        self._wake_executor()
        return client

    def create_service(self, srv_type, srv_name, callback, *,
                       qos_profile=qos_profile_services_default, callback_group=None):
        if callback_group is None:
            callback_group = self.default_callback_group
        from labkit.rclpy.type_support import check_is_valid_srv_type
        check_is_valid_srv_type(srv_type)
        final = self.resolve_service_name(srv_name)
        ep = Endpoint(SRV, final, _type_name(srv_type), self._info, qos_profile)
        service = Service(ep, srv_type, srv_name, callback, callback_group, qos_profile)
        service._node = self
        ep.owner = service
        ep.sink = service._deliver
        callback_group.add_entity(service)
        self._services.append(service)
        GRAPH.add(ep)
        self._wake_executor()
        return service

    def create_timer(self, timer_period_sec, callback, callback_group=None, clock=None):
        timer_period_nsec = int(float(timer_period_sec) * S_TO_NS)
        if callback_group is None:
            callback_group = self.default_callback_group
        if clock is None:
            clock = self._clock
        timer = Timer(callback, callback_group, timer_period_nsec, clock, context=self.context)
        timer._node = self
        callback_group.add_entity(timer)
        self._timers.append(timer)
        _bump_timers()
        self._wake_executor()
        return timer

    def create_guard_condition(self, callback, callback_group=None):
        if callback_group is None:
            callback_group = self.default_callback_group
        guard = GuardCondition(callback, callback_group, context=self.context)
        guard._node = self
        callback_group.add_entity(guard)
        self._guards.append(guard)
        self._wake_executor()
        return guard

    def create_rate(self, frequency, clock=None):
        if frequency <= 0:
            raise ValueError('frequency must be > 0')
        period = 1.0 / frequency
        timer = self.create_timer(period, None, self._rate_group, clock)
        return Rate(timer, context=self.context)

    # ------------------------------------------------------------ destroy
    def _destroy_entity(self, entity, collection):
        if entity in collection:
            collection.remove(entity)
            entity._destroy()
            self._wake_executor()
            return True
        return False

    def destroy_publisher(self, publisher):
        return self._destroy_entity(publisher, self._publishers)

    def destroy_subscription(self, subscription):
        return self._destroy_entity(subscription, self._subscriptions)

    def destroy_client(self, client):
        return self._destroy_entity(client, self._clients)

    def destroy_service(self, service):
        return self._destroy_entity(service, self._services)

    def destroy_timer(self, timer):
        ok = self._destroy_entity(timer, self._timers)
        _bump_timers()
        return ok

    def destroy_guard_condition(self, guard):
        return self._destroy_entity(guard, self._guards)

    def destroy_rate(self, rate):
        success = self.destroy_timer(rate._timer)
        rate.destroy()
        return success

    def destroy_node(self):
        """Destroy the node and everything it created; it leaves the graph."""
        if self._destroyed:
            return
        self._parameter_event_publisher = None
        while self._publishers:
            self.destroy_publisher(self._publishers[0])
        while self._subscriptions:
            self.destroy_subscription(self._subscriptions[0])
        while self._clients:
            self.destroy_client(self._clients[0])
        while self._services:
            self.destroy_service(self._services[0])
        while self._timers:
            self.destroy_timer(self._timers[0])
        while self._guards:
            self.destroy_guard_condition(self._guards[0])
        if self._rosout_sink is not None:
            cfg, sink = self._rosout_sink
            sinks = cfg.rosout.get(self._logger_name, [])
            # rcl: destroying any node of that name unregisters the /rosout publisher
            sinks.clear()
            self._rosout_publisher._destroy()
            self._rosout_sink = None
        self._destroyed = True
        GRAPH.remove_node(self._info)
        try:
            self._process.rclpy.nodes.remove(self)
        except ValueError:
            pass
        executor = self.executor
        if executor is not None:
            executor.remove_node(self)
        self._wake_executor()

    # ------------------------------------------------------------ graph queries
    def _domain(self):
        return self._info.domain_id

    def _by_node(self, kinds, node_name, node_namespace, what):
        with self.handle:
            ns = node_namespace or '/'
            if not any(n.name == node_name and n.namespace == ns
                       for n in GRAPH.node_infos(self._domain())):
                raise NodeNameNonExistentError(
                    f'cannot get {what} names and types for nonexistent node: error not set')
            return GRAPH.names_and_types(kinds, self._domain(), (node_name, ns))

    def get_publisher_names_and_types_by_node(self, node_name, node_namespace,
                                              no_demangle=False):
        return self._by_node([PUB], node_name, node_namespace, 'publisher')

    def get_subscriber_names_and_types_by_node(self, node_name, node_namespace,
                                               no_demangle=False):
        return self._by_node([SUB], node_name, node_namespace, 'subscriber')

    def get_service_names_and_types_by_node(self, node_name, node_namespace):
        return self._by_node([SRV], node_name, node_namespace, 'service')

    def get_client_names_and_types_by_node(self, node_name, node_namespace):
        return self._by_node([CLI], node_name, node_namespace, 'client')

    def get_topic_names_and_types(self, no_demangle=False):
        with self.handle:
            return GRAPH.names_and_types([PUB, SUB], self._domain())

    def get_service_names_and_types(self):
        # rmw lists every rq/rr topic, so a service with only clients is listed too
        with self.handle:
            return GRAPH.names_and_types([SRV, CLI], self._domain())

    def get_node_names(self):
        return [n[0] for n in self.get_node_names_and_namespaces()]

    def get_node_names_and_namespaces(self):
        with self.handle:
            return [(n.name, n.namespace) for n in GRAPH.node_infos(self._domain())]

    def get_node_names_and_namespaces_with_enclaves(self):
        with self.handle:
            return [(n.name, n.namespace, n.enclave) for n in GRAPH.node_infos(self._domain())]

    def _count(self, topic_name, kind):
        fq = expand_topic_name(topic_name, self.get_name(), self.get_namespace())
        validate_full_topic_name(fq)
        with self.handle:
            return len(GRAPH.endpoints_of(kind, fq, self._domain()))

    def count_publishers(self, topic_name):
        return self._count(topic_name, PUB)

    def count_subscribers(self, topic_name):
        return self._count(topic_name, SUB)

    def _get_info_by_topic(self, topic_name, no_mangle, kind):
        with self.handle:
            if no_mangle:
                fq = topic_name
            else:
                fq = expand_topic_name(topic_name, self.get_name(), self.get_namespace())
                validate_full_topic_name(fq)
                fq = _arguments.remap_name(self._rule_sets, _arguments.TOPIC, fq,
                                           self._info.name, self._info.namespace)
            etype = (TopicEndpointTypeEnum.PUBLISHER if kind == PUB
                     else TopicEndpointTypeEnum.SUBSCRIPTION)
            return [TopicEndpointInfo(node_name=ep.node.name, node_namespace=ep.node.namespace,
                                      topic_type=ep.type_name, endpoint_type=etype,
                                      endpoint_gid=list(ep.gid),
                                      qos_profile=_discovered_qos(ep.qos))
                    for ep in GRAPH.endpoints_of(kind, fq, self._domain())]

    def get_publishers_info_by_topic(self, topic_name, no_mangle=False):
        return self._get_info_by_topic(topic_name, no_mangle, PUB)

    def get_subscriptions_info_by_topic(self, topic_name, no_mangle=False):
        return self._get_info_by_topic(topic_name, no_mangle, SUB)

    def __repr__(self):
        return f'<rclpy.node.Node {self._info.fqn}>'


def _discovered_qos(qos):
    """The QoS as discovery reports it under Humble (rmw_fastrtps): no history/depth,
    system defaults resolved, 0 durations shown as infinite."""
    from labkit.rclpy.duration import Infinite
    from labkit.rclpy.qos import HistoryPolicy, LivelinessPolicy, ReliabilityPolicy

    def dur(d):
        return Infinite if d.nanoseconds == 0 else d
    return QoSProfile(
        history=HistoryPolicy.UNKNOWN, depth=0,
        reliability=(ReliabilityPolicy.RELIABLE
                     if qos.reliability == ReliabilityPolicy.SYSTEM_DEFAULT else qos.reliability),
        durability=(DurabilityPolicy.VOLATILE
                    if qos.durability == DurabilityPolicy.SYSTEM_DEFAULT else qos.durability),
        lifespan=dur(qos.lifespan), deadline=dur(qos.deadline),
        liveliness=(LivelinessPolicy.AUTOMATIC
                    if qos.liveliness == LivelinessPolicy.SYSTEM_DEFAULT else qos.liveliness),
        liveliness_lease_duration=dur(qos.liveliness_lease_duration),
        avoid_ros_namespace_conventions=qos.avoid_ros_namespace_conventions)


def _bump_timers():
    _entity_bump()


# Fast DDS (Humble's default rmw) maps a domain to UDP ports 7400 + 250 * domain + offset:
# above 232 the port passes 65535 and the participant of the first node is refused; Fast DDS
# prints this line and ends the whole process with EXIT_FAILURE (PortParameters.h)
_MAX_MAPPABLE_DOMAIN_ID = 232


def _refuse_unmappable_domain(domain_id):
    if domain_id > _MAX_MAPPABLE_DOMAIN_ID:
        import sys
        sys.stdout.write('Calculated port number is too high. Probably the domainId is over '
                         '232 or portBase is too high.\n')
        sys.stdout.flush()
        raise SystemExit(1)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
