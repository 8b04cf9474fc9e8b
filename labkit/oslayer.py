"""The one seam between labkit and the operating system it runs on.

Everything that differs between Linux, macOS and Windows lives here, each with a fallback
per platform, and the rooms call it instead of the OS:

- `split_args`: a command line typed in the book -> argv. POSIX rules (shlex) on Linux and
  macOS; on Windows a backslash is a path separator, never an escape, so
  `ros2 param load /n C:\\ws\\p.yaml` keeps its path (quotes still group words).
- `symlink` / `remove`: colcon's `log/latest*` links and `--symlink-install`. Where the OS
  refuses a symbolic link (Windows without Developer Mode: WinError 1314), a folder becomes
  a directory junction (or a copy) and a file a copy; what the book prints is unchanged.
- `terminal_keys`: raw key presses for the teleop programs: termios on POSIX, msvcrt on
  Windows (its arrow keys are translated to the ESC [ A..D that a Linux terminal sends).
- `exec_replace`, `stop_process`, `KILL_SIGNAL`: starting, replacing and stopping OS
  processes (Windows has no exec and no SIGKILL).
- `shown_path` / `join_home`: the simulated Ubuntu paths the book prints (`/root/...`,
  `./pkg`): forward slashes on every OS.
- DDS loopback: `LOOPBACK_ADDRESS` (an address works on every OS; the interface is `lo`
  on Linux, `lo0` on macOS and has no such name on Windows) and `LOOPBACK_DEVICE`, the
  Linux-only confinement of DDS sockets to the loopback device (SO_BINDTODEVICE);
  `SOCKETS_CONFINABLE` tells whether this OS can do it.
- `open_text`: text files are always UTF-8 (a Chinese Windows' default is GBK).
"""
import errno
import os
import shlex
import shutil
import signal
import subprocess
import sys
import threading
import time

WINDOWS = os.name == 'nt'
MACOS = sys.platform == 'darwin'
LINUX = sys.platform.startswith('linux')

# ----------------------------------------------------------------------------- text files

ENCODING = 'utf-8'


def open_text(path, mode='r', **kwargs):
    """open() of a text file, always UTF-8."""
    kwargs.setdefault('encoding', ENCODING)
    return open(path, mode, **kwargs)


# ----------------------------------------------------------------------------- arguments

def split_args(text, *, windows=None, punctuation_chars=False, comments=False):
    """A command line -> its words, as the learner's shell splits them.

    POSIX shells (Linux, macOS): shlex's POSIX rules (quotes, backslash escapes).
    Windows (`windows=True`, the default there): the same quoting, but a backslash is
    kept as it is typed (it separates path parts). `punctuation_chars` is shlex's (a `>`
    redirection); with `comments`, a `#` that begins a word starts a comment, as in
    bash (`a#b` and a quoted `#` are kept)."""
    windows = WINDOWS if windows is None else windows
    if comments:
        text = strip_comment(text, windows=windows)
    lexer = shlex.shlex(text, posix=True, punctuation_chars=punctuation_chars)
    lexer.whitespace_split = True
    lexer.commenters = ''
    if windows:
        lexer.escape = ''
    return list(lexer)


def strip_comment(line, *, windows=None):
    """The line up to a bash comment: a `#` outside quotes that begins a word."""
    windows = WINDOWS if windows is None else windows
    quote, escaped, blank = None, False, True     # blank: the next character begins a word
    for i, ch in enumerate(line):
        if escaped:
            escaped, blank = False, False
        elif ch == '\\' and quote != "'" and not windows:
            escaped = True
        elif quote:
            quote = None if ch == quote else quote
        elif ch in '"\'':
            quote, blank = ch, False
        elif ch == '#' and blank:
            return line[:i]
        else:
            blank = ch.isspace()
    return line


def quote_arg(arg):
    """One word as the book prints it in a shell command (bash quoting on every OS)."""
    return shlex.quote(arg)


# ----------------------------------------------------------------------------- symlinks

