"""IPython magics: `%ros2 ...` (and, from later layers, `%colcon`, `%source`, ...).

`%load_ext labkit` activates the import hook and registers every magic in
MAGICS; it prints nothing on success. A magic prints like a terminal: stdout,
then stderr, never a traceback; `> file` and `>> file` redirect stdout.
"""
import shlex
import sys

from labkit import plugins
from labkit.commands import emit  # the plumbing lives one floor down (kept importable here)

# magic name -> function(line): the registry in labkit.plugins, where later layers add
# theirs (plugins.register_magic) without importing the CLI
MAGICS = plugins.MAGICS
register = plugins.register_magic


def split_redirect(line):
    """'param dump /t > t.yaml' -> (['param', 'dump', '/t'], 't.yaml', 'w')."""
    lexer = shlex.shlex(line, posix=True, punctuation_chars='>')
    lexer.whitespace_split = True
    lexer.commenters = '#'   # `%ros2 node list  # comment` drops the comment, as a shell does
    tokens = list(lexer)
    target, mode = None, None
    for i, token in enumerate(tokens):
        if token in ('>', '>>'):
            if i + 1 >= len(tokens):
                raise ValueError("syntax error near unexpected token `newline'")
            target, mode = tokens[i + 1], 'a' if token == '>>' else 'w'
            tokens = tokens[:i] + tokens[i + 2:]
            break
    return tokens, target, mode


def ros2_magic(line):
    """%ros2 <noun> <verb> [args] [> file]: run a ros2 command in the notebook."""
    from labkit.cli.ros2 import run_command
    from labkit.cli.ros2.jobs import Job
    try:
        argv, target, mode = split_redirect(line)
    except ValueError as e:
        print(f'ros2: {e}', file=sys.stderr)
        return
    echoed = []

    def echo(name, text):
        if name == 'stdout' and target is not None:
            return                      # goes to the file, like `> file` in a shell
        stream = sys.stdout if name == 'stdout' else sys.stderr
        stream.write(text)
        stream.flush()
        echoed.append(name)

    result = run_command(argv, echo=echo)
    if isinstance(result, Job):
        if target is not None:
            _redirect_job(result.process, target, mode)
        return  # its output arrives through the process sink, like a terminal's
    if target is not None:
        with open(target, mode) as f:
            f.write(result.stdout)
    # lines the command made without the recorder (early argument errors) still show
    if not echoed and (result.stdout or result.stderr) and target is None:
        emit(result)


def _redirect_job(process, target, mode):
    """`%ros2 topic echo /x > file`: the job's later stdout goes on to the file, as in a
    shell; its stderr still shows in the notebook."""
    from labkit import process as processes
    out = open(target, mode)

    def sink(name, text):
        if name == 'stdout':
            out.write(text)
            out.flush()
            return
        stream = processes._original.get(name)
        if stream is not None:
            stream.write(text)
            stream.flush()

    process.sink = sink


MAGICS['ros2'] = ros2_magic

_loaded_into = None


def _late_magic(name, function):
    """A magic registered after `%load_ext labkit`: IPython gets it at once."""
    if _loaded_into is not None:
        _register_one(_loaded_into, name, function)


plugins.on_magic(_late_magic)


def _register_one(ipython, name, function):
    from IPython.core.magic import no_var_expand

    def magic(line):
        return function(line)
    magic.__name__ = name
    magic.__doc__ = function.__doc__
    # `{linear: {x: 2.0}}` must reach ros2 untouched, as in a shell
    ipython.register_magic_function(no_var_expand(magic), 'line', name)


def load_ipython_extension(ipython):
    global _loaded_into
    from labkit import compat
    compat.activate()
    for name, function in MAGICS.items():
        _register_one(ipython, name, function)
    _loaded_into = ipython


def unload_ipython_extension(ipython):
    global _loaded_into
    _loaded_into = None


def _late_magic(name, function):
    """A magic registered after `%load_ext labkit`: IPython gets it at once."""
    if _loaded_into is not None:
        _register_one(_loaded_into, name, function)


plugins.on_magic(_late_magic)
