"""LaunchContext: launch configurations (the values of launch arguments) and scopes."""


class LaunchContext:
    def __init__(self, argv=None, noninteractive=True):
        self.argv = list(argv or [])
        self.noninteractive = noninteractive
        self.launch_configurations = {}
        self.locals = {}                # e.g. current_launch_file_directory
        self._stack = []
        self.launch_service = None      # the runner that starts processes
        self._event_handlers = []       # newest first, as launch keeps them

    def register_event_handler(self, event_handler):
        self._event_handlers.insert(0, event_handler)

    def unregister_event_handler(self, event_handler):
        if event_handler in self._event_handlers:
            self._event_handlers.remove(event_handler)

    def would_handle_event(self, event):
        return any(handler.matches(event) for handler in self._event_handlers)

    def emit_event_sync(self, event):
        self.launch_service.emit_event(event)

    def emit_event(self, event):
        self.launch_service.emit_event(event)

    def _push_launch_configurations(self):
        self._stack.append((dict(self.launch_configurations), dict(self.locals)))

    def _pop_launch_configurations(self):
        self.launch_configurations, self.locals = self._stack.pop()

    def extend_locals(self, values):
        self.locals.update(values)

    def perform_substitution(self, substitution):
        return substitution.perform(self)
