"""Building one package into install/<pkg> (colcon-ros' ament_python and ament_cmake tasks).

Each builder returns a BuildResult (exit code, stdout, stderr, warnings,
cost). Nothing is compiled: ament_python packages are installed from what
their real setup.py declares, interface packages from their real
CMakeLists.txt; the .msg/.srv/.action files are parsed and checked as
rosidl would, and labkit.interfaces generates the classes when imported.

`cost` is a deterministic estimate of how long the real build would take
(seconds), used for the times colcon prints in virtual time mode.
"""
import os
import shutil

from labkit import oslayer
from labkit.ament import cmake, envscripts, setup_py
from labkit.ament.files import write_text as _write

PYTHON_DIR = os.path.join('lib', 'python3.10', 'site-packages')
RESOURCE_INDEX = os.path.join('share', 'ament_index', 'resource_index')

# CMake packages an underlay provides to find_package (besides interface packages)
KNOWN_CMAKE = {
    'ament_cmake', 'ament_cmake_python', 'ament_cmake_core', 'ament_cmake_auto',
    'ament_cmake_gtest', 'ament_cmake_pytest', 'ament_lint_auto', 'ament_lint_common',
    'rosidl_default_generators', 'rosidl_default_runtime', 'rclcpp', 'rclpy',
    'rclcpp_action', 'rclcpp_components', 'tf2', 'tf2_ros', 'tf2_geometry_msgs',
    'cv_bridge', 'image_transport', 'launch', 'launch_ros', 'turtlesim', 'OpenCV',
    'Eigen3', 'rcutils', 'rmw', 'example_interfaces',
}


class BuildResult:
    def __init__(self):
        self.returncode = 0
        self.stdout = []        # lines (shown with console_direct+)
        self.stderr = []        # lines (shown as `--- stderr: pkg`)
        self.warnings = []      # colcon's own log warnings
        self.cost = 0.0

    def fail(self, text, code=1):
        self.stderr.extend(text.rstrip('\n').split('\n'))
        self.returncode = code
        return self


class Context:
    """What a build job knows: workspace paths, mode, which packages exist where."""

    def __init__(self, pkg, build_base, install_base, symlink, is_installed):
        self.pkg = pkg
        self.build_dir = os.path.join(build_base, pkg.name)
        self.prefix = os.path.join(install_base, pkg.name)
        self.symlink = symlink
        self.is_installed = is_installed    # name -> install prefix or None


# ------------------------------------------------------------------ small file helpers

def _place(src, dst, symlink):
    """Copy a file (or symlink it with --symlink-install), replacing what was there."""
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    oslayer.remove(dst)
    if symlink:         # a copy where the OS refuses symlinks (Windows without Developer Mode)
        oslayer.symlink(os.path.abspath(src), dst)
    else:
        shutil.copy2(src, dst)


def _place_tree(src, dst, symlink):
    for root, dirs, files in os.walk(src):
        dirs[:] = [d for d in dirs if d != '__pycache__']
        for f in files:
            if f.endswith('.pyc'):
                continue
            s = os.path.join(root, f)
            _place(s, os.path.join(dst, os.path.relpath(s, src)), symlink)


def _clean(path):
    oslayer.remove(path)