# WinError 1314: "A required privilege is not held by the client" (no Developer Mode)
_REFUSED_WINERRORS = (1314,)
_REFUSED_ERRNOS = (errno.EPERM, errno.EACCES, errno.ENOSYS, errno.EOPNOTSUPP)


def _refused(exc):
    if isinstance(exc, NotImplementedError):
        return True
    if getattr(exc, 'winerror', None) in _REFUSED_WINERRORS:
        return True
    return isinstance(exc, OSError) and exc.errno in _REFUSED_ERRNOS


# links this process had to make as junctions or copies: {abspath: target as asked}, so
# that `tree` still prints `latest -> latest_build` as on Linux
_stand_ins = {}


def _junction(target, path):
    import _winapi                       # Windows only
    _winapi.CreateJunction(target, path)


def symlink(target, path, *, target_is_directory=None):
    """`ln -s target path` (target relative to path's folder, as a symlink's is).

    Returns how it was made: 'symlink', or where the OS refuses symbolic links,
    'junction' (a folder, on Windows) or 'copy'."""
    full = target if os.path.isabs(target) else os.path.join(os.path.dirname(path) or '.', target)
    is_dir = os.path.isdir(full) if target_is_directory is None else target_is_directory
    try:
        os.symlink(target, path, target_is_directory=is_dir)
        if os.path.lexists(path):
            return 'symlink'
        # Wine 8's CreateSymbolicLinkW says yes and makes nothing: treat it as refused
    except (OSError, NotImplementedError) as exc:
        if not _refused(exc):
            raise
    full = os.path.realpath(full)
    how = 'copy'
    if is_dir:
        try:
            if not WINDOWS:
                raise OSError('junctions are a Windows thing')
            _junction(full, path)
            how = 'junction'
        except OSError:
            if os.path.isdir(path) and not os.listdir(path):
                os.rmdir(path)      # CreateJunction made the folder, then failed (Wine)
            shutil.copytree(full, path, symlinks=False)
    else:
        shutil.copy2(full, path)
    _stand_ins[os.path.abspath(path)] = os.fspath(target)
    return how


def refresh(path):
    """A link that had to be a copy shows its target again (a copy of a folder is taken
    once; a link would show what was written there since). Nothing for a real link."""
    target = _stand_ins.get(os.path.abspath(path))
    if target is None or is_link(path) or not os.path.isdir(path):
        return
    full = target if os.path.isabs(target) else os.path.join(os.path.dirname(path), target)
    shutil.copytree(full, path, symlinks=False, dirs_exist_ok=True)


def link_target(path):
    """What `readlink path` prints: the target of a symbolic link, or of a link this
    process had to make as a junction or a copy; None for anything else."""
    if os.path.islink(path):
        return os.readlink(path)
    if not os.path.lexists(path):
        return None
    return _stand_ins.get(os.path.abspath(path))


def is_link(path):
    """A symbolic link or a directory junction."""
    if os.path.islink(path):
        return True
    isjunction = getattr(os.path, 'isjunction', None)        # Python >= 3.12
    if isjunction is not None:
        return isjunction(path)
    try:
        st = os.lstat(path)
    except OSError:
        return False
    return bool(getattr(st, 'st_reparse_tag', 0))


def remove(path):
    """Remove what is at `path` (a link, a junction, a file or a copied folder); nothing
    when there is nothing. A link is removed, never what it points to."""
    if not os.path.lexists(path):
        return
    _stand_ins.pop(os.path.abspath(path), None)
    if is_link(path):
        try:
            os.unlink(path)
        except (IsADirectoryError, PermissionError):
            os.rmdir(path)               # a junction on older Windows Pythons
    elif os.path.isdir(path):
        shutil.rmtree(path)
    else:
        os.unlink(path)


def replace_link(target, path, **kwargs):
    """`ln -sfn target path`: what was at `path` goes first."""
    remove(path)
    return symlink(target, path, **kwargs)


# ----------------------------------------------------------------------------- paths shown

SHOWN_HOME = '/root'


