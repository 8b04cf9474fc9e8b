"""launch.substitutions: the text pieces a launch file computes when it runs."""
import os

from labkit.launch.substitution import Substitution, SubstitutionFailure  # noqa: F401
from labkit.launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class TextSubstitution(Substitution):
    def __init__(self, *, text):
        self.text = text

    def describe(self):
        return "'{}'".format(self.text)

    def perform(self, context):
        return self.text


class LaunchConfiguration(Substitution):
    """The value of a launch argument / configuration (`LaunchConfiguration('camera')`)."""

    def __init__(self, variable_name, *, default=None):
        self.variable_name = normalize_to_list_of_substitutions(variable_name)
        self.default = None if default is None else normalize_to_list_of_substitutions(
            default if not isinstance(default, (list, tuple)) or not default or
            isinstance(default[0], (str, Substitution)) else [str(default)])

    def describe(self):
        return 'LaunchConfig({})'.format(' + '.join(s.describe() for s in self.variable_name))

    def perform(self, context):
        name = perform_substitutions(context, self.variable_name)
        if name in context.launch_configurations:
            return context.launch_configurations[name]
        if self.default is None:
            raise SubstitutionFailure("launch configuration '{}' does not exist".format(name))
        return perform_substitutions(context, self.default)


class EnvironmentVariable(Substitution):
    def __init__(self, name, *, default_value=None):
        self.name = normalize_to_list_of_substitutions(name)
        self.default_value = None if default_value is None else \
            normalize_to_list_of_substitutions(default_value)

    def describe(self):
        return 'EnvVar({})'.format(' + '.join(s.describe() for s in self.name))

    def perform(self, context):
        name = perform_substitutions(context, self.name)
        value = getattr(context, 'environment', os.environ).get(name)
        if value is None:
            if self.default_value is None:
                raise SubstitutionFailure(
                    "environment variable '{}' does not exist".format(name))
            return perform_substitutions(context, self.default_value)
        return value


class PathJoinSubstitution(Substitution):
    def __init__(self, substitutions):
        self.substitutions = [normalize_to_list_of_substitutions(s) for s in substitutions]

    def describe(self):
        return "PathJoin('{}')".format(' + '.join(
            s.describe() for part in self.substitutions for s in part))

    def perform(self, context):
        return os.path.join(*[perform_substitutions(context, s) for s in self.substitutions])


class PythonExpression(Substitution):
    def __init__(self, expression):
        self.expression = normalize_to_list_of_substitutions(expression)

    def describe(self):
        return 'PythonExpr({})'.format(' + '.join(s.describe() for s in self.expression))

    def perform(self, context):
        import math
        return str(eval(perform_substitutions(context, self.expression), math.__dict__.copy()))


class ThisLaunchFileDir(Substitution):
    def describe(self):
        return 'ThisLaunchFileDir()'

    def perform(self, context):
        if 'current_launch_file_directory' not in context.locals:
            raise SubstitutionFailure(
                'ThisLaunchFileDir used outside of a launch file (in a script)')
        return context.locals['current_launch_file_directory']


class ThisLaunchFile(Substitution):
    def describe(self):
        return 'ThisLaunchFile()'

    def perform(self, context):
        if 'current_launch_file_path' not in context.locals:
            raise SubstitutionFailure('ThisLaunchFile used outside of a launch file (in a script)')
        return context.locals['current_launch_file_path']


class AndSubstitution(Substitution):
    def __init__(self, left, right):
        self.left = normalize_to_list_of_substitutions(left)
        self.right = normalize_to_list_of_substitutions(right)

    def perform(self, context):
        from labkit.launch.conditions import evaluate_condition_expression
        return str(evaluate_condition_expression(context, self.left) and
                   evaluate_condition_expression(context, self.right)).lower()


class OrSubstitution(AndSubstitution):
    """`$(or a b)` / OrSubstitution(a, b): 'true' when either side is (Humble has it too)."""

    def perform(self, context):
        from labkit.launch.conditions import evaluate_condition_expression
        return str(evaluate_condition_expression(context, self.left) or
                   evaluate_condition_expression(context, self.right)).lower()


