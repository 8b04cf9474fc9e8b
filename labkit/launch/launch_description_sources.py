"""Where an included launch description comes from (a Python launch file)."""
import importlib.util
import os


class InvalidPythonLaunchFileError(Exception):
    pass


class InvalidLaunchFileError(Exception):
    pass


def load_python_launch_file_as_module(path):
    """Any file, whatever its ending, read as Python source (as launch's loader does)."""
    from importlib.machinery import SourceFileLoader
    name = os.path.basename(path).replace('.', '_')
    spec = importlib.util.spec_from_loader(name, SourceFileLoader(name, path))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def get_launch_description_from_python_launch_file(path):
    module = load_python_launch_file_as_module(path)
    if not hasattr(module, 'generate_launch_description'):
        raise InvalidPythonLaunchFileError(
            "launch file at '{}' does not contain the required function '{}'".format(
                path, 'generate_launch_description()'))
    return module.generate_launch_description()


def get_launch_description_from_any_launch_file(path):
    """launch's loaders in launch's order: a .py file as Python first, anything else
    through the XML/YAML front-ends first (labkit/launch/frontend.py)."""
    from labkit.launch import frontend
    if path.endswith('.py'):
        return get_launch_description_from_python_launch_file(path)
    try:
        return frontend.get_launch_description_from_frontend_launch_file(path)
    except Exception as exc:      # noqa: BLE001 - reported as launch reports it
        errors = [exc]
    try:                          # launch then tries the file as Python (an empty one is)
        return get_launch_description_from_python_launch_file(path)
    except Exception as exc:      # noqa: BLE001 - reported as launch reports it
        errors.append(exc)
    extension = frontend.frontend_format(path) if frontend.is_frontend_file(path) else ''
    raise InvalidLaunchFileError(_load_errors(extension, errors))


def _load_errors(extension, errors):
    """launch.InvalidLaunchFileError's text."""
    if not extension:
        return 'The launch file may have a syntax error, or its format is unknown'
    text = 'Caught {} when trying to load file of format [{}]:'.format(
        'multiple exceptions' if len(errors) > 1 else 'exception', extension)
    for error in errors:
        text += '\n - {}: {}'.format(type(error).__name__, error)
    return text


class LaunchDescriptionSource:
    def __init__(self, launch_description=None, location='<script>', method='interpreted'):
        self._launch_description = launch_description
        self._location = location
        self._method = method

    @property
    def location(self):
        return self._location

    def try_get_launch_description_without_context(self):
        return self._launch_description

    def get_launch_description(self, context):
        return self._launch_description


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    def __init__(self, launch_file_path):
        super().__init__(None, launch_file_path, 'interpreted python launch file')
        self._path = launch_file_path

    def get_launch_description(self, context):
        from labkit.launch.utilities import perform
        if self._launch_description is None:
            self._location = perform(context, self._path)
            self._launch_description = self._load(self._location)
        return self._launch_description

    _load = staticmethod(get_launch_description_from_python_launch_file)

    def try_get_launch_description_without_context(self):
        """As Humble: expand the path in a fresh LaunchContext (FindPackageShare and
        PathJoinSubstitution need no launch configuration) and load it; a path that
        needs one, or any other failure, gives None (`--show-args` leaves it out)."""
        if self._launch_description is not None:
            return self._launch_description
        from labkit.launch.launch_context import LaunchContext
        from labkit.launch.utilities import is_a_substitution, perform
        if not is_a_substitution(self._path):
            self._location = self._path if isinstance(self._path, str) else ''.join(self._path)
            self._launch_description = self._load(self._location)
            return self._launch_description
        try:
            return self._load(perform(LaunchContext(), self._path))
        except Exception:
            return None


class AnyLaunchDescriptionSource(PythonLaunchDescriptionSource):
    _load = staticmethod(get_launch_description_from_any_launch_file)


def _load_frontend(path):
    from labkit.launch import frontend
    return frontend.get_launch_description_from_frontend_launch_file(path)


class FrontendLaunchDescriptionSource(PythonLaunchDescriptionSource):
    """An XML or YAML launch file (launch_xml's and launch_yaml's sources are this one)."""

    _load = staticmethod(_load_frontend)
