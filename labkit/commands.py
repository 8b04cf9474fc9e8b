"""The plumbing every command line shares (layer 3): results, output recording, argparse.

`ros2` (labkit/cli), `colcon`, `rosdep` (labkit/ament), `ros2 bag` (labkit/bag),
`ros2 doctor`, ... all parse a command line, print into two recorded streams and
end with a `CompletedCommand`. That is plumbing, not the CLI: it lives here, one
floor below every tool, so that no tool has to reach up into `labkit.cli`
(the CLI only assembles the verbs; see ARCHITECTURE.md, "The house").

Verbs are written like ros2cli's: `main(args, io)` prints through `io`
(a `Streams`), and returns None/0 (success), an int (exit code) or a str
(one error line, exit 1).
"""
import argparse
import io
import itertools
import sys
import threading

__all__ = ['CompletedCommand', 'Recorder', 'Streams', 'CliError', 'ParserExit', 'Parser',
           'set_parse_streams', 'add_verbs', 'emit', 'CliNode', 'settle', 'is_hidden_name',
           'get_message', 'get_action', 'expand_topic']

HIDDEN_PREFIX = '_'
NODE_NAME_PREFIX = '_ros2cli'


class CompletedCommand:
    """What a finished command left behind (like subprocess.CompletedProcess)."""

    def __init__(self, args, returncode, stdout='', stderr='', exception=None, chunks=None):
        self.args = args
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        self.exception = exception  # an unexpected internal error, kept for debugging
        # [(stream name, text)] in the order printed, so a terminal-like view interleaves them
        self.chunks = chunks if chunks is not None else \
            [c for c in (('stdout', stdout), ('stderr', stderr)) if c[1]]

    def check_returncode(self):
        if self.returncode:
            import subprocess
            raise subprocess.CalledProcessError(
                self.returncode, self.args, self.stdout, self.stderr)

    def text(self):
        return ''.join(text for _, text in self.chunks)

    def __str__(self):
        return self.text()

    def __repr__(self):
        # a notebook shows the command's output, as a terminal would
        return self.text().rstrip('\n')

    def _repr_pretty_(self, p, cycle):
        p.text(self.__repr__())


class Recorder(io.StringIO):
    """One output stream of a command, also noting each write in the shared order."""

    def __init__(self, name, chunks, echo=None):
        super().__init__()
        self.name = name
        self.chunks = chunks
        self.echo = echo

    def write(self, text):
        if text:
            self.chunks.append((self.name, text))
            if self.echo is not None:
                self.echo(self.name, text)
        return super().write(text)


class CliError(Exception):
    """A user mistake: one line on stderr, exit code 1 (ros2cli raises RuntimeError)."""


class ParserExit(Exception):
    def __init__(self, status):
        super().__init__(status)
        self.status = status


class Streams:
    """Where a verb prints: captured text for short verbs, the process sink for jobs."""

    def __init__(self, out, err):
        self.out = out
        self.err = err

    def print(self, *values, sep=' ', end='\n'):
        print(*values, sep=sep, end=end, file=self.out)

    def eprint(self, *values, sep=' ', end='\n'):
        print(*values, sep=sep, end=end, file=self.err)


_parsing = threading.local()  # .streams: the Streams of the command this thread parses


def set_parse_streams(streams):
    _parsing.streams = streams


class Parser(argparse.ArgumentParser):
    """argparse that prints into the command's streams and never calls sys.exit."""

    def _get_formatter(self):
        # a notebook has no terminal: help is laid out for 80 columns, the same every run
        return self.formatter_class(prog=self.prog, width=78)

    def _print_message(self, message, file=None):
        if not message:
            return
        streams = _parsing.streams
        target = streams.err if (file is not None and file is not sys.stdout) else streams.out
        target.write(message)

    def exit(self, status=0, message=None):
        if message:
            self._print_message(message, sys.stderr)
        raise ParserExit(status)


def add_verbs(noun_parser, cli_name, verbs):
    """Add one subparser per verb: `verbs` is [(name, help, add_arguments, main), ...]."""
    description = ''
    width = max(len(v[0]) for v in verbs)
    for name, doc, _, _ in verbs:
        description += f'{name.ljust(width)}  {doc}\n'
    sub = noun_parser.add_subparsers(
        title='Commands', description=description,
        metavar=f'Call `{cli_name} <command> -h` for more detailed usage.',
        parser_class=Parser)
    sub.dest = ' verb'
    sub.required = False
    for name, doc, add_arguments, main in verbs:
        p = sub.add_parser(name, description=doc,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        p.set_defaults(_verb=main)
        if add_arguments is not None:
            add_arguments(p)
    return sub


def emit(result, target=None, mode='w'):
    """Print a finished command as a terminal would: in the order it printed.

    With `target`, stdout goes to that file (`>` / `>>`) and only stderr is shown.
    """
    chunks = getattr(result, 'chunks', None)
    if chunks is None:
        chunks = [('stdout', result.stdout), ('stderr', result.stderr)]
    merged = []  # one write per run of the same stream keeps stored notebooks small
    for name, text in chunks:
        if merged and merged[-1][0] == name:
            merged[-1] = (name, merged[-1][1] + text)
        elif text:
            merged.append((name, text))
    chunks = merged
    if target is not None:
        with open(target, mode, encoding='utf-8') as f:
            f.write(''.join(text for name, text in chunks if name == 'stdout'))
    for name, text in chunks:
        if name == 'stdout' and target is not None:
            continue
        stream = sys.stdout if name == 'stdout' else sys.stderr
        stream.write(text)
        stream.flush()


# --------------------------------------------------------------------------- names

def is_hidden_name(name):
    return any(part.startswith(HIDDEN_PREFIX) for part in name.split('/'))


def expand_topic(node, topic):
    """A topic name as the node sees it ('chatter' -> '/chatter'); bad names: one CliError line."""
    try:
        from labkit.rclpy.expand_topic_name import expand_topic_name
    except ImportError:
        return topic if topic.startswith('/') else '/' + topic
    try:
        return expand_topic_name(topic, node.get_name(), node.get_namespace())
    except Exception as e:  # rclpy's invalid-name exceptions: one line
        raise CliError(str(e))


# --------------------------------------------------------------------------- the command's own node

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
