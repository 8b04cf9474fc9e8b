"""ros2 param list | get | set | describe | dump | load | delete (ros2param).

Everything goes through the node's six parameter services, as ros2param does.
"""
import re

import yaml

from labkit.cli.ros2._base import (
    CliError, CliNode, GaveUp, absolute_node_name, add_verbs, node_names, patience,
    service_names_and_types, split_node_name)
from labkit.cli.ros2.daemon import strategy

SEPARATOR = '.'
TYPE_NAMES = {1: 'boolean', 2: 'integer', 3: 'double', 4: 'string', 5: 'byte array',
              6: 'boolean array', 7: 'integer array', 8: 'double array', 9: 'string array',
              0: 'not set'}
SERVICE_TIMEOUT = 5.0


def _types():
    from labkit.interfaces import get_type
    return get_type


def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('delete', 'Delete parameter', *strategy(_delete_args, delete)),
        ('describe', 'Show descriptive information about declared parameters',
         *strategy(_describe_args, describe)),
        ('dump', 'Show all of the parameters of a node in a YAML file format',
         *strategy(_dump_args, dump)),
        ('get', 'Get parameter', *strategy(_get_args, get)),
        ('list', 'Output a list of available parameters', *strategy(_list_args, list_)),
        ('load', 'Load parameter file for a node', *strategy(_load_args, load)),
        ('set', 'Set parameter', *strategy(_set_args, set_)),
    ])


def _node_arg(p, optional=False):
    p.add_argument('node_name', nargs='?' if optional else None, help='Name of the ROS node')
    p.add_argument('--include-hidden-nodes', action='store_true',
                   help='Consider hidden nodes as well')


# --------------------------------------------------------------------------- values

def value_of(pv):
    """Python value of an rcl_interfaces/ParameterValue (ros2param.api.get_value)."""
    t = pv.type
    return {1: lambda: pv.bool_value, 2: lambda: pv.integer_value, 3: lambda: pv.double_value,
            4: lambda: pv.string_value, 5: lambda: list(pv.byte_array_value),
            6: lambda: list(pv.bool_array_value), 7: lambda: list(pv.integer_array_value),
            8: lambda: list(pv.double_array_value),
            9: lambda: list(pv.string_array_value)}.get(t, lambda: None)()


def parameter_value(string_value):
    """A ParameterValue from command-line text, typed by YAML (ros2param's rules)."""
    value = _types()('rcl_interfaces/msg/ParameterValue')()
    try:
        loaded = yaml.safe_load(string_value)
    except yaml.YAMLError:
        loaded = string_value
    if isinstance(loaded, bool):
        value.type, value.bool_value = 1, loaded
    elif isinstance(loaded, int):
        value.type, value.integer_value = 2, loaded
    elif isinstance(loaded, float):
        value.type, value.double_value = 3, loaded
    elif isinstance(loaded, list):
        if all(isinstance(v, bool) for v in loaded):
            value.type, value.bool_array_value = 6, loaded
        elif all(isinstance(v, int) for v in loaded):
            value.type, value.integer_array_value = 7, loaded
        elif all(isinstance(v, float) for v in loaded):
            value.type, value.double_array_value = 8, loaded
        elif all(isinstance(v, str) for v in loaded):
            value.type, value.string_array_value = 9, loaded
        else:
            value.type, value.string_value = 4, string_value
    else:
        value.type = 4
        value.string_value = loaded if isinstance(loaded, str) else string_value
    return value


def _parameter(name, value):
    p = _types()('rcl_interfaces/msg/Parameter')()
    p.name = name
    p.value = value
    return p


# --------------------------------------------------------------------------- service calls

def _call(node, node_name, service, type_name, request_fields, timeout_sec=None):
    srv = _types()(type_name)
    client = node.create_client(srv, f'{node_name}/{service}')
    try:
        if not client.wait_for_service(timeout_sec=SERVICE_TIMEOUT):
            raise CliError('Wait for service timed out')
        request = srv.Request()
        for key, value in request_fields.items():
            setattr(request, key, value)
        response = node.call(client, request, timeout_sec=timeout_sec or patience())
        if response is None:
            if timeout_sec is not None:
                return None
            raise GaveUp(f'waiting for {node_name} to answer')
        return response
    finally:
        node.destroy_client(client)


def get_parameters(node, node_name, names):
    return _call(node, node_name, 'get_parameters', 'rcl_interfaces/srv/GetParameters',
                 {'names': names})


def set_parameters(node, node_name, parameters):
    return _call(node, node_name, 'set_parameters', 'rcl_interfaces/srv/SetParameters',
                 {'parameters': parameters})


