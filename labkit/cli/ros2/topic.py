"""ros2 topic list | info | type | find | echo | hz | bw | pub (ros2topic)."""
from labkit.cli.ros2._base import (
    CliError, CliNode, GaveUp, add_qos_arguments, add_verbs, configure_profile, convert,
    get_message, load_yaml_values, patience, preset_profile, topic_names_and_types,
    unsigned_int)
from labkit.commands import expand_topic  # noqa: F401  (action.py imports it from here)
from labkit.cli.ros2.daemon import strategy

DEFAULT_TRUNCATE_LENGTH = 128
ECHO_DEFAULT_PROFILE = 'sensor_data'


def add_arguments(parser, cli_name):
    from labkit.cli.ros2 import topic_monitor as m
    parser.add_argument('--include-hidden-topics', action='store_true',
                        help='Consider hidden topics as well')
    add_verbs(parser, cli_name, [
        ('bw', 'Display bandwidth used by topic', m.bw_arguments, m.bw),
        ('delay', 'Display delay of topic from timestamp in header', m.delay_arguments, m.delay),
        ('echo', 'Output messages from a topic', *strategy(_echo_args, echo)),
        ('find', 'Output a list of available topics of a given type',
         *strategy(_find_args, find)),
        ('hz', 'Print the average publishing rate to screen', m.hz_arguments, m.hz),
        ('info', 'Print information about a topic', *strategy(_info_args, info)),
        ('list', 'Output a list of available topics', *strategy(_list_args, list_)),
        ('pub', 'Publish a message to a topic', _pub_args, pub),
        ('type', "Print a topic's type", *strategy(_type_args, type_)),
    ])


def _hidden_flag(p):
    p.add_argument('--include-hidden-topics', action='store_true',
                   help='Consider hidden topics as well')


def _in_job(args):
    return getattr(args, 'in_job', False)


# --------------------------------------------------------------------------- list/info/type/find

def _list_args(p):
    p.add_argument('-t', '--show-types', action='store_true',
                   help='Additionally show the topic type')
    p.add_argument('-c', '--count-topics', action='store_true',
                   help='Only display the number of topics discovered')
    _hidden_flag(p)
    p.add_argument('-v', '--verbose', action='store_true',
                   help='List full details about each topic')


def _endpoint_summary(info, is_publisher):
    text = ('Published' if is_publisher else 'Subscribed') + ' topics:\n'
    for name, types, pubs, subs in info:
        count = pubs if is_publisher else subs
        if count:
            kind = 'publisher' if is_publisher else 'subscriber'
            text += f' * {name} [{", ".join(types)}] {count} {kind}{"s" if count > 1 else ""}\n'
    return text


def list_(args, io):
    with CliNode() as node:
        topics = topic_names_and_types(node, args.include_hidden_topics)
        info = [(n, t, node.count_publishers(n) if args.verbose else 0,
                 node.count_subscribers(n) if args.verbose else 0) for n, t in topics]
    if args.count_topics:
        io.print(len(topics))
    elif topics:
        if args.verbose:
            io.print(_endpoint_summary(info, True))
            io.print(_endpoint_summary(info, False))
        else:
            for name, types, _, _ in info:
                io.print(f'{name} [{", ".join(types)}]' if args.show_types else name)


def _info_args(p):
    p.add_argument('topic_name', help="Name of the ROS topic to get info (e.g. '/chatter')")
    p.add_argument('--verbose', '-v', action='store_true',
                   help='Prints detailed information like the node name, node namespace, '
                        'topic type, GUID and QoS Profile of the publishers and subscribers '
                        'to this topic')


def info(args, io):
    with CliNode() as node:
        for name, types in topic_names_and_types(node, True):
            if name == args.topic_name:
                break
        else:
            return f"Unknown topic '{args.topic_name}'"
        end = '\n\n' if args.verbose else '\n'
        type_str = types[0] if len(types) == 1 else types
        io.print(f'Type: {type_str}', end=end)
        io.print(f'Publisher count: {node.count_publishers(name)}', end=end)
        if args.verbose:
            for endpoint in node.get_publishers_info_by_topic(name):
                io.print(endpoint, end=end)
        io.print(f'Subscription count: {node.count_subscribers(name)}', end=end)
        if args.verbose:
            for endpoint in node.get_subscriptions_info_by_topic(name):
                io.print(endpoint, end=end)


def _type_args(p):
    p.add_argument('topic_name', help="Name of the ROS topic to get type (e.g. '/chatter')")


