"""Background jobs: `ros2 run`, `topic echo`, `topic hz`, ... keep running after the cell.

Each job is a labkit process (labkit/process.py), so its output goes through
the process output sink (kept in `Job.output`). Where it shows:

- virtual time (nbval, `make book-exec`) or a script: as plain text in the
  running cell / the terminal, whole lines at a time;
- live JupyterLab: in an output area that belongs to the job, displayed in the
  cell that started it, with its own Stop button; lines printed while no cell
  runs land there too, never in whatever cell runs next.

Stop a job through the handle the cell got back:

    job = %ros2 run turtlesim turtlesim_node     # (or job = labkit.ros2('run ...'))
    ...
    job.stop()

`ros2 jobs` lists the running ones, `ros2 jobs stop <id>|all` stops them.
Running the very same command line again while it still runs does not start
a duplicate (it shows the running job's windows again, live); `--new`
(labkit-only flag) starts another anyway. Finished jobs are forgotten when the
next job starts and at `labkit.reset()`.
"""
import itertools
import sys

from labkit.cli.ros2._base import Streams, settle

_jobs = []
_ids = itertools.count(1)


class Job:
    """One background command: id, command, pid, state, output, stop()."""

    def __init__(self, job_id, command, process):
        self.id = job_id
        self.command = command
        self.process = process
        self.args = command.split()[1:]
        self._stopped = False
        self.view = None                # live output area (labkit.viz.job_output.JobView)

    @property
    def pid(self):
        return self.process.pid

    @property
    def output(self):
        """The lines the job printed so far (stdout and stderr)."""
        return list(self.process.output)

    @property
    def stdout(self):
        return ''.join(line if line.endswith('\n') else line + '\n' for line in self.output)

    stderr = ''

    def running(self):
        return self.process.running

    @property
    def state(self):
        if self.running():
            return 'running'
        return 'stopped' if self._stopped else 'done'

    @property
    def returncode(self):
        if self.running():
            return None
        return self.process.returncode or 0

    def check_returncode(self):
        if self.returncode:
            import subprocess
            raise subprocess.CalledProcessError(self.returncode, self.args, self.stdout, '')

    def stop(self):
        """Stop the job (Ctrl-C in its terminal): its nodes leave the graph."""
        self._stopped = True
        self.process.stop()
        return self

    def wait(self, timeout=None):
        """Follow the job until it ends (or `timeout` seconds, in the world's time)."""
        self.process.wait(timeout)
        return self.returncode

    def show(self):
        """Show the job's windows (canvas, keypad) and output area again (live JupyterLab)."""
        from labkit import process as processes
        for proc in processes.descendants(self.process):
            for window in list(proc.windows):
                window._ipython_display_()
        if self.view is not None:
            self.view.show()
        return self

    def line(self):
        return f'[{self.id}] {self.pid} {self.state} {self.command}'

    def __repr__(self):
        return self.line()

    def _repr_pretty_(self, p, cycle):
        p.text(self.line())


def all_jobs():
    return list(_jobs)


def running_jobs():
    return [j for j in _jobs if j.running()]


def find_running(command):
    for job in _jobs:
        if job.command == command and job.running():
            return job
    return None


def _completed(argv, rc, out='', err=''):
    from labkit.cli.ros2 import CompletedCommand
    return CompletedCommand(argv, rc, out, err)


def start(argv, command, starter, new=False):
    """Start (or report the running duplicate of) a job; `starter()` makes the process."""
    if not new:
        running = find_running(command)
        if running is not None:
            result = _completed(
                argv, 0,
                f'{running.line()} (already running; `ros2 jobs stop {running.id}` '
                'stops it, --new starts another)\n')
            result.job = running
            if running.view is not None:    # live: the learner gets the window back
                running.show()
            return result
    _forget_finished()
    # Hold back what the program prints while it starts: if it fails at once (a bad
    # type, a crash in __init__) the command ends like a short one, with its error lines.
    held = []
    process = starter(lambda stream, text: held.append((stream, text)))
    settle()  # virtual time: let it run up to its first real wait (or its end)
    view = _live_view(command)
    text = {'stdout': '', 'stderr': ''}
    for stream, chunk in held:
        text[stream] += chunk
    if not process.running and process.returncode:
        process.sink = None
        if view is not None:
            view.close()
        return _completed(argv, process.returncode, text['stdout'], text['stderr'])
    job = Job(next(_ids), command, process)
    _jobs.append(job)
    if view is not None:
        view.attach(job)
        job.view = process.view = view
    process.sink = None  # from now on the process echoes its own output
    for stream, chunk in _merged(held):
        # what it printed while starting shows now, before what the cell does next
        # (as in its terminal), not whenever the kernel's stream buffer is flushed
        process.echo_text(stream, chunk)
    if view is not None:
        view.show()
    return job