def _common_install(ctx, with_manifest, with_marker, hooks=(), extra=()):
    """What every package gets: colcon-core's package list and environment hooks.

    hooks: [(stem, kind, VARIABLE, subfolder)] besides PYTHONPATH (which comes first
    when the package has a site-packages folder); extra: more files package.dsv sources.
    """
    pkg = ctx.pkg
    share = os.path.join(ctx.prefix, 'share', pkg.name)
    run_deps = sorted(pkg.deps.get('run', set()))
    _write(os.path.join(ctx.prefix, 'share', 'colcon-core', 'packages', pkg.name),
           ':'.join(run_deps))
    if os.path.isdir(os.path.join(ctx.prefix, PYTHON_DIR)):
        hooks = [('pythonpath', 'prepend-non-duplicate', 'PYTHONPATH',
                  PYTHON_DIR.replace(os.sep, '/'))] + list(hooks)
    envscripts.package_scripts(ctx.prefix, pkg.name, hooks, extra)
    if with_manifest:
        _place(os.path.join(pkg.path, 'package.xml'), os.path.join(share, 'package.xml'),
               ctx.symlink)
    if with_marker:
        _write(os.path.join(ctx.prefix, RESOURCE_INDEX, 'packages', pkg.name), '')
    _write(os.path.join(ctx.build_dir, 'colcon_build.rc'), '0\n')


# ------------------------------------------------------------------ ament_python

# What Jammy's setuptools 59.6 (python3-setuptools) prints on stderr each time colcon
# runs `setup.py install` (or `setup.py develop` for --symlink-install): harmless, but
# it makes colcon report "N packages had stderr output" on every Humble machine.
_SETUPTOOLS = '/usr/lib/python3/dist-packages/setuptools/command/'
_INSTALL_DEPRECATED = [
    _SETUPTOOLS + 'install.py:34: SetuptoolsDeprecationWarning: setup.py install is '
    'deprecated. Use build and pip and other standards-based tools.',
    '  warnings.warn(']
_EASY_INSTALL_DEPRECATED = [
    _SETUPTOOLS + 'easy_install.py:158: EasyInstallDeprecationWarning: easy_install command '
    'is deprecated. Use build and pip and other standards-based tools.',
    '  warnings.warn(']


