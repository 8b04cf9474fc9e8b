"""launch.event_handlers: run actions when an event happens (process start, output, exit...).

A handler's entities are either a list of actions or a callable that gets the
event (and the context, except OnProcessIO's callbacks) and returns actions.
"""
from labkit.launch.events import ExecutionComplete, Shutdown
from labkit.launch.events.process import ProcessExited, ProcessIO, ProcessStarted


class EventHandler:
    def __init__(self, *, matcher, entities=None, handle_once=False):
        self.matcher = matcher
        self.entities = entities
        self.handle_once = handle_once

    def matches(self, event):
        return self.matcher(event)

    def handle(self, event, context):
        """The entities to visit; `event` is put in the context's locals first."""
        context.extend_locals({'event': event})
        if self.handle_once:
            context.unregister_event_handler(self)
        return _as_list(self.entities)


def _as_list(entities):
    if entities is None:
        return []
    if isinstance(entities, (list, tuple)):
        return list(entities)
    return [entities]


class _TargetedHandler(EventHandler):
    """Matches events of one type, optionally only those of one action."""
    event_type = None

    def __init__(self, *, target_action=None, callback=None, pass_context=True, **kwargs):
        self.target_action = target_action
        self._callback = callback
        self._pass_context = pass_context
        super().__init__(matcher=self._match, entities=None, **kwargs)

    def _match(self, event):
        if not isinstance(event, self.event_type):
            return False
        if self.target_action is None:
            return True
        if callable(self.target_action) and not hasattr(self.target_action, 'visit'):
            return bool(self.target_action(event.action))
        return event.action is self.target_action

    def handle(self, event, context):
        super().handle(event, context)
        if callable(self._callback):
            result = self._callback(event, context) if self._pass_context else \
                self._callback(event)
            return _as_list(result)
        return _as_list(self._callback)


class OnProcessStart(_TargetedHandler):
    event_type = ProcessStarted

    def __init__(self, *, target_action=None, on_start, **kwargs):
        super().__init__(target_action=target_action, callback=on_start, **kwargs)


class OnProcessExit(_TargetedHandler):
    event_type = ProcessExited

    def __init__(self, *, target_action=None, on_exit, **kwargs):
        super().__init__(target_action=target_action, callback=on_exit, **kwargs)


class OnExecutionComplete(_TargetedHandler):
    event_type = ExecutionComplete

    def __init__(self, *, target_action=None, on_completion, **kwargs):
        super().__init__(target_action=target_action, callback=on_completion, **kwargs)


class OnProcessIO(_TargetedHandler):
    """on_stdin/on_stdout/on_stderr: callables taking the ProcessIO event only."""
    event_type = ProcessIO

    def __init__(self, *, target_action=None, on_stdin=None, on_stdout=None, on_stderr=None,
                 **kwargs):
        self._by_fd = {0: on_stdin, 1: on_stdout, 2: on_stderr}
        super().__init__(target_action=target_action, callback=None, pass_context=False,
                         **kwargs)

    def _match(self, event):
        return super()._match(event) and self._by_fd.get(event.fd) is not None

    def handle(self, event, context):
        EventHandler.handle(self, event, context)
        return _as_list(self._by_fd[event.fd](event))


class OnShutdown(_TargetedHandler):
    event_type = Shutdown

    def __init__(self, *, on_shutdown, **kwargs):
        super().__init__(callback=on_shutdown, **kwargs)

    def _match(self, event):
        return isinstance(event, Shutdown)


__all__ = ['EventHandler', 'OnExecutionComplete', 'OnProcessExit', 'OnProcessIO',
           'OnProcessStart', 'OnShutdown']