def type_(args, io):
    with CliNode() as node:
        topics = topic_names_and_types(node, args.include_hidden_topics)
    for name, types in topics:
        if name == args.topic_name:
            for t in types:
                io.print(t)
            return 0
    return 1


def _find_args(p):
    p.add_argument('topic_type',
                   help="Name of the ROS topic type to filter for (e.g. 'std_msg/msg/String')")
    p.add_argument('-c', '--count-topics', action='store_true',
                   help='Only display the number of topics discovered')
    _hidden_flag(p)


def find(args, io):
    with CliNode() as node:
        topics = topic_names_and_types(node, args.include_hidden_topics)
    found = [n for n, types in topics if args.topic_type in types]
    if args.count_topics:
        io.print(len(found))
    else:
        for name in found:
            io.print(name)


# --------------------------------------------------------------------------- message classes

def lookup_message_class(node, topic):
    """The class of a published topic, or None (ros2topic.api._get_msg_class)."""
    expanded = expand_topic(node, topic)
    for name, types in topic_names_and_types(node, True):
        if name == expanded:
            if len(types) > 1:
                raise CliError(f"Cannot echo topic '{topic}', as it contains more than one "
                               f"type: [{', '.join(types)}]")
            try:
                return get_message(types[0])
            except ValueError:
                raise CliError(f"The message type '{types[0]}' is invalid")
    return None


def wait_message_class(node, topic, io):
    """Like get_msg_class(blocking=True): warn once, then poll every 0.1 s."""
    cls = lookup_message_class(node, topic)
    if cls is None:
        io.print(f'WARNING: topic [{topic}] does not appear to be published yet')
        while cls is None and node.ok():
            node.spin_once(timeout_sec=0.1)
            cls = lookup_message_class(node, topic)
    return cls


def spin_forever(node):
    """Spin until the job is stopped (its context shut down)."""
    try:
        while node.ok():
            node.spin_once(timeout_sec=1.0)
    except Exception:
        if node.ok():
            raise


# --------------------------------------------------------------------------- echo

def _echo_args(p):
    p.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    p.add_argument('message_type', nargs='?',
                   help="Type of the ROS message (e.g. 'std_msgs/msg/String')")
    add_qos_arguments(p, 'subscribe', ECHO_DEFAULT_PROFILE, {'history': 'keep_last'})
    p.add_argument('--csv', action='store_true',
                   help='Output all recursive fields separated by commas (e.g. for plotting)')
    p.add_argument('--field', type=str, default=None,
                   help="Echo a selected field of a message. Use '.' to select sub-fields. "
                        'For example, to echo the position field of a nav_msgs/msg/Odometry '
                        "message: 'ros2 topic echo /odom --field pose.pose.position'")
    p.add_argument('--full-length', '-f', action='store_true',
                   help='Output all elements for arrays, bytes, and string with a length > '
                        "'--truncate-length', by default they are truncated after "
                        "'--truncate-length' elements with '...''")
    p.add_argument('--truncate-length', '-l', type=unsigned_int,
                   default=DEFAULT_TRUNCATE_LENGTH,
                   help='The length to truncate arrays, bytes, and string to '
                        f'(default: {DEFAULT_TRUNCATE_LENGTH})')
    p.add_argument('--no-arr', action='store_true', help="Don't print array fields of messages")
    p.add_argument('--no-str', action='store_true', help="Don't print string fields of messages")
    p.add_argument('--flow-style', action='store_true',
                   help='Print collections in the block style (not available with csv format)')
    p.add_argument('--lost-messages', action='store_true', help='DEPRECATED: Does nothing')
    p.add_argument('--no-lost-messages', action='store_true',
                   help="Don't report when a message is lost")
    p.add_argument('--raw', action='store_true', help='Echo the raw binary representation')
    p.add_argument('--filter', dest='filter_expr',
                   help='Python expression to filter messages that are printed. Expression '
                        'can use Python builtins as well as m (the message).')
    p.add_argument('--once', action='store_true',
                   help='Print the first message received and then exit.')
    p.set_defaults(_background=lambda a: not a.once)


