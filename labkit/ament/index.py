"""The ament resource index: which packages exist and where (ament_index_python's view).

A prefix holds `share/ament_index/resource_index/<resource_type>/<name>` marker
files. Prefixes are searched in AMENT_PREFIX_PATH order (a later-sourced
workspace is prepended, so its packages win), then labkit's bundled prefix,
a read-only folder inside labkit standing for /opt/ros/humble.
"""
import os

from labkit import oslayer

RESOURCE_INDEX = os.path.join('share', 'ament_index', 'resource_index')
# Bundled packages (turtlesim, std_msgs, ...): what a Humble binary install reports.
SHOWN_INSTALL_PREFIX = '/opt/ros/humble'
BUNDLED_PREFIX = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'prefix')
_LABKIT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
_extra_bundled = []


def add_bundled_prefix(path):
    """Another read-only prefix inside labkit (a room's `prefix/` folder is found anyway)."""
    path = os.path.abspath(path)
    if path not in _extra_bundled:
        _extra_bundled.append(path)


def bundled_prefixes():
    """labkit/ament/prefix, then every other labkit/<room>/prefix, then added ones."""
    found = [BUNDLED_PREFIX]
    try:
        rooms = sorted(os.listdir(_LABKIT))
    except OSError:
        rooms = []
    for room in rooms:
        prefix = os.path.join(_LABKIT, room, 'prefix')
        if prefix != BUNDLED_PREFIX and os.path.isdir(os.path.join(prefix, RESOURCE_INDEX)):
            found.append(prefix)
    return found + [p for p in _extra_bundled if p not in found]


def bundled_prefix_of(name):
    """The bundled prefix holding a package's share folder, or None."""
    for prefix in bundled_prefixes():
        if os.path.isfile(os.path.join(prefix, RESOURCE_INDEX, 'packages', name)):
            return prefix
    return None


class PackageNotFoundError(KeyError):
    """ament_index_python's error (a KeyError, like the real one)."""


def prefixes():
    """Workspace prefixes from AMENT_PREFIX_PATH, first wins."""
    value = os.environ.get('AMENT_PREFIX_PATH', '')
    return [p for p in value.split(os.pathsep) if p]


def resources(resource_type, prefix):
    folder = os.path.join(prefix, RESOURCE_INDEX, resource_type)
    try:
        return sorted(e.name for e in os.scandir(folder)
                      if e.is_file() and not e.name.startswith('.'))
    except OSError:
        return []


def get_resources(resource_type):
    """name -> prefix of every resource of a type (first prefix wins)."""
    found = {}
    for prefix in prefixes():
        for name in resources(resource_type, prefix):
            found.setdefault(name, prefix)
    return found


def bundled_package_names():
    """Packages labkit itself provides (executables, bundled interfaces and manifests).

    Of the packages ros-humble-desktop depends on (ros2/variants, humble), labkit lists
    those whose executables it really runs: turtlesim, demo_nodes_cpp/_py and the
    minimal publisher/subscriber examples (examples_rclcpp_* and examples_rclpy_*, each
    with a package.xml in labkit/ament/prefix). The other examples_* packages of
    desktop (minimal client/service/action/timer/composition, executors) are not
    listed: `ros2 run` could not start them. colcon's override check (colcon.py) warns
    about a workspace package named like any listed one, as desktop depends on it.
    """
    names = set()
    for prefix in bundled_prefixes():
        names |= set(resources('packages', prefix))
    try:
        from labkit import executables
        from labkit.ament import source
        # labkit's own executables (built in, or registered by labkit's rooms), not the
        # ones a sourced workspace registered
        names |= {p for p, _ in executables.BUILTIN}
        names |= set(executables.packages()) - source.workspace_packages()
    except Exception:
        pass
    try:   # Python packages labkit stands in for (rclpy, launch, tf2_ros, cv_bridge, ...)
        from labkit import compat, plugins
        plugins.register_all()
        names |= compat.aliased_packages()
    except Exception:
        pass
    try:
        from labkit.interfaces import registry
        names |= {n for n, kinds in registry._scan_root(registry.BUNDLED_SHARE).items()
                  if any(kinds.values())}
    except Exception:
        pass
    return {n for n in names if not n.startswith('_')}


def package_names():
    """Workspace packages (from AMENT_PREFIX_PATH); bundled ones are listed by ros2 pkg."""
    return sorted(get_resources('packages'))


def package_prefix(name):
    """Prefix of a workspace package; LookupError for unknown or bundled ones."""
    found = get_resources('packages').get(name)
    if found is None:
        raise LookupError(name)
    return found


def get_package_prefix(package_name):
    try:
        return package_prefix(package_name)
    except LookupError:
        pass
    if package_name in bundled_package_names():
        found = bundled_prefix_of(package_name)
        if found is not None:
            return found
        from labkit.interfaces import registry
        if os.path.isdir(os.path.join(registry.BUNDLED_SHARE, package_name)):
            return os.path.dirname(registry.BUNDLED_SHARE)     # <prefix>/share/<pkg>/msg
        return BUNDLED_PREFIX
    raise PackageNotFoundError(
        "package '{}' not found, searching: {}".format(package_name, search_paths_shown()))


def search_paths_shown():
    """AMENT_PREFIX_PATH as a terminal shows it: the workspaces, then /opt/ros/humble."""
    from labkit.ament import files
    shown = [files.display(p) for p in prefixes()]
    return shown + ([SHOWN_INSTALL_PREFIX] if SHOWN_INSTALL_PREFIX not in shown else [])


def get_package_share_directory(package_name):
    return os.path.join(get_package_prefix(package_name), 'share', package_name)


def shown(text):
    """A path (or text holding paths) as a Humble machine prints it: bundled prefixes are
    /opt/ros/humble, the sandbox home is /root (labkit.ament.files)."""
    from labkit.ament import files
    from labkit.interfaces import registry
    text = str(text)
    for prefix in bundled_prefixes() + [os.path.dirname(registry.BUNDLED_SHARE)]:
        text = text.replace(prefix + os.sep, SHOWN_INSTALL_PREFIX + '/')
        if text == prefix:
            text = SHOWN_INSTALL_PREFIX
    home = files.home()
    if files._home is not None:
        text = text.replace(home + os.sep, files.SHOWN_HOME + '/')
    # '/' in the Ubuntu paths on every OS (Windows joins with '\\')
    return oslayer.slashes_after(text, (SHOWN_INSTALL_PREFIX + '/', files.SHOWN_HOME + '/'))


# a dying Python program's traceback names its files as a Humble machine would
from labkit import process as _process  # noqa: E402
_process.shown_path = shown
