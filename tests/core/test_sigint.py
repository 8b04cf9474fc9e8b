"""Stopping a process does what SIGINT does to a real ROS 2 Humble process, output
included (checked against the real rclpy wheels: KeyboardInterrupt leaves spin, ok() is
False, a later shutdown() raises RCLError; rclpy#937):

- a Python program that does not catch KeyboardInterrupt dies of it: Python prints the
  traceback (its own frames, then the ones Humble's rclpy shows while it waits) and
  `ros2 run` says `[ros2run]: Interrupt`;
- one that catches it runs on: a `destory_node` typo after spin prints the AttributeError
  as Python 3.10 does ('Did you mean ...?'), `ros2 run` says how it ended;
- a C++ program (rclcpp) logs `signal_handler(signum=2)` and ends cleanly;
- `labkit exec` (a terminal): a real SIGINT shuts the program's contexts down first.
"""
import os
import subprocess
import sys
import textwrap

import pytest

import labkit
from labkit import executables

HUMBLE = '/opt/ros/humble/local/lib/python3.10/dist-packages/rclpy/'

UNCAUGHT = '''
import rclpy
from rclpy.node import Node


def main(args=None):
    rclpy.init(args=args)
    node = Node('plain')
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
'''

TYPO = '''
import rclpy
from rclpy.node import Node


def main(args=None):
    rclpy.init(args=args)
    node = Node('typo')
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        print('ok:', rclpy.ok())
        try:
            rclpy.shutdown()
        except Exception as exc:
            print(type(exc).__name__ + ':', exc)
    node.destory_node()
'''


@pytest.fixture(autouse=True)
def hook():
    from labkit import compat, plugins
    plugins.register_all()
    was = compat.is_active()
    compat.activate(quiet=True)
    yield
    if not was:
        compat.deactivate()


def _package(tmp_path, monkeypatch, name, code):
    path = tmp_path / f'{name}.py'
    path.write_text(textwrap.dedent(code), encoding='utf-8')
    monkeypatch.syspath_prepend(str(tmp_path))
    executables.register('sigint_demo', name, f'{name}:main')
    return str(path)


def test_uncaught_interrupt_prints_pythons_traceback(virtual, tmp_path, monkeypatch):
    path = _package(tmp_path, monkeypatch, 'sig_plain', UNCAUGHT)
    job = labkit.ros2('run sigint_demo sig_plain')
    labkit.sleep(0.5)
    job.stop()
    assert job.process.returncode == -2
    assert '\n'.join(job.output) == '\n'.join([
        'Traceback (most recent call last):',
        f'  File "{path}", line 9, in main',
        '    rclpy.spin(node)',
        f'  File "{HUMBLE}__init__.py", line 226, in spin',
        '    executor.spin_once()',
        f'  File "{HUMBLE}executors.py", line 739, in spin_once',
        '    self._spin_once_impl(timeout_sec)',
        f'  File "{HUMBLE}executors.py", line 728, in _spin_once_impl',
        '    handler, entity, node = self.wait_for_ready_callbacks(timeout_sec=timeout_sec)',
        f'  File "{HUMBLE}executors.py", line 711, in wait_for_ready_callbacks',
        '    return next(self._cb_iter)',
        f'  File "{HUMBLE}executors.py", line 608, in _wait_for_ready_callbacks',
        '    wait_set.wait(timeout_nsec)',
        'KeyboardInterrupt',
        '[ros2run]: Interrupt'])


def test_typo_after_spin_shows_the_attribute_error(virtual, tmp_path, monkeypatch):
    path = _package(tmp_path, monkeypatch, 'sig_typo', TYPO)
    job = labkit.ros2('run sigint_demo sig_typo')
    labkit.sleep(0.5)
    job.stop()
    assert job.process.returncode == 1
    assert job.output == [
        'ok: False',
        'RCLError: failed to shutdown: rcl_shutdown already called on the given context',
        'Traceback (most recent call last):',
        f'  File "{path}", line 17, in main',
        '    node.destory_node()',
        "AttributeError: 'Node' object has no attribute 'destory_node'. "
        "Did you mean: 'destroy_node'?",
        '[ros2run]: Process exited with failure 1']


def test_cpp_program_logs_rclcpp_signal_line_and_ends_cleanly(virtual):
    job = labkit.ros2('run demo_nodes_cpp listener')
    labkit.sleep(0.5)
    job.stop()
    assert job.process.returncode == 0
    assert job.output[-1] == '[INFO] [1704067200.500000000] [rclcpp]: signal_handler(signum=2)'


def test_init_installs_the_handler_and_reset_removes_it(virtual):
    import signal
    import labkit.rclpy as rclpy
    from labkit.rclpy import signals
    before = signal.getsignal(signal.SIGINT)
    rclpy.init(args=[])
    assert signals.get_current_signal_handlers_options() == signals.SignalHandlerOptions.ALL
    assert signal.getsignal(signal.SIGINT) is signals._handler
    labkit.reset()
    assert signal.getsignal(signal.SIGINT) is before
    assert signals.get_current_signal_handlers_options() == signals.SignalHandlerOptions.NO


def test_reset_closes_the_window_without_output(virtual, tmp_path, monkeypatch):
    _package(tmp_path, monkeypatch, 'sig_plain2', UNCAUGHT)
    job = labkit.ros2('run sigint_demo sig_plain2')
    cpp = labkit.ros2('run demo_nodes_cpp listener')
    labkit.sleep(0.5)
    labkit.reset()
    assert job.output == [] and cpp.output == []


SCRIPT = '''
import os, signal, threading
import rclpy
from rclpy.node import Node
rclpy.init()
node = Node('terminal')
node.create_timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    print('KeyboardInterrupt', flush=True)
print('ok', rclpy.ok(), flush=True)
try:
    rclpy.shutdown()
except Exception as exc:
    print(type(exc).__name__, exc, flush=True)
'''


def test_labkit_exec_sigint_shuts_the_context_down(tmp_path):
    path = tmp_path / 'terminal.py'
    path.write_text(SCRIPT, encoding='utf-8')
    env = dict(os.environ, LABKIT_DDS='off', PYTHONPATH=os.getcwd())
    out = subprocess.run([sys.executable, '-m', 'labkit', 'exec', str(path)], env=env,
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == [
        'KeyboardInterrupt', 'ok False',
        'RCLError failed to shutdown: rcl_shutdown already called on the given context']
