"""LaunchService: visit a launch description and run its processes as labkit processes.

The console lines are launch's: the log folder and verbosity first, one
`process started with pid [N]` per process, each output line prefixed with
`[<exec>-<n>] `, then `process has finished cleanly [pid N]` or
`process has died [pid N, exit code C, cmd '...'].`. The service ends when
every process has ended (and no timer is pending), or at Ctrl-C (a job's
stop): `user interrupted with ctrl-c (SIGINT)`, then every process is stopped.
Events (process started / output / exited, execution complete, shutdown) are
queued and handled between visits by the registered event handlers, newest first.
"""
import atexit
import datetime
import os
import socket
import sys
import threading
from collections import deque

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
    def __init__(self, name, cmd, output, action=None, argv=None):
        self.name = name            # e.g. capture_image-1
        self.cmd = cmd              # shown in "process has died"
        self.argv = argv or []
        self.output = output        # 'screen' | 'log' | 'both'
        self.action = action        # the ExecuteProcess/Node that started it
        self.proc = None
        self.reported = False
        self.partial = {'stdout': '', 'stderr': ''}
        self.pending_io = {'stdout': '', 'stderr': ''}   # not yet turned into ProcessIO
        self.io_lock = threading.Lock()     # live time: the process writes while we read
        self.held = []              # output kept back while the other processes start


