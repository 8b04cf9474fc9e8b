"""launch.actions: the actions a launch file declares."""
import os

from labkit.launch.action import Action
from labkit.launch.utilities import normalize_to_list_of_substitutions, perform


class DeclareLaunchArgument(Action):
    """A launch argument: `name:=value` on the command line, or its default."""

    def __init__(self, name, *, default_value=None, description=None, choices=None, **kwargs):
        super().__init__(**kwargs)
        self.__name = name
        self.__default = None if default_value is None else \
            normalize_to_list_of_substitutions(default_value)
        if choices is not None:
            choices = list(choices)
            if not choices:
                raise RuntimeError(
                    'Provided choices arg is empty. Use None to ignore the choice list.')
            if isinstance(default_value, str) and default_value not in choices:
                raise RuntimeError('Provided default_value "{}" is not in provided choices "{}".'
                                   .format(default_value, choices))
        if description is None:
            description = 'no description given' if choices is None else \
                'One of: ' + str(choices)
        elif choices is not None:
            description += ('' if description.endswith('.') else '.') + \
                ' Valid choices are: ' + str(choices)
        self.__description = description
        self.__choices = choices
        self._conditionally_included = False

    @property
    def name(self):
        return self.__name

    @property
    def default_value(self):
        return self.__default

    @property
    def description(self):
        return self.__description

    @property
    def choices(self):
        return self.__choices

    def execute(self, context):
        if self.__name not in context.launch_configurations:
            if self.__default is None:
                context.launch_service.log_error(
                    'Required launch argument "{}" (description: "{}") was not provided'
                    .format(self.__name, self.__description))
                raise RuntimeError(
                    'Required launch argument "{}" was not provided.'.format(self.__name))
            context.launch_configurations[self.__name] = perform(context, self.__default)
        if self.__choices is not None:
            value = context.launch_configurations[self.__name]
            if value not in self.__choices:
                message = ('Argument "{}" provided value "{}" is not valid. Valid options '
                           'are: {}'.format(self.__name, value, self.__choices))
                context.launch_service.log_error(message)
                raise RuntimeError(message)


class SetLaunchConfiguration(Action):
    def __init__(self, name, value, **kwargs):
        super().__init__(**kwargs)
        self.__name, self.__value = name, value

    def execute(self, context):
        context.launch_configurations[perform(context, self.__name)] = \
            perform(context, self.__value)


class PushLaunchConfigurations(Action):
    def execute(self, context):
        context._push_launch_configurations()


class PopLaunchConfigurations(Action):
    def execute(self, context):
        context._pop_launch_configurations()


class _SetLocals(Action):
    def __init__(self, values):
        super().__init__()
        self.values = values

    def execute(self, context):
        context.extend_locals(self.values)


class LogInfo(Action):
    def __init__(self, *, msg, **kwargs):
        super().__init__(**kwargs)
        self.__msg = msg

    def execute(self, context):
        context.launch_service.log_info(perform(context, self.__msg), logger='launch.user')


class GroupAction(Action):
    """Actions in a scope: launch configurations set inside do not leak out (scoped=True)."""

    def __init__(self, actions, *, scoped=True, forwarding=True, launch_configurations=None,
                 **kwargs):
        super().__init__(**kwargs)
        self.__actions = list(actions)
        self.__scoped = scoped
        self.__forwarding = forwarding
        self.__configs = dict(launch_configurations or {})

    def get_sub_entities(self):
        return list(self.__actions)

    def execute(self, context):
        entities = []
        if self.__scoped:       # launch configurations and the environment, both scoped
            entities += [PushLaunchConfigurations(), PushEnvironment()]
            if not self.__forwarding:
                entities += [ResetEnvironment(), _ClearLaunchConfigurations()]
        entities += [SetLaunchConfiguration(k, v) for k, v in self.__configs.items()]
        entities += self.__actions
        if self.__scoped:
            entities += [PopEnvironment(), PopLaunchConfigurations()]
        return entities


class _ClearLaunchConfigurations(Action):
    def execute(self, context):
        context.launch_configurations.clear()


