"""ros2 node list | info (ros2node)."""
from labkit.cli.ros2._base import (
    CliNode, add_verbs, is_hidden_name, node_names, split_node_name)
from labkit.cli.ros2.daemon import strategy

DUPLICATE_WARNING = ('WARNING: Be aware that are nodes in the graph that share an exact name, '
                     'this can have unintended side effects.')
INFO_NONUNIQUE = ('There are {num_nodes} nodes in the graph with the exact name "{node_name}". '
                  'You are seeing information about only one of them.')


def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('info', 'Output information about a node', *strategy(_info_args, info)),
        ('list', 'Output a list of available nodes', *strategy(_list_args, list_)),
    ])


def _list_args(p):
    p.add_argument('-a', '--all', action='store_true',
                   help='Display all nodes even hidden ones')
    p.add_argument('-c', '--count-nodes', action='store_true',
                   help='Only display the number of nodes discovered')


def list_(args, io):
    with CliNode() as node:
        names = node_names(node, include_hidden=args.all)
    if args.count_nodes:
        io.print(len(names))
    elif names:
        names = sorted(names)
        if len(set(names)) < len(names):
            io.eprint(DUPLICATE_WARNING)
        io.print(*names, sep='\n')


def _info_args(p):
    p.add_argument('node_name', help='Node name to request information')
    p.add_argument('--include-hidden', action='store_true',
                   help='Display hidden topics, services, and actions as well')


def _section(io, title, names_and_types, include_hidden):
    io.print(f'  {title}:')
    entries = [f'    {n}: ' + ', '.join(t) for n, t in names_and_types
               if include_hidden or not is_hidden_name(n)]
    io.print(*entries, sep='\n')  # an empty section prints an empty line, as ros2cli does


def info(args, io):
    with CliNode() as node:
        names = node_names(node, include_hidden=args.include_hidden, wait_for=args.node_name)
        count = names.count(args.node_name)
        if count > 1:
            io.eprint(INFO_NONUNIQUE.format(num_nodes=count, node_name=args.node_name))
        if count == 0:
            return f"Unable to find node '{args.node_name}'"
        name, namespace = split_node_name(args.node_name)
        hidden = args.include_hidden
        io.print(args.node_name)
        _section(io, 'Subscribers',
                 node.get_subscriber_names_and_types_by_node(name, namespace), hidden)
        _section(io, 'Publishers',
                 node.get_publisher_names_and_types_by_node(name, namespace), hidden)
        _section(io, 'Service Servers',
                 node.get_service_names_and_types_by_node(name, namespace), hidden)
        _section(io, 'Service Clients',
                 node.get_client_names_and_types_by_node(name, namespace), hidden)
        _section(io, 'Action Servers',
                 node.get_action_server_names_and_types_by_node(name, namespace), hidden)
        _section(io, 'Action Clients',
                 node.get_action_client_names_and_types_by_node(name, namespace), hidden)