class LaunchService:
    def __init__(self, *, argv=None, noninteractive=False, debug=False):
        self.context = LaunchContext(argv, noninteractive)
        self.context.launch_service = self
        self._descriptions = []
        self._children = []
        self._timers = []           # [deadline_ns, actions]
        self._events = deque()
        self._count = 0
        self._holding = False
        self._shutting_down = False
        self._params_files = []
        self._saved_environ = None      # os.environ before the first SetEnvironmentVariable
        from labkit import process
        self._owner = process.current()     # the process whose output is the console

    # ------------------------------------------------------------------ API
    def include_launch_description(self, launch_description):
        self._descriptions.append(launch_description)

    def emit_event(self, event):
        self._events.append(event)

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
                self._shutdown(send_sigint=True)
                return 1
        finally:
            self._cleanup()
        return 0

    def _loop(self, shutdown_when_idle):
        from labkit.graph import world
        from labkit.launch.events import Shutdown
        while True:
            self._collect_io()
            if not self._events:        # a process's last output is handled before its exit
                self._report_exits()
            if self._events:
                self._process_events()
                if self._shutting_down:
                    return
                continue
            now = world.system_ns()
            due = [t for t in self._timers if t[0] <= now]
            for timer in due:
                self._timers.remove(timer)
                self._visit_all(timer[1])
            if due:
                continue
            if not self._running() and (not self._timers or not shutdown_when_idle):
                self.emit_event(Shutdown(reason='idle'))
                continue
            self._wait()

    def _interrupted(self):
        """Ctrl-C: the Shutdown event (OnShutdown handlers run), then every process stops."""
        from labkit.launch.events import Shutdown
        self._events.clear()
        self.emit_event(Shutdown(reason='ctrl-c (SIGINT)', due_to_sigint=True))
        try:
            self._process_events()
        except KeyboardInterrupt:
            pass
        except Exception as e:      # a failing handler must not keep processes running
            self.log_error(str(e))
        if not self._shutting_down:
            self._shutting_down = True
            self._shutdown()

    # ------------------------------------------------------------------ events
    def _process_events(self):
        from labkit.launch.events import Shutdown
        while self._events:
            event = self._events.popleft()
            if isinstance(event, Shutdown) and self._shutting_down:
                continue
            for handler in list(self.context._event_handlers):
                if handler.matches(event):
                    saved = self.context.locals.get('event')
                    entities = handler.handle(event, self.context)
                    self._visit_all(entities or [])
                    self.context.locals['event'] = saved
            if isinstance(event, Shutdown):
                self._shutting_down = True
                self._shutdown(send_sigint=not event.due_to_sigint)
                self._collect_io()
                self._report_exits()

    def _collect_io(self):
        """Output a process wrote since the last look: one ProcessIO event per stream
        (like one read of a pipe), for processes some handler may watch."""
        from labkit.launch.events.process import ProcessStderr, ProcessStdout
        for child in self._children:
            for stream, kind in (('stdout', ProcessStdout), ('stderr', ProcessStderr)):
                with child.io_lock:
                    text, child.pending_io[stream] = child.pending_io[stream], ''
                if text:
                    self.emit_event(kind(text=text.encode(), **self._event_fields(child)))

    @staticmethod
    def _event_fields(child):
        return dict(action=child.action, name=child.name, cmd=child.argv,
                    cwd=None, env=None, pid=child.proc.pid)

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
        if self._shutting_down:
            return
        self._timers.append([world.system_ns() + int(period * 1e9), list(actions)])

    def save_environment(self):
        if self._saved_environ is None:
            self._saved_environ = dict(os.environ)

    def initial_environment(self):
        return self._saved_environ if self._saved_environ is not None else dict(os.environ)

    def add_params_file(self, path):
        self._params_files.append(path)
        _PARAMS_FILES.add(path)     # a launch still running when Python exits leaves none

    def start_node(self, *, package, executable, argv, name=None, output='log', cmd=None,
                   exec_name=None, action=None):
        """Start `ros2 run package executable argv...` as one launched process."""
        return self._start(f'{exec_name or executable}', cmd or [executable, *argv], output,
                           action, argv=[package, executable, *argv])

    def start_command(self, action, argv, *, label_name, cmd_text, output='log'):
        """An ExecuteProcess command line: `ros2 run ...`, another ros2 verb, or a labkit
        executable by path or name."""
        from labkit import executables
        if not argv:
            raise RuntimeError('ExecuteProcess: empty command')
        program = os.path.basename(argv[0])
        if program == 'ros2' and argv[1:2] == ['run'] and len(argv) >= 4:
            return self._start(label_name, [cmd_text], output, action, argv=argv[2:])
        if program == 'ros2':
            return self._start(label_name, [cmd_text], output, action,
                               main=_ros2_verb_main, args=['ros2', *argv[1:]])
        package = os.path.basename(os.path.dirname(argv[0]))    # <prefix>/lib/<pkg>/<exe>
        if executables.lookup(package, program) is not None:
            found = (package, program)
        else:
            found = next(((p, e) for p, e in executables.executables() if e == program), None)
        if found is None:
            raise RuntimeError("labkit can only launch `ros2 ...` commands and ROS executables, "
                               "not '{}'".format(' '.join(argv)))
        return self._start(label_name, [cmd_text], output, action,
                           argv=[*found, *argv[1:]])

    def _start(self, name, cmd, output, action, *, argv=None, main=None, args=None):
        from labkit import process
        from labkit.launch.events.process import ProcessStarted
        if self._shutting_down:
            return None
        self._count += 1
        label = f'{name}-{self._count}'
        child = _Child(label, ' '.join(cmd), output, action, list(cmd))
        self._children.append(child)
        sink = (lambda stream, text: self._child_output(child, stream, text))
        if main is not None:
            child.proc = process.start(name=label, main=main, args=args, sink=sink)
        else:
            child.proc = process.start(argv, name=label, sink=sink)
        self.log_info(f'process started with pid [{child.proc.pid}]', logger=label)
        self.emit_event(ProcessStarted(**self._event_fields(child)))
        return child.proc

    # ------------------------------------------------------------------ output
    def _print(self, text):
        self._owner._write('stdout', text)

    def _child_output(self, child, stream, text):
        if child.action is not None:
            with child.io_lock:
                child.pending_io[stream] += text
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
        from labkit.launch.events import ExecutionComplete
        from labkit.launch.events.process import ProcessExited
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
            if child.action is not None:
                self.emit_event(ProcessExited(returncode=code, **self._event_fields(child)))
                self.emit_event(ExecutionComplete(action=child.action))

    def _wait(self):
        from labkit.graph import world
        from labkit.rclpy import _wait
        timeout = None
        if self._timers:
            timeout = max(0, min(t[0] for t in self._timers) - world.system_ns())

        def something_happened():
            return bool(self._events) or any(
                (not c.reported and c.proc is not None and not c.proc.running) or
                c.pending_io['stdout'] or c.pending_io['stderr'] for c in self._children)
        _wait.wait(something_happened, timeout_ns=timeout)

    def _shutdown(self, send_sigint=False):
        """Stop every process. At Ctrl-C the terminal already sent them SIGINT; any other
        shutdown (an event, an error) has launch send it, and say so."""
        self._timers.clear()
        running = [c for c in self._children if c.proc is not None and c.proc.running]
        if send_sigint:
            for child in running:
                self.log_info(f"sending signal 'SIGINT' to process[{child.name}]",
                              logger=child.name)
        for child in running:
            child.proc.stop()
        self._report_exits()

    def _cleanup(self):
        if self._saved_environ is not None:     # what the launch set ends with it
            for name in [n for n in os.environ if n not in self._saved_environ]:
                del os.environ[name]
            os.environ.update(self._saved_environ)
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


def _ros2_verb_main(args=None):
    """A `ros2 <verb> ...` command as a launched process: its lines as it prints them."""
    from labkit.plugins import entry
    run_command = entry('ros2')      # the ros2 program, found by name as on a PATH

    def echo(stream, text):
        (sys.stdout if stream == 'stdout' else sys.stderr).write(text)
    result = run_command(list(args[1:]), echo=echo)
    if getattr(result, 'wait', None) is not None and result.returncode is None:
        try:
            result.wait()
        except KeyboardInterrupt:
            result.stop()
        return 0
    return result.returncode or 0
