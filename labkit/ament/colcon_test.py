"""`colcon test` and `colcon test-result`, as colcon-core / colcon-test-result do them.

colcon test: for each selected ament_python package, pytest runs in a child
process with the workspace sourced (PYTHONPATH holds every install/<pkg>
site-packages folder), in the package's source folder, with colcon's options
in PYTEST_ADDOPTS (`--tb=short --junit-xml=build/<pkg>/pytest.xml
--junit-prefix=<pkg> -o cache_dir=build/<pkg>/.pytest_cache` + --pytest-args).
pytest's output is not shown (colcon keeps it in log/); exit code 1 from
pytest (tests failed) marks the package "with test failures" and colcon
still exits 0, as the real tool does.

The child loads this module as a pytest plugin (`-p labkit.ament.colcon_test`):
it activates labkit's `import rclpy` and registers ament_lint's markers. The
ament linters (ament_copyright, ament_flake8, ament_pep257, ament_xmllint)
are not part of labkit: a test calling one of them is SKIPPED with the reason
"ament_flake8 is not available in labkit" rather than pretending it passed.

ament_cmake packages: ctest is not run (nothing is compiled in labkit); they
finish without a result file.

colcon test-result: reads every *.xml below build/ (dot folders skipped) as
xUnit and prints colcon-test-result's lines.
"""
import os
import re
import subprocess
import sys
import time
import types
import xml.etree.ElementTree as ElementTree

from labkit import oslayer

LINTERS = {       # module -> functions the pkg create templates call
    'ament_copyright': ('main',),
    'ament_flake8': ('main', 'main_with_errors'),
    'ament_pep257': ('main',),
    'ament_xmllint': ('main',),
    'ament_mypy': ('main',),
}
LINT_MARKERS = ('linter', 'copyright', 'flake8', 'pep257', 'xmllint', 'mypy')
PYTEST_TESTS_FAILED, PYTEST_NO_TESTS = 1, 5
HUMBLE_PLATFORM = ('platform linux -- Python 3.10.12, pytest-6.2.5, py-1.10.0, '
                   'pluggy-0.13.0')


# ------------------------------------------------------------------ parsers

def add_arguments(parser, verb):
    if verb == 'test':
        parser.add_argument('--base-paths', nargs='*', default=['.'], metavar='PATH',
                            help='The base paths to recursively crawl for packages '
                                 '(default: .)')
        parser.add_argument('--packages-select', nargs='*', metavar='PKG_NAME',
                            help='Only process a subset of packages')
        parser.add_argument('--packages-skip', nargs='*', metavar='PKG_NAME',
                            help='Skip a set of packages')
        parser.add_argument('--packages-up-to', nargs='*', metavar='PKG_NAME',
                            help='Only process a subset of packages and their recursive '
                                 'dependencies')
        parser.add_argument('--build-base', default='build',
                            help='The base path for all build directories (default: build)')
        parser.add_argument('--install-base', default='install',
                            help='The base path for all install prefixes (default: install)')
        parser.add_argument('--test-result-base',
                            help='The base path for all test results (default: --build-base)')
        parser.add_argument('--event-handlers', nargs='*', default=[], metavar='name+/-',
                            help='Enable or disable event handlers')
        parser.add_argument('--executor', default='parallel',
                            choices=['parallel', 'sequential'])
        parser.add_argument('--parallel-workers', type=int, default=None,
                            metavar='NUMBER')     # None: the cores (colcon.workers())
        parser.add_argument('--abort-on-error', action='store_true',
                            help='Abort after the first package with any errors (failing '
                                 'tests are not considered errors in this context)')
        parser.add_argument('--return-code-on-test-failure', action='store_true',
                            help='Use a non-zero return code to indicate any test failure')
        parser.add_argument('--pytest-args', nargs='*', metavar='*',
                            help='Pass arguments to pytests.')
        parser.add_argument('--ctest-args', nargs='*', metavar='*',
                            help='Pass arguments to CTest projects.')
        parser.add_argument('--merge-install', action='store_true')
    else:
        parser.add_argument('--test-result-base', default='build',
                            help='The base path for all test results (default: build)')
        parser.add_argument('--all', action='store_true',
                            help='Show all test result files (even without errors / '
                                 'failures)')
        parser.add_argument('--verbose', action='store_true',
                            help='Show additional information for each error / failure')
        parser.add_argument('--result-files-only', action='store_true',
                            help='Print only the paths of the result files.')