def _echo_qos(node, args, topic, io):
    from labkit.rclpy.qos import QoSDurabilityPolicy, QoSReliabilityPolicy
    if any(v is not None for v in (args.qos_profile, args.qos_reliability, args.qos_durability,
                                   args.qos_depth, args.qos_history)):
        profile = preset_profile(args.qos_profile or ECHO_DEFAULT_PROFILE)
        return configure_profile(profile, args.qos_reliability, args.qos_durability,
                                 args.qos_depth, args.qos_history)
    profile = preset_profile(ECHO_DEFAULT_PROFILE)
    infos = node.get_publishers_info_by_topic(topic)
    if not infos:
        return profile
    reliable = sum(i.qos_profile.reliability == QoSReliabilityPolicy.RELIABLE for i in infos)
    transient = sum(i.qos_profile.durability == QoSDurabilityPolicy.TRANSIENT_LOCAL
                    for i in infos)
    if reliable == len(infos):
        profile.reliability = QoSReliabilityPolicy.RELIABLE
    else:
        if reliable:
            io.print('Some, but not all, publishers are offering QoSReliabilityPolicy.RELIABLE. '
                     'Falling back to QoSReliabilityPolicy.BEST_EFFORT as it will connect to '
                     'all publishers')
        profile.reliability = QoSReliabilityPolicy.BEST_EFFORT
    if transient == len(infos):
        profile.durability = QoSDurabilityPolicy.TRANSIENT_LOCAL
    else:
        if transient:
            io.print('Some, but not all, publishers are offering '
                     'QoSDurabilityPolicy.TRANSIENT_LOCAL. Falling back to '
                     'QoSDurabilityPolicy.VOLATILE as it will connect to all publishers')
        profile.durability = QoSDurabilityPolicy.VOLATILE
    return profile


def echo(args, io):
    if args.lost_messages:
        io.eprint("WARNING: '--lost-messages' is deprecated; lost messages are reported "
                  'by default')
    field = None
    if args.field is not None:
        field = [f for f in args.field.split('.') if f]
        if not field:
            raise CliError(f"Invalid field value '{args.field}'")
    truncate = None if args.full_length else args.truncate_length
    filter_fn = None
    if args.filter_expr:
        code = compile(args.filter_expr, '<filter>', 'eval')
        filter_fn = lambda m: eval(code, {}, {'m': m})  # noqa: E731 (ros2cli's --filter)
    conv = convert()

    with CliNode(default_context=_in_job(args)) as node:
        topic = expand_topic(node, args.topic_name)
        qos = _echo_qos(node, args, topic, io)
        if args.message_type is None:
            cls = lookup_message_class(node, args.topic_name)
            if cls is None:
                io.print(f'WARNING: topic [{args.topic_name}] does not appear to be published yet')
                raise CliError('Could not determine the type for the passed topic')
        else:
            try:
                cls = get_message(args.message_type)
            except ValueError:
                raise CliError('The passed message type is invalid')
        done = []

        def callback(msg):
            sub = msg
            if field is not None:
                for name in field:
                    try:
                        sub = getattr(sub, name)
                    except AttributeError as ex:
                        raise CliError(f"Invalid field '{'.'.join(field)}': {ex}")
            if filter_fn is not None and not filter_fn(sub):
                return
            if args.once and done:
                return
            done.append(True)
            if args.raw:
                from labkit.interfaces import serialize
                io.print(serialize(msg), end='\n---\n')
            elif args.csv:
                io.print(conv.message_to_csv(sub, truncate_length=truncate, no_arr=args.no_arr,
                                             no_str=args.no_str)
                         if hasattr(sub, '__slots__') else sub)
            elif hasattr(sub, '__slots__'):
                io.print(conv.message_to_yaml(sub, truncate_length=truncate, no_arr=args.no_arr,
                                              no_str=args.no_str, flow_style=args.flow_style),
                         end='---\n')
            else:
                io.print(sub, end='\n---\n')

        node.create_subscription(cls, args.topic_name, callback, qos)
        if args.once:
            limit = patience()
            start = node.get_clock().now().nanoseconds
            while not done:
                node.spin_once(timeout_sec=limit)
                if not done and limit is not None and \
                        node.get_clock().now().nanoseconds - start >= limit * 1e9:
                    raise GaveUp(f'waiting for a message on [{args.topic_name}]')
        else:
            spin_forever(node)


# --------------------------------------------------------------------------- pub

def _nonnegative_int(text):
    value = int(text)
    if value < 0:
        raise ValueError('Value must be positive or zero')
    return value


def _positive_float(text):
    value = float(text)
    if value <= 0.0:
        raise ValueError('Value must be positive')
    return value


_nonnegative_int.__name__ = 'nonnegative_int'
_positive_float.__name__ = 'positive_float'


