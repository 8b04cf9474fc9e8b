"""IPython magics: `%ros2 ...` (and, from later layers, `%colcon`, `%source`, ...).

`%load_ext labkit` activates the import hook and registers every magic in
MAGICS; it prints nothing on success. A magic prints like a terminal: stdout,
then stderr, never a traceback; `> file` and `>> file` redirect stdout.
"""
import sys

from labkit import oslayer, plugins
from labkit.commands import emit  # the plumbing lives one floor down (kept importable here)

# magic name -> function(line): the registry in labkit.plugins, where later layers add
# theirs (plugins.register_magic) without importing the CLI
MAGICS = plugins.MAGICS
register = plugins.register_magic


def split_redirect(line):
    """'param dump /t > t.yaml' -> (['param', 'dump', '/t'], 't.yaml', 'w')."""
    # `%ros2 node list  # comment` drops the comment, as a shell does
    tokens = oslayer.split_args(line, punctuation_chars='>', comments=True)
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
    lines = LineWriter()

    def echo(name, text):
        if name == 'stdout' and target is not None:
            return                      # goes to the file, like `> file` in a shell
        lines.write(name, text)
        echoed.append(name)

    try:
        result = run_command(argv, echo=echo)
    finally:
        lines.flush()
    if isinstance(result, Job):
        if target is not None:
            _redirect_job(result.process, target, mode)
        # its output arrives through the process, like a terminal's; the cell gets the
        # handle: `job = %ros2 run ...`, later `job.stop()`
        return JobHandle(result)
    if target is not None:
        with open(target, mode, encoding='utf-8') as f:
            f.write(result.stdout)
    # lines the command made without the recorder (early argument errors) still show
    if not echoed and (result.stdout or result.stderr) and target is None:
        emit(result)
    running = getattr(result, 'job', None)
    if running is not None:             # "already running": the handle of that job
        return JobHandle(running)


class LineWriter:
    """Writes to sys.stdout/sys.stderr whole lines at a time, as a terminal shows them
    (a verb prints a line in several pieces; the notebook must get it in one)."""

    def __init__(self):
        self._partial = {'stdout': '', 'stderr': ''}

    def write(self, name, text):
        buf = self._partial[name] + text
        cut = buf.rfind('\n') + 1
        self._partial[name] = buf[cut:]
        if cut:
            other = 'stderr' if name == 'stdout' else 'stdout'
            self._out(other, self._partial[other])     # a started line of the other
            self._partial[other] = ''                   # stream goes first, as it came
            self._out(name, buf[:cut])

    def flush(self):
        for name in ('stdout', 'stderr'):
            self._out(name, self._partial[name])
            self._partial[name] = ''

    @staticmethod
    def _out(name, text):
        if text:
            stream, other = (sys.stdout, sys.stderr) if name == 'stdout' else \
                (sys.stderr, sys.stdout)
            other.flush()       # what waits on the other stream was printed first
            stream.write(text)
            stream.flush()


class JobHandle:
    """What `job = %ros2 run ...` gives the cell: the background job (`.stop()`,
    `.wait()`, `.output`, `.show()`, ...). The cell that started the job already shows
    it, so as the cell's last line it adds nothing; displayed later, it shows the
    job again."""

    def __init__(self, job):
        self.job = job
        self._cell = _execution_count()

    def __getattr__(self, name):
        return getattr(self.job, name)

    def __repr__(self):
        return self.job.line()

    def _ipython_display_(self):
        if _execution_count() == self._cell:
            return
        if self.job.view is not None:
            self.job.show()
        else:
            print(self.job.line())


def _execution_count():
    try:
        from IPython import get_ipython
    except ImportError:
        return None
    shell = get_ipython()
    return getattr(shell, 'execution_count', None)


def _redirect_job(process, target, mode):
    """`%ros2 topic echo /x > file`: the job's later stdout goes on to the file, as in a
    shell; its stderr still shows in the notebook."""
    out = open(target, mode, encoding='utf-8')

    def sink(name, text):
        if name == 'stdout':
            out.write(text)
            out.flush()
            return
        process.echo_text(name, text)   # shown as its other lines are (whole lines)

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
    if _loaded_into is not ipython:
        # a line a background process started shows when the cell ends, not later
        ipython.events.register('post_run_cell', _flush_process_lines)
    from labkit import process
    process.live_view = _process_view
    _loaded_into = ipython


class _ProcessJob:
    """A process the notebook started (labkit.process.start), as its output area sees it."""

    def __init__(self, process):
        self.process = process

    def running(self):
        return self.process.returncode is None      # from before its thread starts

    def stop(self):
        self.process.stop()

    def line(self):
        state = 'running' if self.running() else 'stopped'
        return f'{self.process.pid} {state} {self.process.name}'


def _process_view(process):
    """Live JupyterLab: an output area with a Stop button for a process the notebook
    started itself, as a `ros2 run` job has (labkit/viz/job_output.py)."""
    from labkit.viz import job_output
    if not job_output.enabled():
        return None
    view = job_output.JobView(process.name)
    view.attach(_ProcessJob(process))
    view.show()
    return view


def _flush_process_lines(*_):
    process = sys.modules.get('labkit.process')   # nothing to do before any process ran
    if process is not None:
        process.flush_echo_all()


def unload_ipython_extension(ipython):
    global _loaded_into
    try:
        ipython.events.unregister('post_run_cell', _flush_process_lines)
    except ValueError:
        pass
    process = sys.modules.get('labkit.process')
    if process is not None:
        process.live_view = None
    _loaded_into = None
