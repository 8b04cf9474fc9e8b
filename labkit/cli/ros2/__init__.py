"""`ros2 <noun> <verb> ...` on labkit: `run_command("topic list -t")`.

One module per noun (node, topic, service, action, interface, param, pkg, run),
one function per verb, written like ros2cli's verbs on the rclpy API. Short
verbs return a `CompletedCommand`; verbs that keep running (run, echo, hz, ...)
start a background job and return its `Job` at once (see jobs.py).

Adding a noun (later layers: bag, launch, doctor, ...): a module with
`add_arguments(parser, cli_name)` that calls `_base.add_verbs(parser, cli_name,
[(verb, one-line doc, add_arguments(p), main(args, io)), ...])`, registered
with `labkit.plugins.register_noun(name, 'module.path', doc)`. A verb prints through
`io.print`/`io.eprint` and returns None, an exit code, or an error line; a
parser default `_background=lambda args: bool` makes it a job when true.
"""
import argparse
import importlib
import traceback

from labkit import oslayer, plugins
from labkit.cli.ros2 import _base
from labkit.cli.ros2._base import CliError, Parser, ParserExit, Streams
# the command plumbing lives one floor down (tools use it too); kept importable from here
from labkit.commands import CompletedCommand, Recorder as _Recorder

__all__ = ['run_command', 'CompletedCommand', 'register_noun']

# noun -> (module path, one-line doc): the registry in labkit.plugins, where later layers
# (bag, launch, ...) register theirs without importing the CLI.
_NOUNS = plugins.NOUNS
_NOUNS.update({
    'action': ('labkit.cli.ros2.action', 'Various action related sub-commands'),
    'daemon': ('labkit.cli.ros2.daemon', 'Various daemon related sub-commands'),
    'interface': ('labkit.cli.ros2.interface', 'Show information about ROS interfaces'),
    'node': ('labkit.cli.ros2.node', 'Various node related sub-commands'),
    'param': ('labkit.cli.ros2.param', 'Various param related sub-commands'),
    'pkg': ('labkit.cli.ros2.pkg', 'Various package related sub-commands'),
    'run': ('labkit.cli.ros2.run', 'Run a package specific executable'),
    'service': ('labkit.cli.ros2.service', 'Various service related sub-commands'),
    'topic': ('labkit.cli.ros2.topic', 'Various topic related sub-commands'),
})
register_noun = plugins.register_noun


def split_command(command):
    argv = oslayer.split_args(command) if isinstance(command, str) else [str(a) for a in command]
    if argv[:1] == ['ros2']:
        argv = argv[1:]
    return argv


def build_parser(argv):
    parser = Parser(
        prog='ros2', description='ros2 is an extensible command-line tool for ROS 2.',
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument(
        '--use-python-default-buffering', action='store_true', default=False,
        help='Do not force line buffering in stdout and instead use the python default '
             'buffering, which might be affected by PYTHONUNBUFFERED/-u and depends on '
             'whatever stdout is interactive or not')
    width = max(len(n) for n in _NOUNS)
    description = ''.join(f'{n.ljust(width)}  {_NOUNS[n][1]}\n' for n in sorted(_NOUNS))
    sub = parser.add_subparsers(
        title='Commands', description=description,
        metavar='Call `ros2 <command> -h` for more detailed usage.', parser_class=Parser)
    sub.dest = ' command'
    sub.required = False
    # only the chosen noun builds its verbs (cheap start, and a broken noun spares the rest)
    chosen = next((a for a in argv if not a.startswith('-')), None)
    for name in sorted(_NOUNS):
        module_name, doc = _NOUNS[name]
        p = sub.add_parser(name, description=doc,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        p.set_defaults(_noun=name, _noun_parser=p)
        if name == chosen:
            importlib.import_module(module_name).add_arguments(p, f'ros2 {name}')
    return parser


def run_command(command, echo=None):
    """Run one ros2 command line; returns a CompletedCommand, or a Job for long-running verbs.

    `echo(stream_name, text)`, if given, sees every write as it happens (the %ros2
    magic prints through it, so a command's lines and the lines of the nodes it
    talks to appear in the order they happened, as in side-by-side terminals)."""
    plugins.register_all()
    try:
        argv = split_command(command)
    except ValueError as e:  # unbalanced quotes
        return CompletedCommand([], 1, '', f'ros2: error: {e}\n')
    if argv[:1] == ['jobs']:
        from labkit.cli.ros2 import jobs
        return jobs.jobs_command(argv)
    if argv[:1] in (['connect'], ['disconnect']):
        from labkit.cli.ros2 import connect
        return connect.connect_command(argv)
    chunks = []
    out, err = _Recorder('stdout', chunks, echo), _Recorder('stderr', chunks, echo)
    streams = Streams(out, err)
    _base.set_parse_streams(streams)
    from labkit.ament import files
    try:
        parser = build_parser(argv)
        # a path typed back as labkit printed it (/root/... of the sandbox) opens that file
        args = parser.parse_args([files.expand_arg(a) for a in argv])
    except ParserExit as e:
        return CompletedCommand(argv, e.status, out.getvalue(), err.getvalue(), None, chunks)
    except Exception as e:  # a noun module that cannot load: one line, as everywhere
        return CompletedCommand(argv, 1, '', f'ros2: {type(e).__name__}: {e}\n', e)
    verb = getattr(args, '_verb', None)
    if verb is None:
        target = getattr(args, '_noun_parser', parser)
        target.print_help()
        return CompletedCommand(argv, 0, out.getvalue(), err.getvalue(), None, chunks)
    background = getattr(args, '_background', None)
    if background is not None and background(args):
        from labkit.cli.ros2 import jobs
        if getattr(args, '_noun', None) == 'run':
            from labkit.cli.ros2 import run
            try:
                run.check(args.package_name, args.executable_name)
            except CliError as e:
                return CompletedCommand(argv, 1, out.getvalue(), f'{e}\n')
            return run.start_run_job(argv, args)
        return jobs.start_verb_job(argv, verb, args)
    rc, exc = call_verb(verb, args, streams)
    return CompletedCommand(argv, rc, out.getvalue(), err.getvalue(), exc, chunks)


def call_verb(verb, args, streams):
    """Run a verb; map its result and errors to (exit code, unexpected exception)."""
    from labkit.graph.world import Deadlock
    try:
        result = verb(args, streams)
    except Deadlock:
        streams.eprint('labkit: nothing in the graph can answer, so this command would wait '
                       'forever (virtual time)')
        return 1, None
    except (CliError, RuntimeError) as e:
        streams.eprint(str(e))
        return 1, None
    except KeyboardInterrupt:
        return 2, None
    except SystemExit as e:  # the middleware ended the process (Fast DDS on a domain > 232)
        return (e.code if isinstance(e.code, int) else 1), None
    except Exception as e:  # a labkit bug or a deadlock: one line, never a traceback
        name = type(e).__name__
        streams.eprint(f'ros2: {name}: {e}' if str(e) else f'ros2: {name}')
        e.__labkit_traceback__ = traceback.format_exc()
        return 1, e
    if result is None:
        return 0, None
    if isinstance(result, str):
        streams.eprint(result)
        return 1, None
    return int(result), None