def _pub_args(p):
    p.add_argument('topic_name', help="Name of the ROS topic to publish to (e.g. '/chatter')")
    p.add_argument('message_type', help="Type of the ROS message (e.g. 'std_msgs/String')")
    p.add_argument('values', nargs='?', default='{}',
                   help="Values to fill the message with in YAML format (e.g. 'data: Hello "
                        "World'), otherwise the message will be published with default values")
    p.add_argument('-r', '--rate', metavar='N', type=_positive_float, default=1.0,
                   help='Publishing rate in Hz (default: 1)')
    p.add_argument('-p', '--print', metavar='N', type=int, default=1,
                   help='Only print every N-th published message (default: 1)')
    group = p.add_mutually_exclusive_group()
    group.add_argument('-1', '--once', action='store_true', help='Publish one message and exit')
    group.add_argument('-t', '--times', type=_nonnegative_int, default=0,
                       help='Publish this number of times and then exit')
    p.add_argument('-w', '--wait-matching-subscriptions', type=_nonnegative_int, default=None,
                   help='Wait until finding the specified number of matching subscriptions. '
                        'Defaults to 1 when using "-1"/"--once"/"--times", otherwise defaults '
                        'to 0.')
    p.add_argument('--keep-alive', metavar='N', type=_positive_float, default=0.1,
                   help='Keep publishing node alive for N seconds after the last msg '
                        '(default: 0.1)')
    p.add_argument('-n', '--node-name', help='Name of the created publishing node')
    add_qos_arguments(p, 'publish', None, {'depth': -1, 'history': 'keep_last',
                                           'reliability': 'reliable',
                                           'durability': 'transient_local'})
    p.set_defaults(_background=lambda a: not (a.once or a.times))


def pub(args, io):
    from labkit.rclpy.qos import QoSDurabilityPolicy, QoSProfile, QoSReliabilityPolicy
    if args.qos_profile:
        qos = preset_profile(args.qos_profile)
    else:
        qos = QoSProfile(reliability=QoSReliabilityPolicy.RELIABLE,
                         durability=QoSDurabilityPolicy.TRANSIENT_LOCAL, depth=1)
    configure_profile(qos, args.qos_reliability, args.qos_durability, args.qos_depth,
                      args.qos_history)
    times = 1 if args.once else args.times
    wait_subs = args.wait_matching_subscriptions
    if wait_subs is None:
        wait_subs = int(times != 0)
    try:
        cls = get_message(args.message_type)
    except ValueError:
        raise CliError('The passed message type is invalid')
    values = load_yaml_values(args.values)
    if not isinstance(values, dict):
        return 'The passed value needs to be a dictionary in YAML format'

    with CliNode(args.node_name, default_context=_in_job(args)) as node:
        publisher = node.create_publisher(cls, args.topic_name, qos)
        ticks, waited, limit = 0, 0.0, patience()
        while publisher.get_subscription_count() < wait_subs and node.ok():
            if not ticks:
                io.print(f'Waiting for at least {wait_subs} matching subscription(s)...')
            ticks = (ticks + 1) % 10
            if limit is not None and waited >= limit and not _in_job(args):
                raise GaveUp(f'waiting for {wait_subs} matching subscription(s)')
            node.spin_once(timeout_sec=0.1)
            waited += 0.1
        msg = cls()
        try:
            stamp_setters = _set_fields_expanded(msg, values)
        except Exception as e:
            return f'Failed to populate field: {e}'
        io.print('publisher: beginning loop')
        count = 0

        def publish_once():
            nonlocal count
            now = node.get_clock().now().to_msg()
            for setter in stamp_setters:
                setter(now)
            count += 1
            if args.print and count % args.print == 0:
                io.print('publishing #%d: %r\n' % (count, msg))
            publisher.publish(msg)

        publish_once()
        if times != 1:
            timer = node.create_timer(1. / args.rate, publish_once)
            try:
                while (times == 0 or count < times) and node.ok():
                    node.spin_once(timeout_sec=1.0)
            except Exception:
                if node.ok():
                    raise
                return
            node.destroy_timer(timer)
        _linger(node, args.keep_alive)


def _linger(node, seconds):
    """Keep the node alive a moment so late messages are delivered (`--keep-alive`)."""
    from labkit.rclpy.task import Future
    if node.ok():
        node.spin_until(Future(), timeout_sec=seconds)


def _set_fields_expanded(msg, values):
    conv = convert()
    try:
        return conv.set_message_fields(msg, values, expand_header_auto=True,
                                       expand_time_now=True) or []
    except TypeError as e:
        if 'expand_' not in str(e):
            raise
    conv.set_message_fields(msg, values)
    return []