class ResetLaunchConfigurations(Action):
    """Forget every launch configuration of this scope, but set the given ones afterwards
    (their values are read before the forgetting, so `$(var x)` still works)."""

    def __init__(self, launch_configurations=None, **kwargs):
        super().__init__(**kwargs)
        self.__configs = launch_configurations

    def execute(self, context):
        kept = {perform(context, k): perform(context, v)
                for k, v in (self.__configs or {}).items()}
        context.launch_configurations.clear()
        context.launch_configurations.update(kept)


class IncludeLaunchDescription(Action):
    """Another launch file's description, with its arguments set first."""

    def __init__(self, launch_description_source, *, launch_arguments=None, **kwargs):
        super().__init__(**kwargs)
        from labkit.launch.launch_description_sources import (AnyLaunchDescriptionSource,
                                                              LaunchDescriptionSource)
        if not isinstance(launch_description_source, LaunchDescriptionSource):
            launch_description_source = AnyLaunchDescriptionSource(launch_description_source)
        self.__source = launch_description_source
        self.__arguments = list(launch_arguments.items()) if isinstance(
            launch_arguments, dict) else list(launch_arguments or [])

    @property
    def launch_description_source(self):
        return self.__source

    @property
    def launch_arguments(self):
        return list(self.__arguments)

    def get_sub_entities(self):
        description = self.__source.try_get_launch_description_without_context()
        return [description] if description is not None else []

    def execute(self, context):
        description = self.__source.get_launch_description(context)
        location = self.__source.location
        for name, value in self.__arguments:
            context.launch_configurations[perform(context, name)] = perform(context, value)
        declared = [a.name for a in description.get_launch_arguments()]
        for arg in description.get_launch_arguments():
            if arg.default_value is None and arg.name not in context.launch_configurations:
                raise RuntimeError(
                    "Included launch description missing required argument '{}' "
                    "(description: '{}'), given: [{}]".format(
                        arg.name, arg.description,
                        ', '.join(sorted(context.launch_configurations))))
        del declared
        saved = dict(context.locals)
        return [
            _SetLocals({'current_launch_file_path': location,
                        'current_launch_file_directory': os.path.dirname(location)}),
            description,
            _SetLocals(saved),
        ]


class OpaqueFunction(Action):
    """Call a Python function at launch time; it may return more actions."""

    def __init__(self, *, function, args=None, kwargs=None, **left_over):
        super().__init__(**left_over)
        self.__function, self.__args, self.__kwargs = function, args or [], kwargs or {}

    def execute(self, context):
        return self.__function(context, *self.__args, **self.__kwargs)


class TimerAction(Action):
    """Run actions after `period` seconds (world time: simulated in virtual mode)."""

    def __init__(self, *, period, actions, cancel_on_shutdown=True, **kwargs):
        super().__init__(**kwargs)
        self.__period = period
        self.__actions = list(actions)

    def describe_conditional_sub_entities(self):
        return [('{} seconds pass'.format(self.__period), self.__actions)]

    def execute(self, context):
        period = float(perform(context, self.__period)) if not isinstance(
            self.__period, (int, float)) else float(self.__period)
        context.launch_service.add_timer(period, self.__actions)


class SetEnvironmentVariable(Action):
    """Set an environment variable for the processes launched after it (in its scope)."""

    def __init__(self, name, value, **kwargs):
        super().__init__(**kwargs)
        self.__name, self.__value = name, value

    def execute(self, context):
        env = dict(context.environment)
        env[perform(context, self.__name)] = perform(context, self.__value)
        context._set_environment(env)


class UnsetEnvironmentVariable(Action):
    def __init__(self, name, **kwargs):
        super().__init__(**kwargs)
        self.__name = name

    def execute(self, context):
        env = dict(context.environment)
        env.pop(perform(context, self.__name), None)
        context._set_environment(env)


