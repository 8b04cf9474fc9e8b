"""LaunchContext: launch configurations (the values of launch arguments), the environment
launched processes get, and their scopes."""
import os


class LaunchContext:
    def __init__(self, argv=None, noninteractive=True):
        self.argv = list(argv or [])
        self.noninteractive = noninteractive
        self.launch_configurations = {}
        self.locals = {}                # e.g. current_launch_file_directory
        self._stack = []
        self.environment = dict(os.environ)    # what SetEnvironmentVariable changes
        self._environment_stack = []
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

    def _push_environment(self):
        self._environment_stack.append(dict(self.environment))

    def _pop_environment(self):
        self._set_environment(self._environment_stack.pop())

    def _set_environment(self, values):
        """Also os.environ: launched nodes are threads of this Python, reading os.environ
        (the service puts os.environ back when the launch ends)."""
        if self.launch_service is not None:
            self.launch_service.save_environment()
        self.environment = dict(values)
        for name in [n for n in os.environ if n not in values]:
            del os.environ[name]
        os.environ.update(values)

    def extend_locals(self, values):
        self.locals.update(values)

    def perform_substitution(self, substitution):
        return substitution.perform(self)