def build_ament_python(ctx):
    res = BuildResult()
    pkg = ctx.pkg
    if not os.path.isfile(os.path.join(pkg.path, 'setup.py')):
        return res.fail(f"python3: can't open file 'setup.py': [Errno 2] No such file or "
                        f"directory", 2)
    try:
        kwargs = setup_py.run_setup(pkg.path)
    except setup_py.SetupError as e:
        return res.fail(e.text)
    cfg = setup_py.read_setup_cfg(pkg.path)
    name = str(kwargs.get('name') or pkg.name)
    version = str(kwargs.get('version') or '0.0.0')
    packages = list(kwargs.get('packages') or [])
    package_dir = dict(kwargs.get('package_dir') or {})
    py_modules = list(kwargs.get('py_modules') or [])
    data_files = list(kwargs.get('data_files') or [])
    scripts = setup_py.console_scripts(kwargs.get('entry_points'))

    os.makedirs(ctx.build_dir, exist_ok=True)
    site = os.path.join(ctx.prefix, PYTHON_DIR)
    _clean(ctx.prefix)       # a rebuild replaces the package's install space
    os.makedirs(site, exist_ok=True)
    res.stdout += (['running egg_info', 'running build', 'running build_py', 'running install',
                    'running install_lib'] if not ctx.symlink else
                   ['running develop', 'running egg_info', 'running build_ext'])

    # python packages: copied into site-packages, or reached through build/<pkg> links
    tops = set()
    for dotted in packages:
        parts = dotted.split('.')
        src = _package_source(pkg.path, parts, package_dir)
        if not os.path.isdir(src):
            return res.fail(f"error: package directory '{os.path.relpath(src, pkg.path)}' "
                            f"does not exist")
        tops.add(parts[0])
        if not ctx.symlink:
            for f in sorted(os.listdir(src)):
                if f.endswith('.py'):
                    _place(os.path.join(src, f), os.path.join(site, *parts, f), False)
    for module in py_modules:
        src = os.path.join(pkg.path, package_dir.get('', ''), module + '.py')
        if not os.path.isfile(src):
            res.stderr.append(f"file {module}.py (for module {module}) not found")
            continue
        tops.add(module)
        if not ctx.symlink:
            _place(src, os.path.join(site, module + '.py'), False)
    # egg_info passed; the install (or develop) command starts and setuptools warns
    res.stderr += (_EASY_INSTALL_DEPRECATED if ctx.symlink else []) + _INSTALL_DEPRECATED
    egg_name = name.replace('-', '_')
    if ctx.symlink:
        # `setup.py develop`: build/<pkg> mirrors the sources with links; an egg-link and
        # easy-install.pth put build/<pkg> on sys.path
        for top in sorted(tops):
            parts = [top]
            src = _package_source(pkg.path, parts, package_dir)
            if not os.path.exists(src):
                src = os.path.join(pkg.path, package_dir.get('', ''), top + '.py')
                dst = os.path.join(ctx.build_dir, top + '.py')
            else:
                dst = os.path.join(ctx.build_dir, top)
            _place(src, dst, True)
        _write(os.path.join(site, egg_name + '.egg-link'), ctx.build_dir + '\n.')
        _write(os.path.join(site, 'easy-install.pth'), ctx.build_dir + '\n')
        egg_info = os.path.join(ctx.build_dir, egg_name + '.egg-info')
    else:
        egg_info = os.path.join(site, f'{egg_name}-{version}-py3.10.egg-info')
    _write_egg_info(egg_info, name, version, tops, scripts, kwargs,
                    _sdist_sources(pkg.path, packages, package_dir, py_modules, data_files),
                    # colcon runs egg_info with --egg-base build/<pkg>
                    os.path.relpath(ctx.build_dir, pkg.path).replace(os.sep, '/'))

    # console scripts: where setup.cfg sends them ($base/lib/<pkg>), else bin/
    key = 'script_dir' if ctx.symlink else 'install_scripts'
    script_dir = (cfg.get(key) or '$base/bin').replace('$base', ctx.prefix)
    if not ctx.symlink:
        res.stdout += ['running install_data', 'running install_egg_info',
                       'running install_scripts']
    for exe, target in scripts:
        module, _, func = target.partition(':')
        _write(os.path.join(script_dir, exe), _script_text(name, version, exe, module, func),
               0o755)
        res.stdout.append(f'Installing {exe} script to {_shown(script_dir)}')
    if not ctx.symlink:
        res.stdout.append("writing list of installed files to '%s'"
                          % _shown(os.path.join(ctx.build_dir, 'install.log')))

    # data_files, as setuptools installs them (relative to the install prefix)
    installed = set()
    for entry in data_files:
        if isinstance(entry, str):
            dest, sources = '', [entry]
        else:
            dest, sources = entry[0], list(entry[1])
        for src in sources:
            full = os.path.join(pkg.path, src)
            if not os.path.isfile(full):
                return res.fail(f"error: can't copy '{src}': doesn't exist or not a "
                                "regular file")
            target = os.path.join(ctx.prefix, dest, os.path.basename(src))
            _place(full, target, ctx.symlink)
            installed.add(os.path.relpath(target, ctx.prefix).replace(os.sep, '/'))

    marker = f'share/ament_index/resource_index/packages/{pkg.name}'
    manifest = f'share/{pkg.name}/package.xml'
    for path, what in ((marker, 'a marker in the package index'),
                       (manifest, "the 'package.xml' file")):
        if path not in installed:
            res.warnings.append(
                f"WARNING:colcon.colcon_ros.task.ament_python.build:Package '{pkg.name}' "
                f"doesn't explicitly install {what} (colcon-ros currently does it "
                "implicitly but that fallback will be removed in the future)")
    hooks = [('ament_prefix_path', 'prepend-non-duplicate', 'AMENT_PREFIX_PATH', '')]
    if ctx.symlink:     # `setup.py develop` left the code in build/<pkg>
        hooks.append(('pythonpath_develop', 'prepend-non-duplicate', 'PYTHONPATH',
                      os.path.abspath(ctx.build_dir)))
    _common_install(ctx, with_manifest=manifest not in installed,
                    with_marker=marker not in installed,
                    hooks=hooks)
    res.cost = (0.62 + 0.04 * len(packages) + 0.03 * len(data_files) + 0.05 * len(scripts)
                - (0.1 if ctx.symlink else 0.0))
    return res


