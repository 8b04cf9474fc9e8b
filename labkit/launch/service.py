"""LaunchService: visit a launch description and run its processes as labkit processes.

The console lines are launch's: the log folder and verbosity first, one
`process started with pid [N]` per process, each output line prefixed with
`[<exec>-<n>] `, then `process has finished cleanly [pid N]` or
`process has died [pid N, exit code C, cmd '...'].`. The service ends when
every process has ended (and no timer is pending), or at Ctrl-C (a job's
stop): `user interrupted with ctrl-c (SIGINT)`, then every process is stopped.
"""
import atexit
import datetime
import os
import socket

from labkit.launch.launch_context import LaunchContext


_PARAMS_FILES = set()      # every temporary params file not yet removed (atexit removes them)


def _remove_params_files(paths=None):
    for path in list(_PARAMS_FILES if paths is None else paths):
        try:
            os.unlink(path)
        except OSError:
            pass
        _PARAMS_FILES.discard(path)


atexit.register(_remove_params_files)


class _Child:
    def __init__(self, name, cmd, output):
        self.name = name            # e.g. capture_image-1
        self.cmd = cmd              # shown in "process has died"
        self.output = output        # 'screen' | 'log' | 'both'
        self.proc = None
        self.reported = False
        self.partial = {'stdout': '', 'stderr': ''}
        self.held = []              # output kept back while the other processes start


class LaunchService:
    def __init__(self, *, argv=None, noninteractive=False, debug=False):
        self.context = LaunchContext(argv, noninteractive)
        self.context.launch_service = self
        self._descriptions = []
        self._children = []
        self._timers = []           # [deadline_ns, actions]
        self._count = 0
        self._holding = False
        self._params_files = []
        from labkit import process
        self._owner = process.current()     # the process whose output is the console

    # ------------------------------------------------------------------ API
    def include_launch_description(self, launch_description):
        self._descriptions.append(launch_description)

    def run(self, *, shutdown_when_idle=True):
        """Run until every process ended (or Ctrl-C, or a Shutdown event); the exit code."""
        self.log_info('All log files can be found below ' + self._log_dir())
        self.log_info('Default logging verbosity is set to INFO')
        try:
            try:
                self._visit_all(self._descriptions)
                self._loop(shutdown_when_idle)
            except KeyboardInterrupt:
                self._print('[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)\n')
                self._interrupted()
                return 0
            except Exception as e:      # launch's one line for a failing launch file
                message = str(e)    # a KeyError shows its quoted repr, as in launch
                self._print('[ERROR] [launch]: Caught exception in launch (see debug for '
                            f'traceback): {message}\n')
                self._shutting_down = True
                self._shutdown()
                return 1
        finally:
            self._cleanup()
        return 0

    def _loop(self, shutdown_when_idle):
        from labkit.events_placeholder import _noop  # noqa  (replaced below)
    # ------------------------------------------------------------------ visiting
    def _visit_all(self, entities):
        self._holding = True
        try:
            for entity in entities:
                self._visit(entity)
        finally:
            self._holding = False
            self._release_held()

    def _visit(self, entity):
        subs = entity.visit(self.context)
        for sub in subs or ():
            self._visit(sub)

    # ------------------------------------------------------------------ what actions call
    def log_info(self, text, logger='launch'):
        self._print(f'[INFO] [{logger}]: {text}\n')

    def log_warning(self, text, logger='launch'):
        self._print(f'[WARNING] [{logger}]: {text}\n')

    def log_error(self, text, logger='launch'):
        self._print(f'[ERROR] [{logger}]: {text}\n')

    def add_timer(self, period, actions):
        from labkit.graph import world
        self._timers.append([world.system_ns() + int(period * 1e9), list(actions)])

    def add_params_file(self, path):
        self._params_files.append(path)
        _PARAMS_FILES.add(path)     # a launch still running when Python exits leaves none

    def start_node(self, *, package, executable, argv, name=None, output='log', cmd=None,
                   exec_name=None):
        """Start `ros2 run package executable argv...` as one launched process."""
        from labkit import process
        self._count += 1
        label = f'{exec_name or executable}-{self._count}'
        child = _Child(label, ' '.join(cmd or [executable, *argv]), output)
        self._children.append(child)
        child.proc = process.start([package, executable, *argv], name=label,
                                   sink=lambda stream, text: self._child_output(
                                       child, stream, text))
        self.log_info(f'process started with pid [{child.proc.pid}]', logger=label)
        return child.proc

    # ------------------------------------------------------------------ output
    def _print(self, text):
        self._owner._write('stdout', text)

    def _child_output(self, child, stream, text):
        if child.output == 'log' and stream == 'stdout':
            return      # output='log': stdout goes to the log file only, stderr is shown
        buf = child.partial[stream] + text
        *lines, rest = buf.split('\n')
        child.partial[stream] = rest
        for line in lines:
            out = f'[{child.name}] {line}\n'
            if self._holding:
                child.held.append((stream, out))
            else:
                self._owner._write(stream, out)

    def _release_held(self):
        for child in self._children:
            for stream, out in child.held:
                self._owner._write(stream, out)
            child.held.clear()

    def _flush_partial(self, child):
        for stream in ('stdout', 'stderr'):
            if child.partial[stream]:
                self._owner._write(stream, f'[{child.name}] {child.partial[stream]}\n')
                child.partial[stream] = ''

    # ------------------------------------------------------------------ waiting, ending
    def _running(self):
        return [c for c in self._children if c.proc is not None and c.proc.running]

    def _report_exits(self):
        for child in self._children:
            if child.reported or child.proc is None or child.proc.running:
                continue
            child.reported = True
            self._flush_partial(child)
            code = child.proc.returncode or 0
            if code in (0, -2):     # -2: stopped by Ctrl-C, like SIGINT handled by rclpy
                self.log_info(f'process has finished cleanly [pid {child.proc.pid}]',
                              logger=child.name)
            else:
                self.log_error(f"process has died [pid {child.proc.pid}, exit code {code}, "
                               f"cmd '{child.cmd}'].", logger=child.name)

    def _wait(self):
        from labkit.graph import world
        from labkit.rclpy import _wait
        timeout = None
        if self._timers:
            timeout = max(0, min(t[0] for t in self._timers) - world.system_ns())

        def something_happened():
            return any(not c.reported and c.proc is not None and not c.proc.running
                       for c in self._children)
        _wait.wait(something_happened, timeout_ns=timeout)

    def _shutdown(self):
        self._timers.clear()
        for child in self._children:
            if child.proc is not None and child.proc.running:
                child.proc.stop()
        self._report_exits()

    def _cleanup(self):
        _remove_params_files(self._params_files)
        self._params_files.clear()

    def _log_dir(self):
        """~/.ros/log/<date-time>-<host>-<pid>, the same every run in virtual time."""
        from labkit.ament import files
        from labkit.graph import world
        seconds = world.system_ns() / 1e9
        stamp = datetime.datetime.fromtimestamp(seconds, datetime.timezone.utc)
        virtual = world.mode() == 'virtual'
        host = 'labkit' if virtual else socket.gethostname()
        name = '{}-{}-{}'.format(stamp.strftime('%Y-%m-%d-%H-%M-%S-%f'), host,
                                 self._owner.pid)
        return files.display(os.path.join(files.expand('~'), '.ros', 'log', name))
