"""`%load_ext labkit` and `%ros2` in an IPython shell."""
import pytest

from labkit import compat
from labkit.cli import magics


@pytest.fixture(scope='module')
def shell():
    from IPython.core.interactiveshell import InteractiveShell
    ip = InteractiveShell.instance()
    if 'labkit' not in ip.extension_manager.loaded:
        ip.run_line_magic('load_ext', 'labkit')
    yield ip
    compat.deactivate()


def test_load_ext_prints_nothing_and_activates(shell, capsys):
    shell.extension_manager.loaded.discard('labkit')
    shell.run_line_magic('load_ext', 'labkit')
    captured = capsys.readouterr()
    assert (captured.out, captured.err) == ('', '')
    assert compat.is_active()
    assert 'ros2' in shell.magics_manager.magics['line']


def test_ros2_magic_prints_like_a_terminal(shell, capsys):
    shell.run_line_magic('ros2', 'interface show std_msgs/msg/Bool --no-comments')
    assert capsys.readouterr().out == 'bool data\n'
    shell.run_line_magic('ros2', 'interface show nope/msg/X')
    captured = capsys.readouterr()
    assert (captured.out, captured.err) == ('', "Unknown package 'nope'\n")


def test_redirection(shell, tmp_path, capsys):
    target = tmp_path / 'out.txt'
    shell.run_line_magic('ros2', f'interface show std_msgs/msg/Bool --no-comments > {target}')
    shell.run_line_magic('ros2', f'interface show std_msgs/msg/Int8 --no-comments >> {target}')
    assert target.read_text() == 'bool data\nint8 data\n'
    shell.run_line_magic('ros2', f'interface show std_msgs/msg/Int8 --no-comments >{target}')
    assert target.read_text() == 'int8 data\n'
    assert capsys.readouterr().out == ''


def test_braces_reach_ros2_untouched(shell, capsys):
    shell.user_ns['x'] = 'EXPANDED'
    shell.run_cell('%ros2 interface show "{x}"')
    err = capsys.readouterr().err
    assert "Invalid name '{x}'" in err and 'EXPANDED' not in err


def test_split_redirect():
    assert magics.split_redirect("topic pub /t std_msgs/String 'data: a > b'") == (
        ['topic', 'pub', '/t', 'std_msgs/String', 'data: a > b'], None, None)
    assert magics.split_redirect('param dump /turtlesim > t.yaml') == (
        ['param', 'dump', '/turtlesim'], 't.yaml', 'w')
    assert magics.split_redirect('param dump /turtlesim >> t.yaml')[1:] == ('t.yaml', 'a')


def test_magics_registry_is_extensible(shell, capsys):
    magics.register('labkit_echo_test', lambda line: print('got', line))
    try:
        shell.run_line_magic('labkit_echo_test', 'a b')
        assert capsys.readouterr().out == 'got a b\n'
    finally:
        magics.MAGICS.pop('labkit_echo_test')


def test_ros2_run_job_and_jobs_listing(shell, capsys):
    import labkit
    shell.run_line_magic('ros2', 'run demo_nodes_cpp talker')
    captured = capsys.readouterr()
    assert captured.out == ''  # the job's own lines arrive through its process output
    shell.run_line_magic('ros2', 'run demo_nodes_cpp talker')
    assert 'already running' in capsys.readouterr().out
    shell.run_line_magic('ros2', 'jobs')
    assert capsys.readouterr().out.endswith(' running ros2 run demo_nodes_cpp talker\n')
    shell.run_line_magic('ros2', 'jobs stop all')
    assert ' stopped ros2 run demo_nodes_cpp talker' in capsys.readouterr().out
    labkit.reset()
