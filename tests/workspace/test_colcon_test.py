"""colcon test / colcon test-result: pytest in a child process, colcon's lines, xUnit counts."""
import os

import labkit
from labkit.ament import colcon

GOOD = 'from my_pkg.calc import add\n\n\ndef test_add():\n    assert add(1, 2) == 3\n'
BAD = ('from my_pkg.calc import add\n\n\ndef test_add_again():\n'
       '    assert add(2, 2) == 5\n')
ROS = ('import rclpy\nfrom std_msgs.msg import String\n\n\ndef test_node():\n'
       '    rclpy.init()\n    node = rclpy.create_node("t")\n'
       '    assert node.get_name() == "t"\n    assert String(data="x").data == "x"\n'
       '    node.destroy_node()\n    rclpy.shutdown()\n')


def make_pkg(ws, name='my_pkg', tests=(('test_calc.py', GOOD),)):
    here = os.getcwd()
    os.chdir(ws / 'src')
    try:
        r = labkit.ros2(f'pkg create --build-type ament_python {name}')
    finally:
        os.chdir(here)
    assert r.returncode == 0, r.text()
    pkg = ws / 'src' / name
    (pkg / name / 'calc.py').write_text('def add(a, b):\n    return a + b\n')
    for fname, text in tests:
        (pkg / 'test' / fname).write_text(text.replace('my_pkg', name))
    return pkg


def test_passing_package_and_linters_skip_honestly(ws):
    make_pkg(ws)
    assert colcon.run_command('build').returncode == 0
    r = colcon.run_command('test')
    assert r.returncode == 0, r.text()
    lines = r.stdout.splitlines()
    assert lines[0] == 'Starting >>> my_pkg'
    assert lines[1].startswith('Finished <<< my_pkg [') and 'test failures' not in lines[1]
    assert lines[-1].startswith('Summary: 1 package finished [')
    xml = (ws / 'build' / 'my_pkg' / 'pytest.xml').read_text()
    assert 'my_pkg.test.test_calc' in xml          # --junit-prefix
    assert 'ament_flake8 is not available in labkit' in xml
    r = colcon.run_command('test-result --all')
    assert r.stdout == ('build/my_pkg/pytest.xml: 4 tests, 0 errors, 0 failures, '
                        '3 skipped\n\nSummary: 4 tests, 0 errors, 0 failures, 3 skipped\n')
    assert r.returncode == 0
    # without --all only files with errors or failures are listed
    assert colcon.run_command('test-result').stdout == \
        'Summary: 4 tests, 0 errors, 0 failures, 3 skipped\n'


def test_failures_are_reported_like_colcon(ws):
    make_pkg(ws, tests=(('test_calc.py', GOOD), ('test_bad.py', BAD)))
    make_pkg(ws, 'other_pkg')
    assert colcon.run_command('build').returncode == 0
    r = colcon.run_command('test')
    assert r.returncode == 0          # colcon test itself succeeded
    assert any(line.startswith('Finished <<< my_pkg [') and
               line.endswith('\t[ with test failures ]') for line in r.stdout.splitlines())
    assert 'Summary: 2 packages finished [' in r.stdout
    assert '  1 package had test failures: my_pkg' in r.stdout
    assert 'test_add_again' not in r.stdout           # pytest's output stays in the log
    assert colcon.run_command('test --return-code-on-test-failure').returncode == 1
    r = colcon.run_command('test-result --all')
    assert r.stdout.splitlines() == [
        'build/my_pkg/pytest.xml: 5 tests, 0 errors, 1 failure, 3 skipped',
        'build/other_pkg/pytest.xml: 4 tests, 0 errors, 0 failures, 3 skipped',
        '',
        'Summary: 9 tests, 0 errors, 1 failure, 6 skipped']
    assert r.returncode == 1
    r = colcon.run_command('test-result --verbose')
    assert '- my_pkg.test.test_bad test_add_again' in r.stdout
    assert '  <<< failure message' in r.stdout and 'assert 4 == 5' in r.stdout


