"""launch.events: what happens while a launch runs (event handlers react to these)."""
class Event:
    name = 'launch.events.Event'


class Shutdown(Event):
    """Ask the launch to end: OnShutdown handlers run, then every process is stopped."""
    name = 'launch.events.Shutdown'

    def __init__(self, *, reason='reason not given', due_to_sigint=False):
        self.reason = reason
        self.due_to_sigint = due_to_sigint


class ExecutionComplete(Event):
    """An action finished (for a process: when it exited)."""
    name = 'launch.events.ExecutionComplete'

    def __init__(self, *, action):
        self.action = action


class TimerEvent(Event):
    name = 'launch.events.TimerEvent'

    def __init__(self, *, timer_action):
        self.timer_action = timer_action


class IncludeLaunchDescription(Event):
    name = 'launch.events.IncludeLaunchDescription'

    def __init__(self, launch_description):
        self.launch_description = launch_description


from labkit.launch.events import process  # noqa: E402,F401  (after Event)

__all__ = ['Event', 'ExecutionComplete', 'IncludeLaunchDescription', 'Shutdown',
           'TimerEvent', 'process']