# ------------------------------------------------------------------ colcon test

def test_verb(args, io, clock):
    from labkit.ament import build
    from labkit.ament.colcon import _plural, _select, execute, format_duration
    build_base = os.path.abspath(args.build_base)
    install_base = os.path.abspath(args.install_base)
    ordered, selected = _select(args, io, clock, (build_base, install_base,
                                            os.path.abspath(args.log_base)))
    direct = any(h.startswith('console_direct+') or h.startswith('console_cohesion+')
                 for h in args.event_handlers)
    site_dirs = sorted(
        os.path.join(install_base, name, build.PYTHON_DIR)
        for name in (os.listdir(install_base) if os.path.isdir(install_base) else ())
        if os.path.isdir(os.path.join(install_base, name, build.PYTHON_DIR)))

    finished, failed, aborted, with_failures, stderr_pkgs = [], [], [], [], []

    def start(pkg):
        io.print(f'Starting >>> {pkg.name}')
        result_base = os.path.join(os.path.abspath(args.test_result_base or args.build_base),
                                   pkg.name)
        if pkg.build_type == 'ament_python':
            rc, out, err, cost = _run_pytest(pkg, result_base, site_dirs,
                                             args.pytest_args or [])
        else:
            rc, out, err, cost = 0, [], [], 0.2    # ctest: nothing compiled, nothing to run
        # pytest's "tests failed" and "no tests" are not the job's failure
        job_rc = 0 if rc in (0, PYTEST_TESTS_FAILED, PYTEST_NO_TESTS) else rc
        return cost, job_rc, (rc, out, err)

    def end(pkg, payload, took, was_aborted):
        rc, out, err = payload
        took = format_duration(max(took, 0.0))
        if was_aborted:
            aborted.append(pkg.name)
            io.print(f'Aborted  <<< {pkg.name} [{took}]')
            return
        if direct:
            for line in out:
                io.print(line)
        if err:
            stderr_pkgs.append(pkg.name)
            io.eprint(f'--- stderr: {pkg.name}')
            for line in err:
                io.eprint(line)
            io.eprint('---')
        if rc not in (0, PYTEST_TESTS_FAILED, PYTEST_NO_TESTS):
            failed.append(pkg.name)
            io.eprint(f'Failed   <<< {pkg.name} [{took}, exited with code {rc}]')
            return
        finished.append(pkg.name)
        line = f'Finished <<< {pkg.name} [{took}]'
        if rc == PYTEST_TESTS_FAILED:
            with_failures.append(pkg.name)
            line += '\t[ with test failures ]'
        io.print(line)

    not_processed = execute(args, ordered, selected, clock, start, end,
                            'interrupt' if args.abort_on_error else 'continue')

    clock.add(0.2)
    io.print('')
    io.print(f'Summary: {_plural(len(finished))} finished [{format_duration(clock.now())}]')
    for names, what in ((failed, 'failed'), (aborted, 'aborted'),
                        (stderr_pkgs, 'had stderr output'),
                        (with_failures, 'had test failures')):
        if names:
            io.print(f'  {_plural(len(names))} {what}: ' + ' '.join(sorted(names)))
    if not_processed:
        io.print(f'  {_plural(len(not_processed))} not processed')
    if failed:
        return 1
    return 1 if with_failures and args.return_code_on_test_failure else 0


def _has_pytest_config(path):
    """Whether pytest would find its configuration in the package folder itself."""
    for name, marker in (('pytest.ini', ''), ('.pytest.ini', ''),
                         ('pyproject.toml', '[tool.pytest.ini_options]'),
                         ('tox.ini', '[pytest]'), ('setup.cfg', '[tool:pytest]')):
        try:
            with open(os.path.join(path, name), encoding='utf-8') as f:
                if marker in f.read():
                    return True
        except OSError:
            pass
    return False


