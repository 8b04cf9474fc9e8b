"""`source install/setup.bash`: make a built workspace's packages visible in this process.

What the real script does to a shell (AMENT_PREFIX_PATH, PYTHONPATH,
COLCON_PREFIX_PATH) is done to os.environ, and what those variables mean to
ROS tools is done to labkit: sys.path gets the packages' site-packages (and
the .pth entries of --symlink-install builds), labkit.interfaces gets each
package's share/ (add_share_path), `ros2 run` gets the console_scripts.
Sourcing again (after a rebuild) forgets the workspace's imported modules, so
the next run uses the new code. A later-sourced workspace overlays earlier ones.
"""
import importlib
import os
import sys

from labkit.ament import build, files

UNDERLAY_SCRIPTS = ('/opt/ros/humble/setup.bash', '/opt/ros/humble/setup.sh',
                    '/opt/ros/humble/setup.zsh', '/opt/ros/humble/local_setup.bash')

_sourced = []           # install folders, in the order sourced
_workspace_packages = set()     # packages whose executables a workspace registered


class SourceError(Exception):
    pass


def install_dir_of(path):
    """install/setup.bash, install/local_setup.sh or install/ -> the install folder."""
    real = files.expand(os.fspath(path))
    if os.path.isdir(real):
        return os.path.abspath(real)
    if not os.path.exists(real):
        raise SourceError(f'bash: {path}: No such file or directory')
    return os.path.dirname(os.path.abspath(real))


def packages_in(install_dir):
    """Package names of an isolated install folder, dependencies first."""
    index = os.path.join('share', 'colcon-core', 'packages')
    deps = {}
    for entry in sorted(os.listdir(install_dir)):
        marker = os.path.join(install_dir, entry, index, entry)
        if os.path.isfile(marker):
            with open(marker, encoding='utf-8') as f:
                deps[entry] = {d for d in f.read().strip().split(':') if d}
    ordered, left = [], dict(deps)
    while left:
        ready = sorted(n for n, d in left.items() if not (d & set(left) - {n}))
        if not ready:
            ready = sorted(left)    # a cycle cannot be built; keep going alphabetically
        for n in ready:
            ordered.append(n)
            left.pop(n)
    return ordered


def source(path):
    """Source a workspace's setup script; returns the package names it made visible."""
    if os.fspath(path) in UNDERLAY_SCRIPTS:
        return []       # the bundled ROS is always there
    install_dir = install_dir_of(path)
    names = packages_in(install_dir)
    tops = set()
    for name in names:
        prefix = os.path.join(install_dir, name)
        _prepend_env('AMENT_PREFIX_PATH', prefix)
        site = os.path.join(prefix, build.PYTHON_DIR)
        if os.path.isdir(site):
            _prepend_env('PYTHONPATH', site)
            for entry in _python_paths(site):
                if entry in sys.path:
                    sys.path.remove(entry)
                sys.path.insert(0, entry)
            tops |= _top_levels(site)
        if _has_interfaces(prefix, name):
            from labkit import interfaces
            interfaces.add_share_path(os.path.join(prefix, 'share'))
        _register_executables(name, prefix, site)
    _prepend_env('COLCON_PREFIX_PATH', install_dir)
    _forget_modules(tops, install_dir)
    if install_dir in _sourced:
        _sourced.remove(install_dir)
    _sourced.append(install_dir)
    return names


def run(path):
    """labkit.source(path) / %source: like the shell, an error line and exit code 1."""
    try:
        source(path)
    except SourceError as e:
        print(e, file=sys.stderr)
        return 1
    return 0


def workspace_packages():
    return set(_workspace_packages)


def sourced():
    return list(_sourced)


def _prepend_env(var, value):
    parts = [p for p in os.environ.get(var, '').split(os.pathsep) if p and p != value]
    os.environ[var] = os.pathsep.join([value] + parts)


def _python_paths(site):
    """site-packages itself, then what its .pth files add (symlink installs), first wins."""
    paths = [site]
    try:
        names = sorted(os.listdir(site))
    except OSError:
        return paths
    for fname in names:
        if fname.endswith('.pth'):
            with open(os.path.join(site, fname), encoding='utf-8') as f:
                for line in f:
                    line = line.strip()
                    if line and not line.startswith(('#', 'import ')):
                        paths.append(os.path.join(site, line))
    return list(reversed(paths))        # inserted at the front one by one