def join_home(home, tail):
    """`~/a/b` with ~ = `home` -> a real path with this OS's separators ('' -> home)."""
    parts = [p for p in tail.split('/') if p]
    return os.path.join(home, *parts) if parts else home


def shown_path(path, home=None, *, sep=None):
    """How a Linux terminal prints `path`: inside the sandbox `home` as /root/...,
    separators as '/'. A relative path stays relative (`.\\pkg` -> `./pkg`)."""
    sep = os.sep if sep is None else sep
    path = os.fspath(path)
    if home is not None:
        if path == home:
            return SHOWN_HOME
        if path.startswith(home.rstrip(sep) + sep):
            return SHOWN_HOME + '/' + path[len(home.rstrip(sep)) + 1:].replace(sep, '/')
    if sep != '/' and not _is_abs_windows(path):
        return path.replace(sep, '/')
    return path


def slashes_after(text, starts, *, sep=None):
    """In text holding paths: the part of each path after one of `starts` (e.g. '/root/')
    written with '/' (`/root/ws\\install` -> `/root/ws/install`)."""
    import re
    sep = os.sep if sep is None else sep
    if sep == '/':
        return text
    alternatives = '|'.join(re.escape(s) for s in starts)
    return re.sub(f'({alternatives})([^\\s;"\']*)',
                  lambda m: m.group(1) + m.group(2).replace(sep, '/'), text)


def _is_abs_windows(path):
    return len(path) >= 2 and path[1] == ':' or path.startswith('\\\\')


# ----------------------------------------------------------------------------- terminal keys

# msvcrt.getwch() gives '\x00' or '\xe0' then one of these for the arrow keys
_WINDOWS_ARROWS = {'H': 'A', 'P': 'B', 'M': 'C', 'K': 'D'}


def decode_windows_keys(chars):
    """Characters from msvcrt.getwch() -> what a Linux terminal sends for the same keys
    (arrows become ESC [ A..D; other prefixed keys are dropped; Enter is '\\n')."""
    out, i = [], 0
    while i < len(chars):
        ch = chars[i]
        if ch in ('\x00', '\xe0'):
            if i + 1 < len(chars) and chars[i + 1] in _WINDOWS_ARROWS:
                out.append('\x1b[' + _WINDOWS_ARROWS[chars[i + 1]])
            i += 2
            continue
        out.append('\n' if ch == '\r' else ch)
        i += 1
    return ''.join(out)


class _PosixKeys:
    def __init__(self, press, done, pass_ctrl_c, name):
        import termios
        self.press, self.done = press, done
        self.fd = sys.stdin.fileno()
        self.cooked = termios.tcgetattr(self.fd)
        raw = termios.tcgetattr(self.fd)
        raw[3] &= ~(termios.ICANON | termios.ECHO | (termios.ISIG if pass_ctrl_c else 0))
        raw[6][termios.VMIN] = 0
        raw[6][termios.VTIME] = 1          # read() returns after 0.1 s without a key
        termios.tcsetattr(self.fd, termios.TCSANOW, raw)
        self.thread = threading.Thread(target=self._loop, name=name, daemon=True)
        self.thread.start()

    def _loop(self):
        while not self.done():
            data = os.read(self.fd, 1)
            if data:
                self.press(data.decode('latin-1'))

    def close(self):
        import termios
        termios.tcsetattr(self.fd, termios.TCSANOW, self.cooked)


class _WindowsKeys:
    """msvcrt reads the console's keys without echo and without waiting for Enter."""

    def __init__(self, press, done, pass_ctrl_c, name, *, msvcrt=None):
        if msvcrt is None:
            import msvcrt
        self.msvcrt, self.press, self.done = msvcrt, press, done
        self.thread = threading.Thread(target=self._loop, name=name, daemon=True)
        self.thread.start()

    def _loop(self):
        while not self.done():
            if not self.msvcrt.kbhit():
                time.sleep(0.02)
                continue
            chars = self.msvcrt.getwch()
            if chars in ('\x00', '\xe0'):
                chars += self.msvcrt.getwch()
            for ch in decode_windows_keys(chars):
                self.press(ch)

    def close(self):
        pass