def _package_source(root, parts, package_dir):
    """Folder of a dotted package, honouring setup(package_dir={...})."""
    for i in range(len(parts), -1, -1):
        key = '.'.join(parts[:i])
        if key in package_dir:
            return os.path.join(root, package_dir[key], *parts[i:])
    return os.path.join(root, *parts)


def _sdist_sources(root, packages, package_dir, py_modules, data_files):
    """The files setuptools' egg_info lists in SOURCES.txt (relative to the package)."""
    found = [f for f in ('setup.cfg', 'setup.py') if os.path.isfile(os.path.join(root, f))]
    for dotted in packages:
        src = _package_source(root, dotted.split('.'), package_dir)
        if os.path.isdir(src):
            found += [os.path.relpath(os.path.join(src, f), root) for f in os.listdir(src)
                      if f.endswith('.py')]
    found += [os.path.join(package_dir.get('', ''), m + '.py').lstrip('/') for m in py_modules]
    for entry in data_files:
        found += [entry] if isinstance(entry, str) else list(entry[1])
    tests = os.path.join(root, 'test')
    if os.path.isdir(tests):
        found += ['test/' + f for f in os.listdir(tests)
                  if f.startswith('test') and f.endswith('.py')]
    return [f.replace(os.sep, '/') for f in found]


def _write_egg_info(folder, name, version, tops, scripts, kwargs, sources=(), egg_base=''):
    _write(os.path.join(folder, 'PKG-INFO'),
           f'Metadata-Version: 2.1\nName: {name}\nVersion: {version}\n'
           f'Summary: {kwargs.get("description", "UNKNOWN")}\n'
           f'Maintainer: {kwargs.get("maintainer", "UNKNOWN")}\n'
           f'License: {kwargs.get("license", "UNKNOWN")}\n')
    _write(os.path.join(folder, 'top_level.txt'), ''.join(t + '\n' for t in sorted(tops)))
    _write(os.path.join(folder, 'dependency_links.txt'), '\n')
    _write(os.path.join(folder, 'zip-safe'), '\n')
    _write(os.path.join(folder, 'entry_points.txt'),
           '[console_scripts]\n' + ''.join(f'{e} = {t}\n' for e, t in scripts) + '\n'
           if scripts else '')
    requires = [str(r) for r in kwargs.get('install_requires') or []]
    if requires:
        _write(os.path.join(folder, 'requires.txt'), ''.join(r + '\n' for r in requires))
    # SOURCES.txt: what egg_info found in the source tree, then the egg-info files
    own = set(os.listdir(folder)) | {'SOURCES.txt'}
    egg_base = f'{egg_base}/' if egg_base else ''
    _write(os.path.join(folder, 'SOURCES.txt'), ''.join(
        f + '\n' for f in sorted(set(sources) | {
            f'{egg_base}{name.replace("-", "_")}.egg-info/{f}' for f in own})))


def _script_text(name, version, exe, module, func):
    # what a console_scripts launcher does: import the function and exit with its result
    return (f"#!/usr/bin/python3\n"
            f"# console_scripts entry point {exe!r} of {name}=={version}\n"
            f"import sys\n"
            f"from {module} import {func}\n\n"
            f"if __name__ == '__main__':\n"
            f"    sys.exit({func}())\n")


# ------------------------------------------------------------------ ament_cmake