def _merged(chunks):
    """Adjacent pieces of the same stream as one (the order of the streams kept)."""
    merged = []
    for stream, chunk in chunks:
        if merged and merged[-1][0] == stream:
            merged[-1] = (stream, merged[-1][1] + chunk)
        elif chunk:
            merged.append((stream, chunk))
    return merged


def _live_view(command):
    """A job output area, in live JupyterLab only (virtual time prints plain text)."""
    try:
        from labkit.viz import job_output
    except ImportError:
        return None
    return job_output.JobView(command) if job_output.enabled() else None


def _forget_finished():
    """A shell forgets a job once it has ended: its process and output are freed
    (a handle the notebook kept still works)."""
    _jobs[:] = [j for j in _jobs if j.running()]


def start_process(argv, name, target=None, sink=None):
    """labkit.process.start: `ros2 run` argv, or `target` (a main(args=None)) as the program."""
    from labkit import process
    if target is None:
        return process.start(argv, name=name, sink=sink)
    return process.start(argv, name=name, main=target, args=['ros2', *argv], sink=sink)


class _LiveStreams(Streams):
    """Prints to whatever sys.stdout/sys.stderr is in the job's thread (the process sink)."""

    def __init__(self):
        super().__init__(None, None)

    @property
    def out(self):
        return sys.stdout

    @out.setter
    def out(self, value):
        pass

    @property
    def err(self):
        return sys.stderr

    @err.setter
    def err(self, value):
        pass


def start_verb_job(argv, verb, parsed):
    """Run a ros2 verb as a background job."""
    from labkit.cli.ros2 import call_verb
    command = 'ros2 ' + ' '.join(_quote(a) for a in argv)

    def main(args=None):
        parsed.in_job = True
        rc, _ = call_verb(verb, parsed, _LiveStreams())
        return rc

    return start(argv, command,
                 lambda sink: start_process(argv, f'ros2 {argv[0]} {argv[1]}', main, sink))


def _quote(arg):
    import shlex
    return shlex.quote(arg)


def jobs_command(argv):
    """`ros2 jobs` (list) and `ros2 jobs stop <id>|all` (labkit-only)."""
    rest = argv[1:]
    if not rest or rest == ['list']:
        lines = ''.join(j.line() + '\n' for j in running_jobs())
        return _completed(argv, 0, lines)
    if rest[0] == 'stop' and len(rest) == 2:
        if rest[1] == 'all':
            chosen = running_jobs()
        else:
            try:
                wanted = int(rest[1].lstrip('%'))
            except ValueError:
                return _completed(argv, 1, '', f'ros2 jobs: no such job: {rest[1]}\n')
            chosen = [j for j in _jobs if j.id == wanted]
            if not chosen:
                return _completed(argv, 1, '', f'ros2 jobs: no such job: {rest[1]}\n')
        out = ''
        for job in chosen:
            job.stop()
            out += job.line() + '\n'
        return _completed(argv, 0, out)
    return _completed(argv, 2, '', 'usage: ros2 jobs [list | stop <id>|all]\n')


def forget_all():
    """Called when labkit resets: every process is gone."""
    for job in _jobs:
        if job.view is not None:
            job.view.finish()
    _jobs.clear()


def _install_reset_hook():
    from labkit import process
    if forget_all not in process.reset_hooks:
        process.reset_hooks.append(forget_all)


_install_reset_hook()