class NotSubstitution(Substitution):
    def __init__(self, value):
        self.value = normalize_to_list_of_substitutions(value)

    def perform(self, context):
        from labkit.launch.conditions import evaluate_condition_expression
        return str(not evaluate_condition_expression(context, self.value)).lower()


class Command(Substitution):
    """The output of a command (`Command(['xacro ', LaunchConfiguration('model')])`).

    labkit has no shell: the command's first word must be a labkit executable
    (e.g. `xacro`), whose main() runs here with its output captured.
    """

    def __init__(self, command, *, on_stderr='fail'):
        self.command = normalize_to_list_of_substitutions(command)
        self.on_stderr = normalize_to_list_of_substitutions(on_stderr)

    def describe(self):
        return 'Command({})'.format(' + '.join(s.describe() for s in self.command))

    def perform(self, context):
        from labkit import oslayer
        mode = perform_substitutions(context, self.on_stderr)
        if mode not in _ON_STDERR:
            raise SubstitutionFailure('expected \'on_stderr\' to be one of: ' + ', '.join(
                f"'{m}'" for m in _ON_STDERR[:-1]) + f" or '{_ON_STDERR[-1]}'")
        on_stderr = mode
        command_str = perform_substitutions(context, self.command)
        argv = oslayer.split_args(command_str)
        code, out, err = _run_labkit_command(argv)
        if on_stderr == 'capture':
            out, err = out + err, ''
        if code != 0:
            message = f'executed command failed. Command: {command_str}'
            if err:
                message += f'\nCaptured stderr output: {err}'
            raise SubstitutionFailure(message)
        if err:
            message = (f'executed command showed stderr output. Command: {command_str}\n'
                       f'Captured stderr output:\n{err}')
            if on_stderr == 'fail':
                raise SubstitutionFailure(message)
            if on_stderr == 'warn':
                context.launch_service.log_warning(message)
        return out


_ON_STDERR = ('fail', 'ignore', 'warn', 'capture')


def _run_labkit_command(argv):
    """(returncode, stdout, stderr) of a labkit executable named like the command."""
    import contextlib
    import io
    from labkit import executables
    if not argv:
        raise SubstitutionFailure('file not found: empty command')
    name = os.path.basename(argv[0])
    target = next((executables.lookup(p, e) for p, e in executables.executables()
                   if e == name), None)
    if target is None:
        raise SubstitutionFailure(
            f"file not found: [Errno 2] No such file or directory: '{argv[0]}'")
    main = executables.resolve(target)
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main([argv[0], *argv[1:]])
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    return code or 0, out.getvalue(), err.getvalue()


class LocalSubstitution(Substitution):
    """A value from the context's locals, e.g. `LocalSubstitution('event.reason')` in a handler."""

    def __init__(self, expression, description=None):
        self.expression = expression
        self.description = description

    def describe(self):
        return "LocalVar('{}')".format(self.description or self.expression)

    def perform(self, context):
        try:
            return str(eval(self.expression, {}, dict(context.locals)))
        except (NameError, AttributeError) as e:
            raise SubstitutionFailure(
                "Expression '{}' not found in context locals: {}".format(self.expression, e))


class FindExecutable(Substitution):
    """The path of a program on PATH; labkit knows `ros2` and its executables by name."""

    def __init__(self, *, name):
        self.name = normalize_to_list_of_substitutions(name)

    def describe(self):
        return 'FindExec({})'.format(' + '.join(s.describe() for s in self.name))

    def perform(self, context):
        from labkit import executables
        name = perform_substitutions(context, self.name)
        if name == 'ros2':
            return '/opt/ros/humble/bin/ros2'
        for package, executable in executables.executables():
            if executable == name:
                return executables.path_of(package, executable)
        raise SubstitutionFailure("executable '{}' not found on the PATH".format(name))


class AnonName(Substitution):
    def __init__(self, name):
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context):
        import random
        key = 'anon' + perform_substitutions(context, self.name)
        if key not in context.locals:
            context.locals[key] = '{}_{}'.format(perform_substitutions(context, self.name),
                                                 random.Random(key).randint(0, 2 ** 31))
        return context.locals[key]
