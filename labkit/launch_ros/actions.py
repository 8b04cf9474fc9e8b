"""launch_ros.actions.Node: a ROS node (a `ros2 run` executable) started by launch."""
import os
import posixpath
import tempfile

import yaml

from labkit.launch.action import Action
from labkit.launch.utilities import is_a_substitution, normalize_to_list_of_substitutions, \
    perform

__all__ = ['Node', 'PushRosNamespace', 'SetParameter', 'SetRemap']


def executable_path(package, executable):
    """Where ros2run would find it: <prefix>/lib/<package>/<executable> (as printed)."""
    from labkit import executables
    from labkit.ament import files, index
    try:
        prefix = files.display(index.package_prefix(package))
    except LookupError:
        if package not in index.bundled_package_names():
            raise index.PackageNotFoundError(
                "package '{}' not found, searching: {}".format(
                    package, index.search_paths_shown()))
        prefix = index.SHOWN_INSTALL_PREFIX
    # a printed path: /opt/ros/humble/... and /root/... with '/' on every OS; a real
    # Windows path (a workspace outside the book's sandbox) with its own separator
    join = posixpath.join if prefix.startswith('/') else os.path.join
    libexec = join(prefix, 'lib', package)
    if executables.lookup(package, executable) is None:
        raise RuntimeError(
            "executable '{}' not found on the libexec directory '{}' ".format(
                executable, libexec))
    return join(libexec, executable)


class Node(Action):
    _completes_on_exit = True
    def __init__(self, *, executable, package=None, name=None, namespace=None, exec_name=None,
                 parameters=None, remappings=None, ros_arguments=None, arguments=None,
                 output='log', emulate_tty=False, respawn=False, additional_env=None,
                 node_executable=None, node_name=None, **kwargs):
        super().__init__(condition=kwargs.pop('condition', None))
        self.__package = package
        self.__executable = executable if node_executable is None else node_executable
        self.__name = name if node_name is None else node_name
        self.__namespace = namespace
        self.__exec_name = exec_name
        self.__parameters = list(parameters or [])
        self.__remappings = list(remappings or [])
        self.__ros_arguments = list(ros_arguments or [])
        self.__arguments = list(arguments or [])
        self.__output = output
        self.emulate_tty = emulate_tty

    @property
    def node_package(self):
        return self.__package

    @property
    def node_executable(self):
        return self.__executable

    @property
    def node_name(self):
        return self.__name

    def execute(self, context):
        service = context.launch_service
        package = perform(context, self.__package)
        executable = perform(context, self.__executable)
        path = executable_path(package, executable)
        argv = [perform(context, a) for a in self.__arguments]
        ros_args = [perform(context, a) for a in self.__ros_arguments]
        if self.__name is not None:
            ros_args += ['-r', '__node:=' + perform(context, self.__name)]
        ns = _full_namespace(context, self.__namespace)
        if ns is not None:
            ros_args += ['-r', '__ns:=' + ns]
        from labkit.launch_ros.parameter_descriptions import ParameterFile
        for entry in self.__parameters:
            if isinstance(entry, ParameterFile):
                entry = entry.evaluate(context)
            if isinstance(entry, dict):
                ros_args += ['--params-file', self._params_file(context, entry, service)]
            else:
                path_ = perform(context, entry)
                if not os.path.isfile(path_):
                    raise RuntimeError(
                        "Parameter file path is not a file: {}".format(path_))
                ros_args += ['--params-file', path_]
        for name, value in context.launch_configurations.get('ros_global_params', []):
            ros_args += ['-p', '{}:={}'.format(name, value)]
        remaps = list(context.launch_configurations.get('ros_remaps', [])) + \
            [(perform(context, s), perform(context, d)) for s, d in self.__remappings]
        for src, dst in remaps:
            ros_args += ['-r', '{}:={}'.format(perform(context, src), perform(context, dst))]
        full = argv + (['--ros-args'] + ros_args if ros_args else [])
        exec_name = perform(context, self.__exec_name) if self.__exec_name else None
        service.start_node(package=package, executable=executable, argv=full,
                           output=perform(context, self.__output), cmd=[path, *full],
                           exec_name=exec_name, action=self)

    @staticmethod
    def _params_file(context, params, service):
        """A dict of parameters -> a temporary params file (`/**: ros__parameters:`)."""
        values = {}

        def flatten(prefix, value):
            if isinstance(value, dict):
                for k, v in value.items():
                    flatten(f'{prefix}{perform(context, k)}.', v)
            else:
                values[prefix[:-1]] = _evaluate(context, value)
        flatten('', params)
        fd, path = tempfile.mkstemp(prefix='launch_params_')
        with os.fdopen(fd, 'w', encoding='utf-8') as f:
            yaml.safe_dump({'/**': {'ros__parameters': values}}, f, default_flow_style=False)
        service.add_params_file(path)
        return path


def _full_namespace(context, namespace):
    """The node's namespace under a PushRosNamespace (an absolute one stays as it is)."""
    pushed = context.launch_configurations.get('ros_namespace')
    ns = None if namespace is None else perform(context, namespace)
    if ns is not None and ns.startswith('/'):
        return ns
    if pushed is None:
        return None if ns is None else '/' + ns
    if not ns:
        return pushed
    return pushed.rstrip('/') + '/' + ns


class PushRosNamespace(Action):
    """Put the nodes after it (in its GroupAction's scope) under a namespace."""

    def __init__(self, namespace, **kwargs):
        super().__init__(**kwargs)
        self.__namespace = namespace

    @property
    def namespace(self):
        return self.__namespace

    def execute(self, context):
        ns = perform(context, self.__namespace)
        if not ns.startswith('/'):
            pushed = context.launch_configurations.get('ros_namespace', '')
            ns = pushed.rstrip('/') + '/' + ns
        context.launch_configurations['ros_namespace'] = ns.rstrip('/') or '/'


class SetRemap(Action):
    """A remapping for every node after it in the scope."""

    def __init__(self, src, dst, **kwargs):
        super().__init__(**kwargs)
        self.__src, self.__dst = src, dst

    def execute(self, context):
        remaps = list(context.launch_configurations.get('ros_remaps', []))
        remaps.append((perform(context, self.__src), perform(context, self.__dst)))
        context.launch_configurations['ros_remaps'] = remaps


class SetParameter(Action):
    """A parameter set on every node after it in the scope."""

    def __init__(self, name, value, **kwargs):
        super().__init__(**kwargs)
        self.__name, self.__value = name, value

    def execute(self, context):
        params = list(context.launch_configurations.get('ros_global_params', []))
        params.append((perform(context, self.__name), perform(context, self.__value)))
        context.launch_configurations['ros_global_params'] = params


def _evaluate(context, value):
    """A substitution's text is read as YAML (so '3' is an int), like launch_ros does."""
    from labkit.launch_ros.parameter_descriptions import ParameterValue
    if isinstance(value, ParameterValue):
        return value.evaluate(context)
    if is_a_substitution(value):
        text = perform(context, value)
        try:
            parsed = yaml.safe_load(text)
        except yaml.YAMLError:
            return text
        return parsed if isinstance(parsed, (bool, int, float, str, list)) else text
    if isinstance(value, (list, tuple)):
        return [_evaluate(context, v) for v in value]
    return value


del normalize_to_list_of_substitutions
