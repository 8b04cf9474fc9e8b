"""What every `ros2` verb shares: output streams, the argparse flavour, the CLI's own node.

Verbs are written like ros2cli's: `main(args, io)` prints through `io`, and
returns None/0 (success), an int (exit code) or a str (one error line, exit 1).
"""
import argparse
import copy
import itertools

import yaml

# the command plumbing lives one floor down (labkit/commands.py), shared with the tools
from labkit.commands import (CliError, Parser, ParserExit, Streams,  # noqa: F401
                             add_verbs, set_parse_streams)

HIDDEN_PREFIX = '_'
NODE_NAME_PREFIX = '_ros2cli'


# --------------------------------------------------------------------------- names

def is_hidden_name(name):
    return any(part.startswith(HIDDEN_PREFIX) for part in name.split('/'))


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


# --------------------------------------------------------------------------- the CLI node

_counter = itertools.count(1)


def world():
    from labkit.graph import world as w
    return w


def settle():
    """Let every runnable thread finish its work (virtual time): graph queries see the news."""
    try:
        w = world()
    except ImportError:
        return
    fn = getattr(w, 'settle', None)
    if fn is not None:
        fn()


class CliNode:
    """The hidden node a verb queries and talks through (ros2cli's DirectNode).

    It lives in a Context of its own, so the user's `rclpy.init()` state is
    never touched, and it is gone when the verb ends.
    """

    def __init__(self, name=None, *, suffix=None, default_context=False):
        import labkit.rclpy as rclpy
        from labkit.rclpy.context import Context
        from labkit.rclpy.executors import SingleThreadedExecutor
        self.rclpy = rclpy
        if default_context:
            # a background job: the job's process context, so stopping the job ends the verb
            self.context = rclpy.get_default_context()
            if not self.context.ok():
                rclpy.init(args=[], context=self.context)
        else:
            self.context = Context()
            rclpy.init(args=[], context=self.context)
        if name is None:
            name = f'{NODE_NAME_PREFIX}_{suffix or next(_counter)}'
        # like ros2cli's DirectNode: rosout on, no parameter services
        self.node = rclpy.create_node(name, context=self.context, start_parameter_services=False)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        if not default_context:
            # a job needs no settle: it starts while every other thread waits
            settle()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        try:
            self.executor.shutdown()
        except Exception:
            pass
        try:
            self.node.destroy_node()
        except Exception:
            if self.context.ok():
                raise
        finally:
            if self.context.ok():
                self.context.try_shutdown()

    def spin_until(self, future, timeout_sec=None):
        self.executor.spin_until_future_complete(future, timeout_sec=timeout_sec)
        return future

    def spin_once(self, timeout_sec=None):
        self.executor.spin_once(timeout_sec=timeout_sec)

    def ok(self):
        return self.context.ok()

    def call(self, client, request, timeout_sec=None):
        """call_async + spin until done; None on timeout."""
        future = client.call_async(request)
        self.spin_until(future, timeout_sec)
        if not future.done():
            client.remove_pending_request(future) if hasattr(
                client, 'remove_pending_request') else None
            return None
        return future.result()

    # rclpy.action's graph functions take the node: offer them as methods like DirectNode
    def get_action_names_and_types(self):
        from labkit.rclpy.action import get_action_names_and_types
        return get_action_names_and_types(self.node)

    def get_action_server_names_and_types_by_node(self, name, namespace):
        from labkit.rclpy.action import get_action_server_names_and_types_by_node
        return get_action_server_names_and_types_by_node(self.node, name, namespace)

    def get_action_client_names_and_types_by_node(self, name, namespace):
        from labkit.rclpy.action import get_action_client_names_and_types_by_node
        return get_action_client_names_and_types_by_node(self.node, name, namespace)

    def __getattr__(self, name):
        return getattr(self.node, name)


def node_names(node, include_hidden=False):
    """Full names of the nodes in the graph (ros2node.api.get_node_names)."""
    return [
        full_node_name(n, ns) for n, ns in node.get_node_names_and_namespaces()
        if include_hidden or (n and not n.startswith(HIDDEN_PREFIX))]


def topic_names_and_types(node, include_hidden=False):
    return [(n, t) for n, t in node.get_topic_names_and_types()
            if include_hidden or not is_hidden_name(n)]


def service_names_and_types(node, include_hidden=False):
    return [(n, t) for n, t in node.get_service_names_and_types()
            if include_hidden or not is_hidden_name(n)]


# --------------------------------------------------------------------------- interfaces

def _interfaces():
    import labkit.interfaces as ifc
    return ifc


def _get(identifier, default_kind):
    """rosidl_runtime_py.utilities.get_* : 'pkg/Name' or 'pkg/kind/Name' -> class."""
    parts = identifier.split('/')
    if len(parts) == 2:
        parts = [parts[0], default_kind, parts[1]]
    if len(parts) != 3 or not all(parts):
        raise ValueError(identifier)
    try:
        return _interfaces().get_type('/'.join(parts))
    except LookupError as e:
        raise ValueError(identifier) from e


def get_message(identifier):
    cls = _get(identifier, 'msg')
    if not hasattr(cls, 'SLOT_TYPES') and not hasattr(cls, '__slots__'):
        raise ValueError(identifier)
    return cls


def get_action(identifier):
    cls = _get(identifier, 'action')
    if not (hasattr(cls, 'Goal') and hasattr(cls, 'Result') and hasattr(cls, 'Feedback')):
        raise ValueError(identifier)
    return cls


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