def describe_parameters(node, node_name, names):
    return _call(node, node_name, 'describe_parameters',
                 'rcl_interfaces/srv/DescribeParameters', {'names': names})


def list_parameters(node, node_name, prefixes=(), timeout_sec=None):
    response = _call(node, node_name, 'list_parameters', 'rcl_interfaces/srv/ListParameters',
                     {'prefixes': list(prefixes)}, timeout_sec)
    if response is None:
        raise CliError('None')  # what ros2param prints for a node that does not answer
    return response.result.names


def _check_node(node, args):
    name = absolute_node_name(args.node_name)
    if name not in node_names(node, args.include_hidden_nodes, wait_for=name):
        raise CliError('Node not found')
    return name


# --------------------------------------------------------------------------- verbs

def _list_args(p):
    _node_arg(p, optional=True)
    p.add_argument('--filter', nargs=1,
                   help='Only parameters matching the regex expression will be showed. '
                        'Supports `re` regex syntax.')
    p.add_argument('--param-prefixes', nargs='+', default=[],
                   help='Only list parameters with the provided prefixes')
    p.add_argument('--param-type', action='store_true',
                   help='Print parameter types with parameter names')


def list_(args, io):
    regex = re.compile(args.filter[0]) if args.filter else None
    with CliNode() as node:
        wanted = absolute_node_name(args.node_name)
        names = node_names(node, args.include_hidden_nodes, wait_for=wanted)
        if args.node_name:
            if wanted not in names:
                return 'Node not found'
            names = [wanted]
        services = {n for n, _ in service_names_and_types(node, args.include_hidden_nodes)}
        # ros2param sorts its NodeName tuples: by base name first, then namespace
        for full in sorted(names, key=lambda f: (*split_node_name(f), f)):
            if f'{full}/list_parameters' not in services:
                continue
            try:
                # ros2param gives each node one second to answer
                params = sorted(list_parameters(node, full, args.param_prefixes, 1.0))
            except CliError as e:
                io.eprint(f"Exception while calling service of node '{full}': {e}")
                continue
            if regex is not None:
                params = [p for p in params if regex.match(p)]
            if not args.node_name and params:
                io.print(f'{full}:')
            types = {}
            if args.param_type and params:
                for d in describe_parameters(node, full, params).descriptors:
                    types[d.name] = TYPE_NAMES.get(d.type, 'not set')
            for name in params:
                io.print(f'  {name} (type: {types[name]})' if args.param_type else f'  {name}')


def _get_args(p):
    _node_arg(p)
    p.add_argument('parameter_name', help='Name of the parameter')
    p.add_argument('--hide-type', action='store_true', help='Hide the type information')


GET_LABELS = {1: 'Boolean value is:', 2: 'Integer value is:', 3: 'Double value is:',
              4: 'String value is:', 5: 'Byte values are:', 6: 'Boolean values are:',
              7: 'Integer values are:', 8: 'Double values are:', 9: 'String values are:'}


def _array_text(pv):
    """How ros2param prints array values (array('q', [1, 2]) for numeric sequences)."""
    t = pv.type
    return {5: pv.byte_array_value, 6: pv.bool_array_value, 7: pv.integer_array_value,
            8: pv.double_array_value, 9: pv.string_array_value}[t]


def get(args, io):
    with CliNode() as node:
        name = _check_node(node, args)
        response = get_parameters(node, name, [args.parameter_name])
    if not response.values:
        return 'Parameter not set'
    pv = response.values[0]
    if pv.type == 0:
        io.print('Parameter not set.')
        return
    if pv.type not in GET_LABELS:
        return f"Unknown parameter type '{pv.type}'"
    value = value_of(pv) if pv.type <= 4 else _array_text(pv)
    io.print(value if args.hide_type else f'{GET_LABELS[pv.type]} {value}')


def _set_args(p):
    _node_arg(p)
    p.add_argument('parameter_name', help='Name of the parameter')
    p.add_argument('value', help='Value of the parameter')


def set_(args, io):
    with CliNode() as node:
        name = _check_node(node, args)
        response = set_parameters(
            node, name, [_parameter(args.parameter_name, parameter_value(args.value))])
    result = response.results[0]
    if result.successful:
        io.print('Set parameter successful' + (': ' + result.reason if result.reason else ''))
    else:
        io.eprint('Setting parameter failed' + (': ' + result.reason if result.reason else ''))


def _delete_args(p):
    _node_arg(p)
    p.add_argument('parameter_name', help='Name of the parameter')