def test_select_pytest_args_and_console_direct(ws):
    make_pkg(ws, tests=(('test_calc.py', GOOD), ('test_bad.py', BAD)))
    make_pkg(ws, 'other_pkg')
    colcon.run_command('build')
    r = colcon.run_command('test --packages-select my_pkg --pytest-args -k test_calc '
                           '--event-handlers console_direct+')
    assert [ln for ln in r.stdout.splitlines() if ln.startswith('Starting')] == \
        ['Starting >>> my_pkg']
    assert 'test with failures' not in r.stdout
    assert 'passed' in r.stdout and '4 deselected' in r.stdout   # pytest's own lines shown
    assert 'platform linux -- Python 3.10.12' in r.stdout         # as on a Humble machine
    assert not (ws / 'build' / 'other_pkg' / 'pytest.xml').exists()


def test_rclpy_works_inside_package_tests_and_output_is_deterministic(ws):
    make_pkg(ws, tests=(('test_ros.py', ROS),))
    colcon.run_command('build')
    first = colcon.run_command('test --event-handlers console_direct+')
    assert '1 passed' in first.stdout, first.text()
    assert colcon.run_command('test --event-handlers console_direct+').stdout == first.stdout
    assert 'my_pkg/pytest.xml: 4 tests, 0 errors, 0 failures, 3 skipped' in \
        colcon.run_command('test-result --all').stdout


def test_test_result_without_build_folder(ws):
    r = colcon.run_command('test-result')
    assert r.returncode == 2
    assert "Path 'build' does not exist" in r.stderr


def test_pytest_that_cannot_start_fails_the_package(ws):
    pkg = make_pkg(ws)
    (pkg / 'conftest.py').write_text('raise RuntimeError("broken conftest")\n')
    colcon.run_command('build')
    r = colcon.run_command('test')
    assert r.returncode == 1
    assert 'Failed   <<< my_pkg [' in r.stderr and 'exited with code' in r.stderr
    assert '  1 package failed: my_pkg' in r.stdout
    # colcon's placeholder result is left where pytest wrote none
    assert colcon.run_command('test-result').stdout.startswith(
        'build/my_pkg/pytest.xml: 1 test, 1 error, 0 failures, 0 skipped')


def test_independent_packages_are_tested_side_by_side(ws):
    # my_pkg has one test more than other_pkg: its pytest runs longer, it ends last
    make_pkg(ws, tests=(('test_calc.py', GOOD), ('test_bad.py', BAD)))
    make_pkg(ws, 'other_pkg')
    assert colcon.run_command('build').returncode == 0
    r = colcon.run_command('test')
    order = [line.split(' [')[0] for line in r.stdout.splitlines()
             if '<<<' in line or '>>>' in line]
    assert order == ['Starting >>> my_pkg', 'Starting >>> other_pkg',
                     'Finished <<< other_pkg', 'Finished <<< my_pkg']
    r = colcon.run_command('test --executor sequential')
    order = [line.split(' [')[0] for line in r.stdout.splitlines()
             if '<<<' in line or '>>>' in line]
    assert order == ['Starting >>> my_pkg', 'Finished <<< my_pkg',
                     'Starting >>> other_pkg', 'Finished <<< other_pkg']


def test_pytest_output_is_jammys(ws):
    # what `--event-handlers console_direct+` shows: pytest 6.2.5 on Python 3.10
    raises = ('from my_pkg.calc import add\n\n\ndef test_add_none():\n'
              '    assert add(2, None) == 2\n')
    make_pkg(ws, tests=(('test_bad.py', BAD), ('test_raises.py', raises)))
    assert colcon.run_command('build').returncode == 0
    r = colcon.run_command('test --event-handlers console_direct+')
    assert '    return a + b\nE   TypeError: unsupported operand' in r.stdout
    lines = r.stdout.splitlines()
    platform = lines.index('platform linux -- Python 3.10.12, pytest-6.2.5, py-1.10.0, '
                           'pluggy-0.13.0')
    assert lines[platform + 1].startswith('cachedir: ')
    assert any(line.startswith('plugins: ') and 'ament-flake8-' in line and
               'launch-testing-' in line for line in lines[platform:platform + 5])
    assert '    assert add(2, 2) == 5' in lines
    # Python 3.11's carets under the failing line: Python 3.10 prints none
    assert not any(set(line.strip()) <= {'^', '~'} and line.strip() for line in lines)
