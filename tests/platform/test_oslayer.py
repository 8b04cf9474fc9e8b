"""labkit.oslayer, the one seam to the operating system: each platform's branch is
driven here on Linux by simulating what the other OS does (its refusal, its keys, its
separators); tests/platform/test_windows_wine.py runs them on real Windows CPython."""
import errno
import io
import os
import threading

import pytest

from labkit import oslayer
from labkit.ament import colcon, files


# ----------------------------------------------------------------------------- arguments

def test_windows_paths_keep_their_backslashes():
    line = r'param load /turtlesim C:\Users\me\ros2_ws\turtlesim.yaml'
    assert oslayer.split_args(line, windows=True) == [
        'param', 'load', '/turtlesim', r'C:\Users\me\ros2_ws\turtlesim.yaml']
    # POSIX rules (Linux, macOS) eat them, as bash does: the bug this seam fixes on Windows
    assert oslayer.split_args(line, windows=False)[-1] == 'C:Usersmeros2_wsturtlesim.yaml'


def test_windows_splitting_still_groups_quoted_words():
    line = r'''topic pub /chatter std_msgs/msg/String "{data: 'hi there'}" --params-file "C:\a b\p.yaml"'''
    assert oslayer.split_args(line, windows=True) == [
        'topic', 'pub', '/chatter', 'std_msgs/msg/String', "{data: 'hi there'}",
        '--params-file', r'C:\a b\p.yaml']


def test_posix_splitting_is_shlex():
    line = r'''run pkg node --ros-args -p "msg:=a \"b\"" -r __ns:=/x'''
    assert oslayer.split_args(line, windows=False) == [
        'run', 'pkg', 'node', '--ros-args', '-p', 'msg:=a "b"', '-r', '__ns:=/x']


def test_redirection_and_comments_on_both():
    for windows in (True, False):
        assert oslayer.split_args(r'param dump /t > out\t.yaml  # c', windows=windows,
                                  punctuation_chars='>', comments=True)[-2:] == \
            ['>', r'out\t.yaml' if windows else 'outt.yaml']


def test_ros2_and_colcon_use_the_seam(monkeypatch):
    """The rooms split with oslayer.split_args: on Windows a params path survives."""
    from labkit.cli import ros2
    monkeypatch.setattr(oslayer, 'WINDOWS', True)
    assert ros2.split_command(r'ros2 param load /t C:\ws\p.yaml')[-1] == r'C:\ws\p.yaml'
    monkeypatch.setattr(oslayer, 'WINDOWS', False)
    assert ros2.split_command(r'ros2 param load /t C:\ws\p.yaml')[-1] == r'C:wsp.yaml'


# ----------------------------------------------------------------------------- symlinks

def _refuse(*args, **kwargs):
    # what Windows says without Developer Mode (the winerror attribute is Windows-only,
    # so set it by hand on Linux)
    exc = OSError(errno.EPERM, 'A required privilege is not held by the client')
    exc.winerror = 1314
    raise exc


def test_symlink_when_the_os_allows(tmp_path):
    (tmp_path / 'target').mkdir()
    how = oslayer.symlink('target', str(tmp_path / 'latest'))
    assert oslayer.link_target(str(tmp_path / 'latest')) == 'target'
    if oslayer.WINDOWS and how != 'symlink':
        pytest.skip('this Windows refuses symbolic links (no Developer Mode, or Wine): '
                    f'made a {how}')
    assert how == 'symlink' and os.path.islink(tmp_path / 'latest')


def test_refused_symlink_of_a_folder_becomes_a_copy_that_still_reads_as_the_link(
        tmp_path, monkeypatch):
    src = tmp_path / 'build_1'
    src.mkdir()
    (src / 'events.log').write_text('x', encoding='utf-8')
    monkeypatch.setattr(os, 'symlink', _refuse)
    how = oslayer.symlink('build_1', str(tmp_path / 'latest_build'))
    assert how == 'copy'                  # no junction off Windows
    assert (tmp_path / 'latest_build' / 'events.log').read_text(encoding='utf-8') == 'x'
    assert oslayer.link_target(str(tmp_path / 'latest_build')) == 'build_1'
    # replacing it removes the copy, never the folder it stood for
    (tmp_path / 'build_2').mkdir()
    oslayer.replace_link('build_2', str(tmp_path / 'latest_build'))
    assert (src / 'events.log').exists()
    assert oslayer.link_target(str(tmp_path / 'latest_build')) == 'build_2'


def test_refused_symlink_of_a_file_is_a_copy(tmp_path, monkeypatch):
    src = tmp_path / 'talker.py'
    src.write_text('print(1)\n', encoding='utf-8')
    monkeypatch.setattr(os, 'symlink', _refuse)
    assert oslayer.symlink(str(src), str(tmp_path / 'installed.py')) == 'copy'
    assert (tmp_path / 'installed.py').read_text(encoding='utf-8') == 'print(1)\n'
    oslayer.remove(str(tmp_path / 'installed.py'))
    assert src.exists() and not (tmp_path / 'installed.py').exists()


