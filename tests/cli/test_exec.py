"""`labkit exec FILE ARGS...` runs a ROS 2 Python program like `python FILE ARGS...`."""
import subprocess
import sys
import textwrap

import pytest

from labkit.cli.main import exec_file, main


@pytest.fixture(autouse=True)
def _keep_time_mode(monkeypatch):
    # exec_file switches LABKIT_TIME to live for the program it runs; keep ours afterwards
    monkeypatch.setenv('LABKIT_TIME', 'virtual')


def _script(tmp_path, body, name='prog.py'):
    path = tmp_path / name
    path.write_text(textwrap.dedent(body))
    return str(path)


def test_exec_runs_as_main_with_argv_and_the_hook(tmp_path, capsys):
    path = _script(tmp_path, '''
        import sys
        from std_msgs.msg import String
        print(__name__, sys.argv[1:], String(data='x'))
    ''')
    assert exec_file(path, ['a', '--b']) == 0
    assert capsys.readouterr().out == "__main__ ['a', '--b'] std_msgs.msg.String(data='x')\n"


def test_exit_codes_like_python(tmp_path, capsys):
    assert exec_file(_script(tmp_path, 'raise SystemExit(3)\n')) == 3
    assert exec_file(_script(tmp_path, 'import sys; sys.exit("bad thing")\n')) == 1
    assert capsys.readouterr().err == 'bad thing\n'
    assert exec_file(_script(tmp_path, 'import sys; sys.exit()\n')) == 0


def test_uncaught_exception_shows_only_user_frames(tmp_path, capsys):
    path = _script(tmp_path, '''
        def f():
            raise ValueError('boom')
        f()
    ''')
    assert exec_file(path) == 1
    err = capsys.readouterr().err
    assert err.startswith('Traceback (most recent call last):\n')
    assert err.rstrip().endswith('ValueError: boom')
    assert 'runpy' not in err and 'labkit' not in err


def test_missing_file(tmp_path, capsys):
    assert exec_file(str(tmp_path / 'nope.py')) == 2
    assert "can't open file" in capsys.readouterr().err


def test_python_dash_m_labkit_exec(tmp_path):
    path = _script(tmp_path, '''
        import sys, os
        from geometry_msgs.msg import Twist
        print(Twist().linear.x, os.environ['LABKIT_TIME'], sys.argv[1])
        sys.exit(5)
    ''')
    done = subprocess.run([sys.executable, '-m', 'labkit', 'exec', path, 'hello'],
                          capture_output=True, text=True)
    assert done.returncode == 5, done.stderr
    assert done.stdout == '0.0 live hello\n'


def test_labkit_ros2_standalone(capsys):
    assert main(['ros2', 'interface', 'show', '--no-comments', 'std_msgs/msg/Bool']) == 0
    assert capsys.readouterr().out == 'bool data\n'
    assert main(['ros2', 'interface', 'show', 'nope/msg/X']) == 1
    assert capsys.readouterr().err == "Unknown package 'nope'\n"


def test_exec_an_rclpy_program_in_live_time(tmp_path):
    path = _script(tmp_path, '''
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        rclpy.init()
        node = Node('probe')
        got = []
        node.create_subscription(String, 'chat', lambda m: got.append(m.data), 10)
        pub = node.create_publisher(String, 'chat', 10)
        for i in range(3):
            pub.publish(String(data=f'm{i}'))
        while len(got) < 3:
            rclpy.spin_once(node, timeout_sec=1.0)
        print(got, type(node).__init__.__module__)   # the class itself says rclpy.node
        node.destroy_node()
        rclpy.shutdown()
    ''')
    done = subprocess.run([sys.executable, '-m', 'labkit', 'exec', path],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "['m0', 'm1', 'm2'] labkit.rclpy.node\n"