def _run_pytest(pkg, result_base, site_dirs, pytest_args):
    """Run pytest for one package as colcon-core's pytest step does; (rc, out, err, cost)."""
    from labkit.graph import world
    os.makedirs(result_base, exist_ok=True)
    junit = os.path.join(result_base, 'pytest.xml')
    # colcon's placeholder, replaced by pytest's own file when pytest gets that far
    with open(junit, 'w', encoding='utf-8') as f:
        f.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                f'<testsuite name="{pkg.name}" tests="1" failures="0" time="0" errors="1" '
                'skipped="0">\n'
                f'  <testcase classname="{pkg.name}" name="pytest.missing_result" time="0">\n'
                '    <failure message="The test invocation failed without generating a '
                'result file."/>\n  </testcase>\n</testsuite>\n')
    options = ['--tb=short', f'--junit-xml={junit}', f'--junit-prefix={pkg.name}',
               '-o', f'cache_dir={os.path.join(result_base, ".pytest_cache")}',
               '-p', 'labkit.ament.colcon_test']
    if not _has_pytest_config(pkg.path):
        # no configuration of its own: do not let pytest climb to a parent project's
        options += ['-c', os.devnull, f'--rootdir={pkg.path}']
    options += [a.strip() for a in pytest_args]
    env = dict(os.environ)
    # pytest splits PYTEST_ADDOPTS with POSIX shlex: quoted, a Windows path keeps its '\\'
    env['PYTEST_ADDOPTS'] = ' '.join(oslayer.quote_arg(a) for a in options)
    labkit_root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    env['PYTHONPATH'] = os.pathsep.join(
        [*site_dirs, *[p for p in env.get('PYTHONPATH', '').split(os.pathsep) if p],
         labkit_root])
    env['LABKIT_TIME'] = world.mode()
    env.pop('PYTEST_CURRENT_TEST', None)
    # the plugins of this Python (nbval, xdist...) are not a Humble machine's, and slow
    env['PYTEST_DISABLE_PLUGIN_AUTOLOAD'] = '1'
    # colcon reads pytest through a pipe: plain text, whatever the notebook's terminal says
    env['PY_COLORS'] = '0'
    env.pop('FORCE_COLOR', None)
    env['PYTHONIOENCODING'] = 'utf-8'       # the pipe is read as UTF-8 on every OS
    started = time.monotonic()
    done = subprocess.run([sys.executable, '-m', 'pytest'], cwd=pkg.path, env=env,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          encoding='utf-8', errors='replace')
    measured = time.monotonic() - started
    counts = _counts(junit)
    virtual = world.mode() == 'virtual'
    cost = 0.45 + 0.04 * sum(counts) if virtual else measured
    out = _lines(done.stdout, cost, virtual)
    err = _lines(done.stderr, cost, virtual)
    return done.returncode, out, err, cost


# The `plugins:` line of pytest's header on a Humble desktop machine: the pytest11 entry
# points of ros-humble-launch-testing-ros, ament_lint's linters, launch-testing and
# python3-colcon-core. Names, versions and their order are copied from one real Humble
# log with the same pytest 6.2.5 / py 1.10.0 (pytest run by colcon test through ctest's
# ament_cmake_pytest; the plugins are the same for an ament_python package, as a
# ros2/launch_ros#390 log of `colcon test` shows with older versions). Not verified: that
# this exact set of versions is what a current ros-humble-desktop install has; other
# machines list the same plugins in another order or with later patch versions (each
# sync bumps them), and add ament-mypy when it is installed.
HUMBLE_PLUGINS = ('plugins: launch-testing-ros-0.19.7, ament-xmllint-0.12.10, '
                  'ament-copyright-0.12.10, ament-lint-0.12.10, ament-pep257-0.12.10, '
                  'launch-testing-1.0.4, ament-flake8-0.12.10, colcon-core-0.15.2')
# Python 3.11+ underlines the failing expression in a traceback (^^^^, ~~~^~~~); 3.10 not
CARETS = re.compile(r'^\s*[~^]*\^[~^]*\s*$')


def _lines(text, cost, virtual):
    """pytest's output as Jammy's pytest 6.2.5 on Python 3.10 prints it."""
    result = []
    for line in text.splitlines():
        if CARETS.match(line):
            continue
        line = _shown(line, cost, virtual)
        if line is None:
            continue
        # pytest 6 prints the config file and testpaths on the rootdir line
        if line.startswith(('configfile: ', 'testpaths: ')) and result and \
                result[-1].startswith('rootdir: '):
            result[-1] += ', ' + line
            continue
        if virtual and line.startswith('plugins: '):
            continue        # this Python's own plugins (none: autoload is off)
        if virtual and result and result[-1].startswith('rootdir: ') and \
                HUMBLE_PLATFORM in result[-3:-1]:
            result.append(HUMBLE_PLUGINS)
        result.append(line)
    return result


def _counts(junit):
    try:
        r = parse_xunit(junit)
    except (OSError, ValueError, ElementTree.ParseError):
        return (0,)
    return (r.tests,)