def test_other_symlink_errors_are_not_hidden(tmp_path, monkeypatch):
    def no_space(*a, **k):
        raise OSError(errno.ENOSPC, 'No space left on device')
    monkeypatch.setattr(os, 'symlink', no_space)
    with pytest.raises(OSError):
        oslayer.symlink('x', str(tmp_path / 'y'))


def test_colcon_log_links_without_symlinks_print_as_humble(tmp_path, monkeypatch):
    """colcon's log/latest and log/latest_build where the OS refuses symlinks: the build
    works and `tree log` prints the links as on Linux."""
    monkeypatch.setattr(os, 'symlink', _refuse)
    log = tmp_path / 'log'
    log.mkdir()
    folder = colcon._new_log_dir(str(log))
    second = colcon._new_log_dir(str(log))
    assert os.path.basename(second) != os.path.basename(folder)
    lines = files.tree_lines(str(log))
    assert '├── latest -> latest_build' in lines
    assert f'└── latest_build -> {os.path.basename(second)}' in lines
    # what the build logs later shows through the copies too, as through a link
    colcon._write_package_log(second, 'my_pkg', _Res())
    for link in ('latest', 'latest_build'):
        assert (log / link / 'my_pkg' / 'stdout.log').is_file()


class _Res:
    stdout, stderr = ['out'], []


# ----------------------------------------------------------------------------- keys

def test_msvcrt_arrow_keys_become_what_a_linux_terminal_sends():
    assert oslayer.decode_windows_keys('\xe0H') == '\x1b[A'
    assert oslayer.decode_windows_keys('\xe0P\xe0M\x00K') == '\x1b[B\x1b[C\x1b[D'
    assert oslayer.decode_windows_keys('\xe0S') == ''          # Delete: not a key here
    assert oslayer.decode_windows_keys('q\r') == 'q\n'


class _FakeMsvcrt:
    """A console that has these key codes waiting."""

    def __init__(self, codes):
        self.codes = list(codes)

    def kbhit(self):
        return bool(self.codes)

    def getwch(self):
        return self.codes.pop(0)


def test_windows_key_reader_drives_turtle_teleop():
    """The msvcrt reader feeds the arrow keys to turtle_teleop_key's own mapping."""
    from labkit.sims.turtlesim.keys import TTY_CHARS
    got, done = [], threading.Event()

    def press(ch):
        got.append(ch)
        if ch == 'q':
            done.set()
    reader = oslayer._WindowsKeys(press, done.is_set, False, 'test-keys',
                                  msvcrt=_FakeMsvcrt(['\xe0', 'H', '\xe0', 'K', 'q']))
    reader.thread.join(5)
    assert ''.join(got) == '\x1b[A\x1b[Dq'
    assert [TTY_CHARS[c] for c in got if c in TTY_CHARS] == ['up', 'left']


def test_no_terminal_no_key_reader(monkeypatch):
    monkeypatch.setattr('sys.stdin', io.StringIO(''))
    assert oslayer.terminal_keys(lambda c: None, lambda: True) is None


# ----------------------------------------------------------------------------- paths shown

def test_shown_paths_are_ubuntu_paths_on_windows():
    home = r'C:\Users\me\book\_work\ch11'
    assert oslayer.shown_path(home, home, sep='\\') == '/root'
    assert oslayer.shown_path(home + r'\facer_ws\src', home, sep='\\') == '/root/facer_ws/src'
    assert oslayer.shown_path(r'.\my_first_pkg', None, sep='\\') == './my_first_pkg'
    assert oslayer.shown_path('/root/x', None, sep='/') == '/root/x'
    # outside the sandbox an absolute Windows path stays what it is
    assert oslayer.shown_path(r'D:\data', home, sep='\\') == r'D:\data'


def test_home_expansion_uses_one_separator(tmp_path):
    files.use_home(str(tmp_path / 'home'))
    try:
        real = files.expand('~/ros2_ws/src')
        assert real == os.path.join(str(tmp_path / 'home'), 'ros2_ws', 'src')
        assert files.display(real) == '/root/ros2_ws/src'
        assert files.display('~') == '/root'
        assert files.display(os.path.join('.', 'my_first_pkg')) == './my_first_pkg'
    finally:
        files.leave_home()


# ----------------------------------------------------------------------------- processes, DDS

def test_stop_process_stops_a_child_and_kill_signal_exists():
    import subprocess
    import sys
    child = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(60)'],
                             **oslayer.new_group_options())
    code = oslayer.stop_process(child, timeout=10)
    assert child.poll() is not None and code != 0
    assert oslayer.KILL_SIGNAL is not None


def test_dds_loopback_is_an_address_on_every_os():
    from labkit.dds import config
    xml = config.cyclone_xml(True)
    assert '<NetworkInterface address="127.0.0.1"/>' in xml
    assert 'name="lo"' not in xml
    assert config.LOOPBACK_DEVICE == ('lo' if oslayer.LINUX else None)


def test_sockets_are_not_confined_where_the_os_cannot(monkeypatch):
    from labkit.dds import sockets
    assert sockets.confine({}, True, device=None) == []