class AppendEnvironmentVariable(Action):
    """Add a value to a path-like variable (after it, or before with prepend=True)."""

    def __init__(self, name, value, *, prepend=False, separator=os.pathsep, **kwargs):
        super().__init__(**kwargs)
        self.__name, self.__value = name, value
        self.__prepend, self.__separator = prepend, separator

    def execute(self, context):
        env = dict(context.environment)
        name, value = perform(context, self.__name), perform(context, self.__value)
        if env.get(name):
            value = value + self.__separator + env[name] if self.__prepend else \
                env[name] + self.__separator + value
        env[name] = value
        context._set_environment(env)


class PushEnvironment(Action):
    def execute(self, context):
        context._push_environment()


class PopEnvironment(Action):
    def execute(self, context):
        context._pop_environment()


class ResetEnvironment(Action):
    def execute(self, context):
        context._set_environment(dict(context.launch_service.initial_environment()))


class RegisterEventHandler(Action):
    """Start reacting to events (e.g. OnProcessStart of a node)."""

    def __init__(self, event_handler, **kwargs):
        super().__init__(**kwargs)
        self.__event_handler = event_handler

    @property
    def event_handler(self):
        return self.__event_handler

    def describe_conditional_sub_entities(self):
        entities = getattr(self.__event_handler, '_callback', None)
        if isinstance(entities, (list, tuple)):
            return [('event handler', list(entities))]
        return []

    def execute(self, context):
        context.register_event_handler(self.__event_handler)


class UnregisterEventHandler(Action):
    def __init__(self, event_handler, **kwargs):
        super().__init__(**kwargs)
        self.__event_handler = event_handler

    def execute(self, context):
        context.unregister_event_handler(self.__event_handler)


class EmitEvent(Action):
    def __init__(self, *, event, **kwargs):
        super().__init__(**kwargs)
        self.__event = event

    @property
    def event(self):
        return self.__event

    def execute(self, context):
        context.launch_service.emit_event(self.__event)


class Shutdown(EmitEvent):
    """launch.actions.Shutdown: emit launch.events.Shutdown(reason=...)."""

    def __init__(self, *, reason='reason not given', **kwargs):
        from labkit.launch.events import Shutdown as ShutdownEvent
        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)


class ExecuteProcess(Action):
    """A command launched as a process.

    labkit has no shell and no other programs: it runs `ros2 ...` command lines (a
    `ros2 run` starts the executable itself; any other verb runs as one short
    process whose output is that verb's) and labkit executables named by their path
    or name. `shell=True` joins the pieces into one command line, as a shell would.
    """

    _completes_on_exit = True

    def __init__(self, *, cmd, name=None, cwd=None, env=None, additional_env=None,
                 shell=False, sigterm_timeout=None, sigkill_timeout=None, emulate_tty=False,
                 prefix=None, output='log', output_format='[{this.process_description.name}] '
                 '{line}', log_cmd=False, on_exit=None, respawn=False, respawn_delay=0.0,
                 **kwargs):
        super().__init__(**kwargs)
        self.__cmd = [normalize_to_list_of_substitutions(c) for c in cmd]
        self.__name = name
        self.__shell = shell
        self.__output = output
        self.__additional_env = list((additional_env or {}).items())
        self.__on_exit = on_exit

    @property
    def cmd(self):
        return self.__cmd

    @property
    def name(self):
        return self.__name

    @property
    def shell(self):
        return self.__shell

    @property
    def output(self):
        return self.__output

    def execute(self, context):
        from labkit import oslayer
        cmd = [perform(context, c) for c in self.__cmd]
        if self.__name is not None:
            name = perform(context, self.__name)
        else:
            name = os.path.basename(cmd[0]) if cmd else ''
        argv = oslayer.split_args(' '.join(cmd)) if self.__shell else list(cmd)
        service = context.launch_service
        if self.__on_exit is not None:
            from labkit.launch.event_handlers import OnProcessExit
            context.register_event_handler(OnProcessExit(target_action=self,
                                                         on_exit=self.__on_exit))
        service.start_command(self, argv, label_name=name, cmd_text=' '.join(cmd),
                              output=perform(context, self.__output))