_WINDOWS_TEST_PATH = re.compile(r'(?<![\w:\\])((?:[\w.-]+\\)+[\w.-]+\.py)\b')


def _shown(line, cost, virtual):
    """A line of pytest's output as a Humble machine's terminal would show it."""
    from labkit.ament import files
    home = files.home()
    if files._home is not None:
        line = oslayer.slashes_after(line.replace(home, files.SHOWN_HOME),
                                     (files.SHOWN_HOME,))
    if os.sep == '\\':     # pytest names test files with the OS's separator: test/x.py
        line = _WINDOWS_TEST_PATH.sub(lambda m: m.group(1).replace('\\', '/'), line)
    # -c os.devnull: `../../dev/null` on Linux, `\\\\.\\nul\\` on Windows
    if line.startswith('configfile: ') and line.rstrip('\\/').endswith(os.devnull.lstrip('/')):
        return None
    if virtual:
        if line.startswith('platform ') and ' -- Python ' in line:   # win32, darwin too
            return HUMBLE_PLATFORM
        line = re.sub(r' in \d+\.\d+s( \([0-9:]+\))? (=+)$', f' in {cost:.2f}s \\2', line)
    return _recentre(line)


def _recentre(line, width=80):
    """pytest's `==== title ====` lines, re-padded after a path or time in them changed."""
    m = re.match(r'^([=_-])\1+ (.*?) \1+$', line)
    if not m:
        return line
    sep, title = m.groups()
    fill = sep * max((width - len(title) - 2) // 2, 1)
    line = f'{fill} {title} {fill}'
    return line + sep if len(line) + 1 <= width else line


# ------------------------------------------------------------------ colcon test-result

class Result:
    """The counts of one xUnit file (or the summary of all)."""

    def __init__(self, path):
        self.path = path
        self.tests = self.errors = self.failures = self.skipped = 0
        self.details = []

    def add(self, other):
        self.tests += other.tests
        self.errors += other.errors
        self.failures += other.failures
        self.skipped += other.skipped
        self.details += other.details

    def __str__(self):
        def n(count, word):
            return f'{count} {word}' + ('' if count == 1 else 's')
        return (f'{oslayer.shown_path(self.path)}: {n(self.tests, "test")}, {n(self.errors, "error")}, '
                f'{n(self.failures, "failure")}, {self.skipped} skipped')


def parse_xunit(path):
    """A Result from a junit/xUnit file; ValueError when it is not one."""
    root = ElementTree.parse(path).getroot()
    suites = [root] if root.tag == 'testsuite' else \
        [c for c in root if c.tag == 'testsuite'] if root.tag == 'testsuites' else None
    if suites is None:
        raise ValueError("the root tag is neither 'testsuite' nor 'testsuites'")
    result = Result(path)
    for suite in suites:
        for attribute in ('tests', 'failures'):
            if attribute not in suite.attrib:
                raise ValueError(f"the '{attribute}' attribute is required")
        result.tests += int(suite.attrib['tests'])
        result.failures += int(suite.attrib['failures'])
        result.errors += int(suite.attrib.get('errors', 0))
        result.skipped += sum(int(suite.attrib.get(a, 0))
                              for a in ('skip', 'skipped', 'disabled'))
        result.details += _details(suite)
    return result


def _details(suite):
    """`--verbose`: one block per failed/erroneous test case, as colcon-test-result prints."""
    blocks = []
    for case in suite:
        if case.tag != 'testcase':
            continue
        errors = [c.attrib.get('message', '') for c in case if c.tag == 'error']
        failures = [c.attrib.get('message', '') for c in case if c.tag == 'failure']
        if not errors and not failures:
            continue
        label = ' '.join(x for x in (case.attrib.get('classname'), case.attrib.get('name'))
                         if x)
        lines = [label]
        for title, messages in (('error message', errors), ('failure message', failures)):
            if messages:
                lines.append('<<< ' + title)
                for message in messages:
                    lines += ['  ' + m for m in message.strip('\n\r').splitlines()]
                lines.append('>>>')
        blocks.append('\n'.join(lines))
    return blocks


def test_result_verb(args, io, clock):
    base = args.test_result_base
    if not os.path.isdir(base):
        io.eprint('usage: colcon test-result [-h] [--test-result-base TEST_RESULT_BASE] '
                  '[--all] [--verbose]\n                          [--result-files-only] '
                  '[--delete] [--delete-yes]')
        io.eprint(f"colcon test-result: error: argument --test-result-base: Path '{base}' "
                  'does not exist')
        return 2
    results = []
    for folder, dirs, names in os.walk(base):
        dirs[:] = sorted(d for d in dirs if not d.startswith('.'))
        for name in sorted(names):
            if not name.endswith('.xml'):
                continue
            path = os.path.join(folder, name)
            try:
                results.append(parse_xunit(path))
            except ElementTree.ParseError as e:
                io.eprint(f"[{clock.now():.3f}s] WARNING:colcon.colcon_test_result.test_result"
                          f".xunit:Skipping '{path}': {e}")
            except ValueError:
                pass
    shown = sorted((r for r in results if r.errors or r.failures or args.all),
                   key=lambda r: r.path)
    for r in shown:
        if args.result_files_only:
            io.print(oslayer.shown_path(r.path))
            continue
        io.print(str(r))
        if args.verbose:
            for detail in r.details:
                for i, line in enumerate(detail.splitlines()):
                    io.print(('-' if i == 0 else ' ') + ' ' + line)
    summary = Result('Summary')
    for r in results:
        summary.add(r)
    if not args.result_files_only:
        if shown:
            io.print('')
        io.print(str(summary))
    return 1 if summary.errors or summary.failures else 0


# ------------------------------------------------------------------ pytest plugin (child side)

def _linter_module(name, function_names):
    module = types.ModuleType(name + '.main')

    def unavailable(*args, **kwargs):
        import pytest
        pytest.skip(f'{name} is not available in labkit')
    for fn in function_names:
        setattr(module, fn, unavailable)
    return module


def pytest_load_initial_conftests(early_config, parser, args):
    """Before the package's conftest and tests import anything: labkit's rclpy, linters."""
    import importlib.util
    from labkit import compat, plugins
    plugins.register_all()      # launch, ament_index_python... as in the notebook
    compat.activate()
    for name, function_names in LINTERS.items():
        if importlib.util.find_spec(name) is not None:
            continue
        package = types.ModuleType(name)
        package.__path__ = []
        package.main = _linter_module(name, function_names)
        sys.modules[name] = package
        sys.modules[name + '.main'] = package.main


def pytest_configure(config):
    for marker in LINT_MARKERS:
        config.addinivalue_line('markers', f'{marker}: ament_lint test ({marker})')


# ------------------------------------------------------------------ tests of the tests

def test_variant(package_path, edits):
    """Run a package's tests (`colcon test`) on a changed copy of it: a Result.

    `edits` maps a file of the package (relative path) to a list of (old, new)
    text replacements, each `old` occurring in that file, or to the whole new
    text of the file (a str; the file may be new). The copy lives in a
    scratch workspace that is removed afterwards, so the learner's workspace
    (build/, log/) is untouched. A test suite that really tests the package
    fails on a copy where the package was broken on purpose: that is how the
    book checks that a learner's tests are worth their name.
    """
    import shutil
    import tempfile

    from labkit.ament import colcon, files
    source = os.path.abspath(files.expand(package_path))
    name = os.path.basename(source.rstrip(os.sep))
    scratch = tempfile.mkdtemp(prefix='labkit-variant-')
    here = os.getcwd()
    try:
        copy = os.path.join(scratch, 'src', name)
        shutil.copytree(source, copy, symlinks=True,
                        ignore=shutil.ignore_patterns('__pycache__', '.pytest_cache'))
        for relative, replacements in edits.items():
            path = os.path.join(copy, relative)
            if isinstance(replacements, str):       # the whole file (new or replaced)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, 'w', encoding='utf-8') as f:
                    f.write(replacements)
                continue
            with open(path, encoding='utf-8') as f:
                text = f.read()
            for old, new in replacements:
                if old not in text:
                    raise ValueError(f'{relative}: {old!r} not found')
                text = text.replace(old, new)
            with open(path, 'w', encoding='utf-8') as f:
                f.write(text)
        os.chdir(scratch)
        done = colcon.run_command(['test', '--packages-select', name])
        junit = os.path.join(scratch, 'build', name, 'pytest.xml')
        if not os.path.exists(junit):
            raise RuntimeError(f'colcon test found no package {name}: {done.stderr.strip()}')
        return parse_xunit(junit)
    finally:
        os.chdir(here)
        shutil.rmtree(scratch, ignore_errors=True)