def _egg_infos(site):
    """Folders holding entry_points.txt: site-packages' egg-info, or an egg-link's."""
    found = []
    try:
        names = sorted(os.listdir(site))
    except OSError:
        return found
    for fname in names:
        full = os.path.join(site, fname)
        if fname.endswith('.egg-info') and os.path.isdir(full):
            found.append(full)
        elif fname.endswith('.egg-link'):
            with open(full, encoding='utf-8') as f:
                target = f.readline().strip()
            egg = os.path.join(target, fname[:-len('.egg-link')] + '.egg-info')
            if os.path.isdir(egg):
                found.append(egg)
    return found


def _top_levels(site):
    tops = set()
    for egg in _egg_infos(site):
        try:
            with open(os.path.join(egg, 'top_level.txt'), encoding='utf-8') as f:
                tops |= {line.strip() for line in f if line.strip()}
        except OSError:
            pass
    return tops


def _entry_points(egg):
    scripts, section = [], None
    try:
        with open(os.path.join(egg, 'entry_points.txt'), encoding='utf-8') as f:
            lines = f.read().splitlines()
    except OSError:
        return scripts
    for line in lines:
        line = line.strip()
        if line.startswith('['):
            section = line.strip('[]')
        elif '=' in line and section == 'console_scripts':
            name, _, target = line.partition('=')
            scripts.append((name.strip(), target.strip()))
    return scripts


def _has_interfaces(prefix, name):
    share = os.path.join(prefix, 'share', name)
    return any(os.path.isdir(os.path.join(share, k)) for k in ('msg', 'srv', 'action'))


def _register_executables(name, prefix, site):
    """`ros2 run <pkg> <exe>` finds what is in install/<pkg>/lib/<pkg>/ (like ros2run)."""
    from labkit import executables
    executables.overlay_package(name)
    _workspace_packages.add(name)
    libexec = os.path.join(prefix, 'lib', name)
    registered = set()
    for egg in _egg_infos(site):
        for exe, target in _entry_points(egg):
            if os.path.isfile(os.path.join(libexec, exe)):
                executables.register(name, exe, launcher_target(name, exe, target),
                                     path=_shown(os.path.join(libexec, exe)))
                registered.add(exe)
    # other executables there (install(PROGRAMS ...), data_files): Python scripts run as
    # __main__; anything else (a compiled program) cannot run in labkit
    try:
        entries = sorted(os.listdir(libexec))
    except OSError:
        entries = []
    for exe in entries:
        path = os.path.join(libexec, exe)
        if exe in registered or not os.path.isfile(path) or not os.access(path, os.X_OK):
            continue
        if _is_python_script(path):
            executables.register(name, exe, launcher_target(name, exe, None, script=path),
                                 path=_shown(path))


def _shown(path):
    from labkit.ament import index
    return index.shown(path)


def _is_python_script(path):
    try:
        with open(path, 'rb') as f:
            first = f.readline(200)
    except OSError:
        return False
    return first.startswith(b'#!') and b'python' in first or path.endswith('.py')


# ------------------------------------------------------------------ console_scripts launchers

_LAUNCHERS = 'labkit.ament._launchers'


def launcher_target(package, exe, target, script=None):
    """A "module:function" for executables.register that imports `target` when run.

    The import happens inside the started process, so a console_scripts entry
    pointing at a missing module fails at `ros2 run` time with Python's
    traceback, like a real console script does.
    """
    module = sys.modules.get(_LAUNCHERS)
    if module is None:
        import types
        module = types.ModuleType(_LAUNCHERS)
        sys.modules[_LAUNCHERS] = module
    func_name = f'{package}__{exe}'.replace('-', '_').replace('.', '_')

    def main(args=None):
        if script is not None:
            import runpy
            runpy.run_path(script, run_name='__main__')
            return 0
        mod_name, _, attr = target.partition(':')
        func = importlib.import_module(mod_name)
        for part in attr.split('.') if attr else ():
            func = getattr(func, part)
        return func()       # console scripts call main() without arguments
    main.__name__ = func_name
    setattr(module, func_name, main)
    return f'{_LAUNCHERS}:{func_name}'


def _forget_modules(tops, install_dir):
    """Drop the workspace's modules from sys.modules: the next import reads the new code.

    Only modules of this workspace's python packages, or loaded from its install/ or
    build/ (symlink installs) folders; never labkit's own.
    """
    roots = [install_dir + os.sep,
             os.path.join(os.path.dirname(install_dir), 'build') + os.sep]
    for key in list(sys.modules):
        top = key.split('.')[0]
        if top == 'labkit':
            continue
        path = getattr(sys.modules.get(key), '__file__', None) or ''
        if top in tops or (path and os.path.abspath(path).startswith(tuple(roots))):
            del sys.modules[key]
    importlib.invalidate_caches()
