"""ros2 action list | info | send_goal (ros2action)."""
from labkit.cli.ros2._base import (
    NODE_NAME_PREFIX, CliError, CliNode, GaveUp, patience, add_verbs, get_action, load_yaml_values,
    message_to_yaml, node_names, set_message_fields, split_node_name)

def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('info', 'Print information about an action', _info_args, info),
        ('list', 'Output a list of action names', _list_args, list_),
        ('send_goal', 'Send an action goal', _send_goal_args, send_goal),
    ])


def _list_args(p):
    p.add_argument('-t', '--show-types', action='store_true',
                   help='Additionally show the action type')
    p.add_argument('-c', '--count-actions', action='store_true',
                   help='Only display the number of actions discovered')


def list_(args, io):
    with CliNode() as node:
        actions = node.get_action_names_and_types()
    if args.count_actions:
        io.print(len(actions))
        return
    for name, types in actions:
        io.print(f'{name} [{", ".join(types)}]' if args.show_types else name)


def _info_args(p):
    p.add_argument('action_name', help="Name of the ROS action to get info (e.g. '/fibonacci')")
    p.add_argument('-t', '--show-types', action='store_true',
                   help='Additionally show the action type')
    p.add_argument('-c', '--count', action='store_true',
                   help='Only display the number of action clients and action servers')


def _expand(node, name):
    from labkit.cli.ros2.topic import expand_topic
    return expand_topic(node, name)


def info(args, io):
    with CliNode() as node:
        action = _expand(node, args.action_name)
        clients, servers = [], []
        for full in node_names(node, include_hidden=True):
            name, namespace = split_node_name(full)
            for n, t in node.get_action_client_names_and_types_by_node(name, namespace):
                if n == action:
                    clients.append((full, t))
            for n, t in node.get_action_server_names_and_types_by_node(name, namespace):
                if n == action:
                    servers.append((full, t))
    io.print(f'Action: {args.action_name}')
    for title, entries in (('Action clients', clients), ('Action servers', servers)):
        io.print(f'{title}: {len(entries)}')
        if not args.count:
            for node_name, types in entries:
                io.print(f'    {node_name} [{", ".join(types)}]' if args.show_types
                         else f'    {node_name}')


def _send_goal_args(p):
    p.add_argument('action_name', help="Name of the ROS action (e.g. '/fibonacci')")
    p.add_argument('action_type',
                   help="Type of the ROS action (e.g. 'example_interfaces/action/Fibonacci')")
    p.add_argument('goal', help="Goal request values in YAML format (e.g. '{order: 10}')")
    p.add_argument('-f', '--feedback', action='store_true',
                   help='Echo feedback messages for the goal')


STATUS_NAMES = {1: 'ACCEPTED', 2: 'EXECUTING', 3: 'CANCELING', 4: 'SUCCEEDED',
                5: 'CANCELED', 6: 'ABORTED'}


def send_goal(args, io):
    try:
        action_cls = get_action(args.action_type)
    except ValueError:
        raise CliError('The passed action type is invalid')
    values = load_yaml_values(args.goal)
    from labkit.rclpy.action import ActionClient
    node_name = f"{NODE_NAME_PREFIX}_send_goal_{args.action_type.replace('/', '_')}"
    with CliNode(node_name) as node:
        client = ActionClient(node.node, action_cls, args.action_name)
        goal_handle = None
        try:
            goal = action_cls.Goal()
            try:
                set_message_fields(goal, values)
            except Exception as ex:
                return 'Failed to populate message fields: {!r}'.format(ex)
            io.print('Waiting for an action server to become available...')
            if not client.wait_for_server(timeout_sec=patience()):
                raise GaveUp(f'waiting for action server [{args.action_name}]')
            io.print('Sending goal:\n     {}'.format(message_to_yaml(goal)))
            feedback = None
            if args.feedback:
                def feedback(msg):
                    io.print('Feedback:\n    {}'.format(message_to_yaml(msg.feedback)))
            # goal ids: rclpy.action draws them from a seeded stream in virtual time
            future = client.send_goal_async(goal, feedback)
            node.spin_until(future)
            goal_handle = future.result()
            if goal_handle is None:
                raise CliError('Exception while sending goal: {!r}'.format(future.exception()))
            if not goal_handle.accepted:
                io.print('Goal was rejected.')
                goal_handle = None
                return
            io.print('Goal accepted with ID: {}\n'.format(bytes(goal_handle.goal_id.uuid).hex()))
            result_future = goal_handle.get_result_async()
            node.spin_until(result_future)
            result = result_future.result()
            if result is None:
                raise CliError('Exception while getting result: {!r}'.format(
                    result_future.exception()))
            goal_handle = None
            io.print('Result:\n    {}'.format(message_to_yaml(result.result)))
            io.print('Goal finished with status: {}'.format(
                STATUS_NAMES.get(result.status, 'UNKNOWN')))
        finally:
            if goal_handle is not None and goal_handle.status in (1, 2) and node.ok():
                io.print('Canceling goal...')
                cancel = goal_handle.cancel_goal_async()
                node.spin_until(cancel)
                io.print('Goal canceled.')
            client.destroy()

