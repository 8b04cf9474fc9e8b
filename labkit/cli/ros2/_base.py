"""What every `ros2` verb shares: output streams, the argparse flavour, the CLI's own node.

Verbs are written like ros2cli's: `main(args, io)` prints through `io`, and
returns None/0 (success), an int (exit code) or a str (one error line, exit 1).
"""
import argparse
import copy

import yaml

# the command plumbing lives one floor down (labkit/commands.py), shared with the tools
from labkit.commands import (HIDDEN_PREFIX, NODE_NAME_PREFIX, CliError, CliNode,  # noqa: F401
                             Parser, ParserExit, Streams, add_verbs, get_action, get_message,
                             is_hidden_name, set_parse_streams, settle, world)


# --------------------------------------------------------------------------- names

def absolute_node_name(node_name):
    if not node_name:
        return None
    return node_name if node_name.startswith('/') else '/' + node_name


def split_node_name(full_name):
    """'/ns/name' -> ('name', '/ns'); 'name' -> ('name', '/')."""
    full = absolute_node_name(full_name)
    namespace, name = full.rsplit('/', 1)
    return name, namespace or '/'


def full_node_name(name, namespace):
    return namespace + ('' if namespace.endswith('/') else '/') + name


# --------------------------------------------------------------------------- waiting

# A real terminal waits until Ctrl-C; an unattended notebook in virtual time must
# not: bounded verbs give up after this much simulated time.
VIRTUAL_PATIENCE_S = 60.0


def patience():
    """Seconds a bounded verb may wait (None: forever, like the real CLI in live time)."""
    return VIRTUAL_PATIENCE_S if world().mode() == 'virtual' else None


class GaveUp(CliError):
    def __init__(self, what):
        super().__init__(f'labkit: gave up after {VIRTUAL_PATIENCE_S:g} s of simulated time '
                         f'{what} (a terminal would wait until Ctrl-C)')


# --------------------------------------------------------------------------- graph queries

def node_names(node, include_hidden=False, wait_for=None):
    """Full names of the nodes in the graph (ros2node.api.get_node_names).

    wait_for: the node a verb is about to use; on DDS a fresh process may not have
    discovered it yet (ros2cli asks its daemon, which has): wait for it, bounded."""
    def names():
        return [full_node_name(n, ns) for n, ns in node.get_node_names_and_namespaces()
                if include_hidden or (n and not n.startswith(HIDDEN_PREFIX))]
    if wait_for is not None:
        from labkit import dds
        dds.wait_until(lambda: wait_for in names())
    return names()


def topic_names_and_types(node, include_hidden=False):
    return [(n, t) for n, t in node.get_topic_names_and_types()
            if include_hidden or not is_hidden_name(n)]


def service_names_and_types(node, include_hidden=False):
    return [(n, t) for n, t in node.get_service_names_and_types()
            if include_hidden or not is_hidden_name(n)]


# --------------------------------------------------------------------------- interfaces

def convert():
    import labkit.interfaces.convert as c
    return c


def message_to_yaml(msg, **kwargs):
    return convert().message_to_yaml(msg, **kwargs)


def set_message_fields(msg, values):
    return convert().set_message_fields(msg, values)


def load_yaml_values(text):
    """The YAML argument of `topic pub`, `service call`, `action send_goal`."""
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as e:
        raise CliError(f'The passed value is not valid YAML: {e}'.splitlines()[0])


# --------------------------------------------------------------------------- QoS options

PRESET_KEYS = ['unknown', 'system_default', 'sensor_data', 'services_default',
               'parameters', 'parameter_events', 'action_status_default']
HISTORY_KEYS = ['system_default', 'keep_last', 'keep_all', 'unknown']
RELIABILITY_KEYS = ['system_default', 'reliable', 'best_effort', 'unknown']
DURABILITY_KEYS = ['system_default', 'transient_local', 'volatile', 'unknown']


def _short_keys(enum_name, fallback):
    try:
        from labkit.rclpy import qos
        return getattr(qos, enum_name).short_keys()
    except Exception:
        return fallback


def add_qos_arguments(parser, verb, default_profile_name, defaults):
    """The --qos-* options of `topic echo` (verb='subscribe') and `topic pub` (verb='publish')."""
    parser.add_argument(
        '--qos-profile', choices=_short_keys('QoSPresetProfiles', PRESET_KEYS),
        help=f'Quality of service preset profile to {verb} with'
             + (f' (default: {default_profile_name})' if default_profile_name else ''))
    parser.add_argument(
        '--qos-depth', metavar='N', type=int, default=defaults.get('depth'),
        help=f'Queue size setting to {verb} with '
             '(overrides depth value of --qos-profile option)')
    parser.add_argument(
        '--qos-history', choices=_short_keys('QoSHistoryPolicy', HISTORY_KEYS),
        help=f'History of samples setting to {verb} with '
             '(overrides history value of --qos-profile option, default: '
             f'{defaults.get("history", "keep_last")})')
    parser.add_argument(
        '--qos-reliability', choices=_short_keys('QoSReliabilityPolicy', RELIABILITY_KEYS),
        help=f'Quality of service reliability setting to {verb} with '
             '(overrides reliability value of --qos-profile option, default: '
             f'{defaults.get("reliability", "Automatically match existing publishers ")})')
    parser.add_argument(
        '--qos-durability', choices=_short_keys('QoSDurabilityPolicy', DURABILITY_KEYS),
        help=f'Quality of service durability setting to {verb} with '
             '(overrides durability value of --qos-profile option, default: '
             f'{defaults.get("durability", "Automatically match existing publishers ")})')


def preset_profile(name):
    """A private copy of a preset (ros2cli mutates the shared one; we must not)."""
    from labkit.rclpy import qos
    return copy.copy(qos.QoSPresetProfiles.get_from_short_key(name))


def configure_profile(profile, reliability=None, durability=None, depth=None, history=None):
    from labkit.rclpy import qos
    if history:
        profile.history = qos.QoSHistoryPolicy.get_from_short_key(history)
    if durability:
        profile.durability = qos.QoSDurabilityPolicy.get_from_short_key(durability)
    if reliability:
        profile.reliability = qos.QoSReliabilityPolicy.get_from_short_key(reliability)
    if depth is not None and depth >= 0:
        profile.depth = depth
    elif profile.durability == qos.QoSDurabilityPolicy.TRANSIENT_LOCAL and profile.depth == 0:
        profile.depth = 1
    return profile


def unsigned_int(string):
    try:
        value = int(string)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError('value must be non-negative integer')
    return value


def positive_int(string):
    try:
        value = int(string)
    except ValueError:
        value = -1
    if value <= 0:
        raise argparse.ArgumentTypeError('value must be a positive integer')
    return value