def build_ament_cmake(ctx):
    from labkit.interfaces import parser as p
    res = BuildResult()
    pkg = ctx.pkg
    lists = os.path.join(pkg.path, 'CMakeLists.txt')
    if not os.path.isfile(lists):
        return res.fail(f'CMake Error: The source directory "{_shown(pkg.path)}" does not '
                        'appear to contain CMakeLists.txt.\nSpecify --help for usage, or '
                        'press the help button on the CMake GUI.')
    with open(lists, encoding='utf-8') as f:
        text = f.read()

    def known(name):
        return name in KNOWN_CMAKE or ctx.is_installed(name) is not None \
            or _bundled_interface_package(name)
    try:
        conf = cmake.configure(text, pkg.name, known, pkg.groups)
    except cmake.CMakeError as e:
        res.stdout.append('-- Configuring incomplete, errors occurred!')
        return res.fail(e.text)
    res.stdout += ['-- Found ament_cmake: 1.3.11 (/opt/ros/humble/share/ament_cmake/cmake)',
                   '-- Configuring done', '-- Generating done',
                   f'-- Build files have been written to: {_shown(ctx.build_dir)}']

    # rosidl: every file exists, parses, and uses only types it can see
    specs = []
    for rel in conf.interfaces:
        full = os.path.join(pkg.path, rel)
        if not os.path.isfile(full):
            return res.fail(cmake.rosidl_error(
                93, f"rosidl_generate_interfaces() the passed file '{rel}' doesn't exist "
                    f"relative to the CMAKE_CURRENT_SOURCE_DIR '{_shown(pkg.path)}'",
                conf.interface_line).text)
        kind = os.path.basename(os.path.dirname(rel))
        stem, ext = os.path.splitext(os.path.basename(rel))
        with open(full, encoding='utf-8') as f:
            body = f.read()
        try:
            if ext == '.msg':
                spec = p.parse_message_string(pkg.name, stem, body)
            elif ext == '.srv':
                spec = p.parse_service_string(pkg.name, stem, body)
            elif ext == '.action':
                spec = p.parse_action_string(pkg.name, stem, body)
            else:
                return res.fail(f"Unsupported interface type '{ext}'")
        except Exception as e:      # rosidl_adapter's errors, named by the file
            return res.fail(f'Error processing {rel}: {type(e).__name__}: {e}\n'
                            'gmake[2]: *** [CMakeFiles/%s__rosidl_generator_type_adapter.dir/'
                            'build.make:70] Error 1\ngmake: *** [Makefile:146: all] Error 2'
                            % pkg.name, 2)
        specs.append((rel, kind, stem, spec))
    local = {(k, s) for _, k, s, _ in specs}
    for rel, kind, stem, spec in specs:
        problem = _unknown_type(pkg.name, spec, local, conf.interface_deps, ctx)
        if problem:
            return res.fail(
                f'Traceback (most recent call last):\n'
                f'  File "/opt/ros/humble/share/rosidl_generator_c/cmake/../../../lib/'
                f'rosidl_generator_c/rosidl_generator_c", line 8, in <module>\n'
                f'rosidl_adapter.parser.UnknownMessageType: {problem}\n'
                f'gmake[2]: *** [CMakeFiles/{pkg.name}__rosidl_generator_c.dir/build.make:'
                f'71: rosidl_generator_c/{pkg.name}/{kind}/{_snake(stem)}.h] Error 1\n'
                f'gmake: *** [Makefile:146: all] Error 2', 2)

    os.makedirs(ctx.build_dir, exist_ok=True)
    _write(os.path.join(ctx.build_dir, 'CMakeCache.txt'),
           f'CMAKE_PROJECT_NAME:STATIC={pkg.name}\nCMAKE_INSTALL_PREFIX:PATH='
           f'{ctx.prefix}\n')
    _clean(ctx.prefix)
    share = os.path.join(ctx.prefix, 'share', pkg.name)
    for rel, kind, stem, spec in specs:
        _place(os.path.join(pkg.path, rel), os.path.join(share, rel), False)
    if specs:
        _write(os.path.join(ctx.prefix, RESOURCE_INDEX, 'rosidl_interfaces', pkg.name),
               ''.join(f'{rel}\n' for rel, *_ in specs))
        res.stdout.append(f'[100%] Built target {pkg.name}')
    for kind, sources, destination in conf.installs:
        for src in sources:
            full = os.path.join(pkg.path, src)
            dest = os.path.join(ctx.prefix, destination)
            if kind == 'DIRECTORY':
                if not os.path.isdir(full):
                    return res.fail(f'CMake Error at cmake_install.cmake:41 (file):\n'
                                    f'  file INSTALL cannot find\n  "{_shown(full)}":\n'
                                    f'  No such file or directory.')
                # `install(DIRECTORY launch ...)` puts the folder itself below DESTINATION
                target = dest if src.endswith('/') else os.path.join(dest, os.path.basename(
                    src.rstrip('/')))
                _place_tree(full, target, ctx.symlink)
            else:
                if not os.path.isfile(full):
                    return res.fail(f'CMake Error at cmake_install.cmake:41 (file):\n'
                                    f'  file INSTALL cannot find\n  "{_shown(full)}":\n'
                                    f'  No such file or directory.')
                _place(full, os.path.join(dest, os.path.basename(src)), ctx.symlink)
    for module, package_dir in conf.python_packages:
        src = os.path.join(pkg.path, package_dir)
        if not os.path.isdir(src):
            return res.fail(f"error: package directory '{package_dir}' does not exist")
        _place_tree(src, os.path.join(ctx.prefix, PYTHON_DIR, module), False)
    # without ament_package() nothing registers the package in the ament index
    extra = []
    if conf.ament_package:      # ament_package() installs the environment and CMake config
        extra = envscripts.ament_cmake_files(
            ctx.prefix, pkg.name, os.path.isdir(os.path.join(ctx.prefix, PYTHON_DIR)))
    _common_install(ctx, with_manifest=conf.ament_package, with_marker=conf.ament_package,
                    hooks=[('cmake_prefix_path', 'prepend-non-duplicate', 'CMAKE_PREFIX_PATH',
                            '')], extra=extra)
    res.cost = 1.45 + 0.85 * len(specs) + 0.05 * len(conf.installs) + \
        0.2 * len(conf.targets)
    return res