def delete(args, io):
    with CliNode() as node:
        name = _check_node(node, args)
        value = _types()('rcl_interfaces/msg/ParameterValue')()
        value.type = 0
        response = set_parameters(node, name, [_parameter(args.parameter_name, value)])
    result = response.results[0]
    if result.successful:
        io.print('Deleted parameter successfully'
                 + (': ' + result.reason if result.reason else ''))
    else:
        io.eprint('Deleting parameter failed' + (': ' + result.reason if result.reason else ''))


def _describe_args(p):
    _node_arg(p)
    p.add_argument('parameter_names', nargs='+', help='Names of the parameters')


def describe(args, io):
    with CliNode() as node:
        name = _check_node(node, args)
        response = describe_parameters(node, name, args.parameter_names)
    for d in response.descriptors:
        io.print('Parameter name:', d.name)
        io.print('  Type:', TYPE_NAMES.get(d.type, 'not set'))
        if d.description:
            io.print('  Description:', d.description)
        io.print('  Constraints:')
        if d.read_only:
            io.print('    Read only: true')
        ranges = list(d.floating_point_range) + list(d.integer_range)
        if ranges:
            io.print('    Min value:', ranges[0].from_value)
            io.print('    Max value:', ranges[0].to_value)
            if ranges[0].step:
                io.print('    Step:', ranges[0].step)
        if d.additional_constraints:
            io.print('    Additional constraints:', d.additional_constraints)


def _dump_args(p):
    _node_arg(p)
    p.add_argument('--output-dir', default='.',
                   help='DEPRECATED: The absolute path where to save the generated file')
    p.add_argument('--print', action='store_true', help='DEPRECATED: Does nothing.')


def _insert(tree, key, value):
    head, dot, rest = key.partition(SEPARATOR)
    if dot:
        _insert(tree.setdefault(head, {}), rest, value)
    else:
        tree[key] = value


def dump(args, io):
    import os
    with CliNode() as node:
        name = _check_node(node, args)
        if not os.path.isdir(args.output_dir):
            raise CliError(f"'{args.output_dir}' is not a valid directory.")
        params = {}
        for pname in sorted(list_parameters(node, name)):
            response = get_parameters(node, name, [pname])
            _insert(params, pname, value_of(response.values[0]) if response.values
                    else '# Parameter not set')
    document = {name: {'ros__parameters': params}}
    if args.print:
        io.eprint("WARNING: '--print' is deprecated; this utility prints to stdout by default")
    if args.output_dir == '.':
        io.print(yaml.dump(document, default_flow_style=False))
        return
    io.eprint("WARNING: '--output-dir' is deprecated; use redirection to save to a file")
    path = os.path.join(args.output_dir, name.lstrip('/').replace('/', '__') + '.yaml')
    io.print('Saving to: ', path)
    with open(path, 'w', encoding='utf-8') as f:
        yaml.dump(document, f, default_flow_style=False)


def _load_args(p):
    _node_arg(p)
    p.add_argument('parameter_file', help='Parameter file')
    p.add_argument('--no-use-wildcard', action='store_true',
                   help="Do not load parameters in the '/**' namespace into the node")


def _flatten(namespace, values):
    out = []
    for key, value in values.items():
        full = namespace + key
        if isinstance(value, dict):
            out += _flatten(full + SEPARATOR, value)
        else:
            out.append(_parameter(full, parameter_value(str(value))))
    return out


def load(args, io):
    with CliNode() as node:
        name = _check_node(node, args)
        try:
            with open(args.parameter_file, encoding='utf-8') as f:
                document = yaml.safe_load(f)
        except OSError as e:
            raise CliError(str(e))
        keys = []
        if not args.no_use_wildcard and '/**' in document:
            keys.append('/**')
        if name in document:
            keys.append(name)
        if not keys:
            raise CliError(f'Param file does not contain parameters for {name},  only for '
                           f'nodes: {document.keys()}')
        values = {}
        for key in keys:
            entry = document[key]
            if not isinstance(entry, dict) or 'ros__parameters' not in entry:
                raise CliError(f'Invalid structure of parameter file for node {key}expected '
                               'same format as provided by ros2 param dump')
            values.update(entry['ros__parameters'])
        parameters = _flatten('', values)
        response = set_parameters(node, name, parameters)
    for parameter, result in zip(parameters, response.results):
        text = f'Set parameter {parameter.name} ' + ('successful' if result.successful
                                                      else 'failed')
        if result.reason:
            text += ': ' + result.reason
        (io.print if result.successful else io.eprint)(text)