def terminal_keys(press, done, *, pass_ctrl_c=False, name='teleop-tty'):
    """Raw single key presses of the controlling terminal: `press(char)` on a thread
    until `done()`; `.close()` restores the terminal. None when stdin is no terminal."""
    try:
        if sys.stdin is None or not sys.stdin.isatty():
            return None
        if WINDOWS:
            return _WindowsKeys(press, done, pass_ctrl_c, name)
        return _PosixKeys(press, done, pass_ctrl_c, name)
    except (OSError, ValueError, ImportError):
        return None


# ----------------------------------------------------------------------------- processes

# Windows has no SIGKILL: TerminateProcess (what Popen.kill does) is its nearest
KILL_SIGNAL = getattr(signal, 'SIGKILL', signal.SIGTERM)


# what glibc's strsignal() says for Linux's signal numbers (the simulated processes' exit
# codes are Humble's: -6 is SIGABRT on Linux, while Windows numbers its signals otherwise)
_LINUX_SIGNALS = {1: 'Hangup', 2: 'Interrupt', 3: 'Quit', 4: 'Illegal instruction',
                  5: 'Trace/breakpoint trap', 6: 'Aborted', 7: 'Bus error',
                  8: 'Floating point exception', 9: 'Killed', 10: 'User defined signal 1',
                  11: 'Segmentation fault', 12: 'User defined signal 2', 13: 'Broken pipe',
                  14: 'Alarm clock', 15: 'Terminated'}


def linux_signal_description(signum):
    """strsignal() of a Linux signal number, on every OS; None for an unknown one."""
    if LINUX:
        try:
            return signal.strsignal(signum)
        except ValueError:
            return None
    return _LINUX_SIGNALS.get(signum)


def exec_replace(argv, env=None):
    """Become `argv` (os.execv on POSIX). Windows has no exec that keeps the console and
    the exit code: run it as a child, wait, and exit with its code."""
    if not WINDOWS:
        if env is None:
            os.execv(argv[0], argv)
        os.execve(argv[0], argv, env)
    try:
        code = subprocess.call(argv, env=env)
    except KeyboardInterrupt:
        code = 130
    sys.exit(code)


def new_group_options():
    """Popen options that start a child in its own process group (so stopping it does not
    stop us, and Ctrl-C in our terminal is ours)."""
    if WINDOWS:
        return {'creationflags': subprocess.CREATE_NEW_PROCESS_GROUP}
    return {'start_new_session': True}


def stop_process(proc, timeout=10.0):
    """Ask a Popen child to stop (SIGINT on POSIX like Ctrl-C, CTRL_BREAK on Windows for a
    child started with new_group_options(), else terminate), wait `timeout`, then kill.
    Returns its exit code."""
    if proc.poll() is not None:
        return proc.returncode
    try:
        if WINDOWS:
            proc.send_signal(getattr(signal, 'CTRL_BREAK_EVENT', signal.SIGTERM))
        else:
            proc.send_signal(signal.SIGINT)
    except (OSError, ValueError, SystemError):    # Wine: CTRL_BREAK -> WinError 12
        proc.terminate()
    try:
        return proc.wait(timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        return proc.wait()


# ----------------------------------------------------------------------------- DDS loopback

# Cyclone's localhost mode names the loopback by address: every OS has 127.0.0.1, while
# the interface is `lo` on Linux, `lo0` on macOS and has no such name on Windows.
LOOPBACK_ADDRESS = '127.0.0.1'
# Linux only: the device that Cyclone's wildcard receive sockets are bound to
# (SO_BINDTODEVICE, labkit.dds.sockets); elsewhere sockets cannot be confined so.
LOOPBACK_DEVICE = 'lo' if LINUX else None
SOCKETS_CONFINABLE = LINUX and hasattr(__import__('socket'), 'SO_BINDTODEVICE')