def _shown(path):
    from labkit.ament import files
    return files.display(path)


def _snake(name):
    import re
    return re.sub(r'(?<!^)(?=[A-Z])', '_', name).lower()


def _bundled_interface_package(name):
    try:
        from labkit.interfaces import registry
        return name in registry.index()
    except Exception:
        return False


def _unknown_type(own, spec, local, deps, ctx):
    """rosidl's complaint for the first field whose type cannot be found, or None."""
    from labkit.interfaces import parser as p
    if isinstance(spec, p.ServiceSpec):
        label, messages = 'Service', [spec.request, spec.response]
    elif isinstance(spec, p.ActionSpec):
        label, messages = 'Action', [spec.goal, spec.result, spec.feedback]
    else:
        label, messages = 'Message', [spec]
    for msg in messages:
        for field in msg.fields:
            t = field.msg_type
            if t.pkg_name is None:
                continue    # a primitive type
            base = f'{t.pkg_name}/{t.type}'
            if t.pkg_name == own:
                ok = ('msg', t.type) in local
            else:
                ok = t.pkg_name in deps and _type_exists(t.pkg_name, t.type, ctx)
            if not ok:
                shown = f'{base}[]' if t.is_array else base
                return (f"{label} interface '{own}/{msg.msg_name}' contains an unknown "
                        f"field type: {shown} {field.name}")
    return None


def _type_exists(pkg, name, ctx):
    prefix = ctx.is_installed(pkg)
    if prefix is not None and os.path.isfile(
            os.path.join(prefix, 'share', pkg, 'msg', name + '.msg')):
        return True
    try:
        from labkit.interfaces import registry
        return registry.find_file(pkg, 'msg', name) is not None
    except Exception:
        return False
