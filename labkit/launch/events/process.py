"""launch.events.process: a launched process started, wrote output, or exited."""
from labkit.launch.events import Event


class RunningProcessEvent(Event):
    def __init__(self, *, action, name, cmd, cwd=None, env=None, pid):
        self.action = action
        self.execute_process_action = action
        self.name = name
        self.cmd = cmd
        self.cwd = cwd
        self.env = env
        self.pid = pid


class ProcessStarted(RunningProcessEvent):
    pass


class ProcessExited(RunningProcessEvent):
    def __init__(self, *, returncode, **kwargs):
        super().__init__(**kwargs)
        self.returncode = returncode


class ProcessIO(RunningProcessEvent):
    """`text` is bytes, as read from the pipe; `fd` 1 is stdout, 2 stderr."""

    def __init__(self, *, text, fd, **kwargs):
        super().__init__(**kwargs)
        self.text = text
        self.fd = fd


class ProcessStdout(ProcessIO):
    def __init__(self, **kwargs):
        super().__init__(fd=1, **kwargs)


class ProcessStderr(ProcessIO):
    def __init__(self, **kwargs):
        super().__init__(fd=2, **kwargs)


__all__ = ['ProcessExited', 'ProcessIO', 'ProcessStarted', 'ProcessStderr', 'ProcessStdout',
           'RunningProcessEvent']
