"""Run a package's real setup.py and capture what its `setup(...)` call declares.

colcon's ament_python build runs `python3 setup.py ...`; setuptools reads the
arguments (packages, data_files, entry_points) and installs accordingly. Here
the file runs in its own folder with a stand-in `setuptools` module whose
`setup()` only records its keyword arguments; `find_packages` works like
setuptools' (folders with an __init__.py). setup.cfg is read for the script
folders (`[develop] script_dir`, `[install] install_scripts`).
"""
import configparser
import fnmatch
import os
import sys
import threading
import traceback
import types

_lock = threading.Lock()


class SetupError(Exception):
    """setup.py failed: `text` is what python printed (a traceback)."""

    def __init__(self, text):
        super().__init__(text)
        self.text = text


def find_packages(where='.', exclude=(), include=('*',)):
    """setuptools.find_packages: dotted names of folders holding an __init__.py."""
    found = []
    for root, dirs, files in os.walk(where):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.') and d != '__pycache__')
        if root == where:
            continue
        rel = os.path.relpath(root, where)
        if '__init__.py' not in files:
            dirs[:] = []    # like setuptools: no package, so none below it either
            continue
        name = rel.replace(os.sep, '.')
        if any(fnmatch.fnmatchcase(name, pat) for pat in exclude):
            continue
        if any(fnmatch.fnmatchcase(name, pat) for pat in include):
            found.append(name)
    return found


def _stand_in(captured):
    module = types.ModuleType('setuptools')

    def setup(**kwargs):
        captured.update(kwargs)

    module.setup = setup
    module.find_packages = find_packages
    module.find_namespace_packages = find_packages
    module.__labkit_stand_in__ = True
    return module


def run_setup(package_dir):
    """Execute `<package_dir>/setup.py`; return the keyword arguments of setup()."""
    path = os.path.join(package_dir, 'setup.py')
    with open(path, encoding='utf-8') as f:
        source = f.read()
    captured = {}
    stand_in = _stand_in(captured)
    with _lock:
        saved_modules = {k: sys.modules.get(k) for k in ('setuptools',)}
        saved_cwd, saved_argv = os.getcwd(), sys.argv
        sys.modules['setuptools'] = stand_in
        os.chdir(package_dir)       # setup.py files glob relative paths ('launch/*.py')
        sys.argv = ['setup.py', 'build']
        try:
            code = compile(source, 'setup.py', 'exec')
            exec(code, {'__name__': '__main__', '__file__': 'setup.py'})
        except SystemExit as e:
            if e.code not in (None, 0):
                raise SetupError(f'{e.code}\n') from None
        except BaseException:
            raise SetupError(_short_traceback()) from None
        finally:
            os.chdir(saved_cwd)
            sys.argv = saved_argv
            for key, value in saved_modules.items():
                if value is None:
                    sys.modules.pop(key, None)
                else:
                    sys.modules[key] = value
    if not captured:
        raise SetupError("setup.py did not call setup()\n")
    return captured


def _short_traceback():
    """The traceback from setup.py's own frames on (not labkit's)."""
    etype, value, tb = sys.exc_info()
    while tb is not None and tb.tb_frame.f_code.co_filename != 'setup.py':
        tb = tb.tb_next
    return ''.join(traceback.format_exception(etype, value, tb))


def read_setup_cfg(package_dir):
    """{'script_dir': ..., 'install_scripts': ...} as written ($base/lib/<pkg>), or None."""
    parser = configparser.ConfigParser()
    try:
        parser.read(os.path.join(package_dir, 'setup.cfg'), encoding='utf-8')
    except configparser.Error:
        return {}
    return {
        'script_dir': parser.get('develop', 'script_dir', fallback=None),
        'install_scripts': parser.get('install', 'install_scripts', fallback=None),
    }


def console_scripts(entry_points):
    """[(name, 'module:function')] from setup(entry_points=...) in any accepted form."""
    if not entry_points:
        return []
    items = entry_points.get('console_scripts', []) if isinstance(entry_points, dict) else []
    if isinstance(items, str):
        items = items.splitlines()
    scripts = []
    for item in items:
        name, sep, target = item.partition('=')
        if sep and name.strip():
            scripts.append((name.strip(), target.strip().split()[0] if target.strip() else ''))
    return scripts
