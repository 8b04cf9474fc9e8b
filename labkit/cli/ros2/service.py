"""ros2 service list | type | find | call (ros2service)."""
from labkit.cli.ros2._base import (
    NODE_NAME_PREFIX, CliError, CliNode, GaveUp, add_verbs, load_yaml_values, patience,
    service_names_and_types, set_message_fields)
from labkit.cli.ros2.daemon import strategy


def add_arguments(parser, cli_name):
    parser.add_argument('--include-hidden-services', action='store_true',
                        help='Consider hidden services as well')
    add_verbs(parser, cli_name, [
        ('call', 'Call a service', _call_args, call),
        ('find', 'Output a list of available services of a given type', _find_args, find),
        ('list', 'Output a list of available services', *strategy(_list_args, list_)),
        ('type', "Output a service's type", _type_args, type_),
    ])


def _hidden_flag(p):
    p.add_argument('--include-hidden-services', action='store_true',
                   help='Consider hidden services as well')


def _list_args(p):
    p.add_argument('-t', '--show-types', action='store_true',
                   help='Additionally show the service type')
    p.add_argument('-c', '--count-services', action='store_true',
                   help='Only display the number of services discovered')
    _hidden_flag(p)


def list_(args, io):
    with CliNode() as node:
        services = service_names_and_types(node, args.include_hidden_services)
    if args.count_services:
        io.print(len(services))
        return
    for name, types in services:
        io.print(f'{name} [{", ".join(types)}]' if args.show_types else name)


def _type_args(p):
    p.add_argument('service_name',
                   help="Name of the ROS service to get type (e.g. '/talker/list_parameters')")


def type_(args, io):
    with CliNode() as node:
        services = service_names_and_types(node, args.include_hidden_services)
    for name, types in services:
        if name == args.service_name:
            for t in types:
                io.print(t)
            return 0
    return 1


def _find_args(p):
    p.add_argument('service_type',
                   help="Name of the ROS service type to filter for "
                        "(e.g. 'rcl_interfaces/srv/ListParameters')")
    p.add_argument('-c', '--count-services', action='store_true',
                   help='Only display the number of services discovered')
    _hidden_flag(p)


def find(args, io):
    with CliNode() as node:
        services = service_names_and_types(node, args.include_hidden_services)
    found = [n for n, types in services if args.service_type in types]
    if args.count_services:
        io.print(len(found))
    else:
        for name in found:
            io.print(name)


def _call_args(p):
    p.add_argument('service_name',
                   help="Name of the ROS service to call to (e.g. '/add_two_ints')")
    p.add_argument('service_type', help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    p.add_argument('values', nargs='?', default='{}',
                   help="Values to fill the service request with in YAML format (e.g. "
                        "'{a: 1, b: 2}'), otherwise the service request will be published "
                        'with default values')
    p.add_argument('-r', '--rate', metavar='N', type=float,
                   help='Repeat the call at a specific rate in Hz')
    p.set_defaults(_background=lambda a: a.rate is not None and a.rate > 0)


def _service_class(service_type):
    import labkit.interfaces as ifc
    parts = service_type.split('/')
    if len(parts) == 2:
        parts = [parts[0], 'srv', parts[1]]
    try:
        cls = ifc.get_type('/'.join(parts))
    except (LookupError, ValueError):
        raise CliError('The passed service type is invalid')
    if not (hasattr(cls, 'Request') and hasattr(cls, 'Response')):
        raise CliError('The passed type is not a service')
    return cls, parts[0], parts[-1]


SERVER_GONE = "Exception while calling service: the server of '{}' went away before it answered"


def _spin_while_served(node, client, future, name):
    """Spin until the response arrives. On DDS a server may go away mid-call (stopped,
    crashed): a real `ros2 service call` then waits forever; labkit stops with one
    line once no server is left. In-process, the graph answers or says why itself."""
    from labkit import dds
    if not dds.is_connected():
        node.spin_until(future)
        return
    while not future.done():
        node.spin_until(future, timeout_sec=0.1)
        if not future.done() and not client.service_is_ready():
            client.remove_pending_request(future)
            raise CliError(SERVER_GONE.format(name))


def call(args, io):
    if args.rate is not None and args.rate <= 0:
        raise CliError('rate must be greater than zero')
    period = 1. / args.rate if args.rate else None
    cls, package, name = _service_class(args.service_type)
    values = load_yaml_values(args.values)
    in_job = getattr(args, 'in_job', False)
    with CliNode(f'{NODE_NAME_PREFIX}_requester_{package}_{name}',
                 default_context=in_job) as node:
        client = node.create_client(cls, args.service_name)
        request = cls.Request()
        try:
            set_message_fields(request, values)
        except Exception as e:
            return f'Failed to populate field: {e}'
        if not client.service_is_ready():
            io.print('waiting for service to become available...')
            if not client.wait_for_service(timeout_sec=None if in_job else patience()):
                raise GaveUp(f'waiting for service [{args.service_name}]')
        clock = node.get_clock()
        while True:
            io.print('requester: making request: %r\n' % request)
            last_call = clock.now().nanoseconds
            future = client.call_async(request)
            _spin_while_served(node, client, future, args.service_name)
            if future.result() is None:
                raise CliError('Exception while calling service: %r' % future.exception())
            io.print('response:\n%r\n' % future.result())
            if period is None or not node.ok():
                break
            remaining = last_call * 1e-9 + period - clock.now().nanoseconds * 1e-9
            if remaining > 0:
                from labkit.rclpy.task import Future
                node.spin_until(Future(), timeout_sec=remaining)
