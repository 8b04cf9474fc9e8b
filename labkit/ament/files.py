"""A small sandbox "home folder" for the book, and the shell commands it needs.

A chapter that builds a workspace on disk does it in a throw-away folder next
to the notebook (`use_home('_work')`). Inside it, `~` means that folder, and
every path labkit prints shows it as the home of the container user, `/root`,
so the printed text is the same on every machine and reads like a terminal's:

    use_home('_work')          # ~ is now ./_work, shown as /root
    mkdir('~/ros2_ws/src')     # mkdir -p ~/ros2_ws/src
    cd('~/ros2_ws/src')        # cd ~/ros2_ws/src
    pwd()                      # /root/ros2_ws/src
    tree('~/ros2_ws')          # tree ~/ros2_ws
    leave_home()               # back to where we were; the folder is removed

Without a sandbox, `~` is the real home folder and paths print unchanged.
"""
import os
import shutil

from labkit import oslayer

SHOWN_HOME = oslayer.SHOWN_HOME

_home = None        # the real folder standing for ~ (absolute), or None
_created = None     # the outermost folder use_home() had to create
_previous_cwd = None


def use_home(folder, *, clean=True):
    """Make `folder` the sandbox home (created; emptied first when `clean`)."""
    global _home, _created, _previous_cwd
    real = os.path.abspath(folder)
    if clean and os.path.isdir(real):
        shutil.rmtree(real)
    _created = real
    while not os.path.exists(os.path.dirname(_created)):
        _created = os.path.dirname(_created)
    os.makedirs(real, exist_ok=True)
    if _previous_cwd is None:
        _previous_cwd = os.getcwd()
    _home = real
    os.chdir(real)          # a new terminal starts in the home folder
    # returns nothing: a notebook cell would print the path of this machine


def leave_home(*, remove=True):
    """Go back to the folder we were in before use_home(); remove the sandbox."""
    global _home, _created, _previous_cwd
    if _previous_cwd is not None:
        os.chdir(_previous_cwd)
    if remove and _home is not None and os.path.isdir(_home):
        shutil.rmtree(_home)
        # remove the empty parents use_home() created (`_work` of `_work/ch08`), no others
        folder = os.path.dirname(_home)
        while _created is not None and len(folder) >= len(_created):
            try:
                os.rmdir(folder)
            except OSError:
                break
            folder = os.path.dirname(folder)
    _home, _created, _previous_cwd = None, None, None


def home():
    """The real folder `~` stands for."""
    return _home if _home is not None else os.path.expanduser('~')


def expand(path):
    """`~` and `~/x` -> the real folder (as a shell expands them); inside the sandbox also
    the /root/... that labkit prints for it (typed back, it must open the same file);
    others unchanged."""
    path = os.fspath(path)
    if path == '~' or path.startswith('~/'):
        return oslayer.join_home(home(), path[2:])      # this OS's separators
    if _home is not None and (path == SHOWN_HOME or path.startswith(SHOWN_HOME + '/')):
        return oslayer.join_home(_home, path[len(SHOWN_HOME) + 1:])
    return path


def expand_arg(arg):
    """A command-line word naming a path as labkit printed it (/root/... in the sandbox)
    -> the real path; any other word (names, `key:=value`, options) unchanged."""
    if _home is None or not isinstance(arg, str):
        return arg
    return expand(arg) if arg == SHOWN_HOME or arg.startswith(SHOWN_HOME + '/') else arg


def display(path):
    """How a terminal in the sandbox would print `path` (relative paths stay relative)."""
    path = os.fspath(path)
    if path == '~' or path.startswith('~/'):
        path = expand(path)
    # /root/... inside the sandbox; '/' separators on every OS (`.\\pkg` -> `./pkg`)
    return oslayer.shown_path(path, _home if _home is not None and os.path.isabs(path) else None)


def display_abspath(path):
    return display(os.path.abspath(expand(path)))


# ----------------------------------------------------------------------------- shell commands

def write_text(path, text, mode=None):
    """Write a generated file (its folders made first), replacing a symlink left
    by --symlink-install instead of writing through it."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if oslayer.link_target(path) is not None:
        oslayer.remove(path)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text)
    if mode is not None:
        os.chmod(path, mode)


def mkdir(*paths):
    """`mkdir -p PATH...`"""
    for path in paths:
        os.makedirs(expand(path), exist_ok=True)


def cd(path='~'):
    """`cd PATH`"""
    os.chdir(expand(path))


def pwd():
    """`pwd`"""
    print(display(os.getcwd()))


def ls(*args, all=False):
    """`ls [-a|-A] [PATH]` (names sorted, one line, like ls when its output is not a
    terminal's). Names starting with a dot are shown only with -a (which adds . and
    ..), -A or all=True, as ls does."""
    options = [a for a in args if a.startswith('-') and len(a) > 1]
    paths = [a for a in args if a not in options] or ['.']
    for option in options:
        if option not in ('-a', '-A'):
            raise ValueError(f'ament.ls knows -a and -A, not {option}')
    for path in paths:
        names = os.listdir(expand(path))
        if '-a' in options or '-A' in options or all:
            names += ['.', '..'] if '-a' in options else []
        else:
            names = [n for n in names if not n.startswith('.')]
        print('  '.join(sorted(names)))


def cat(path):
    """`cat PATH`"""
    with open(expand(path), encoding='utf-8') as f:
        print(f.read(), end='')


def tree_lines(path='.'):
    """The lines `tree PATH` prints: entries sorted by name (C locale), then the counts."""
    real = expand(path)
    lines = [display(path)]
    counts = {'dirs': 0, 'files': 0}

    def walk(folder, prefix):
        # like tree without -a: hidden entries are left out; a link shows its target
        names = sorted(n for n in os.listdir(folder) if not n.startswith('.'))
        for i, name in enumerate(names):
            last = i == len(names) - 1
            full = os.path.join(folder, name)
            label = name
            target = oslayer.link_target(full)     # also a link the OS made a copy of
            if target is not None:
                label += ' -> ' + (display(target) if os.path.isabs(target) else target)
            lines.append(prefix + ('└── ' if last else '├── ') + label)
            if os.path.isdir(full):
                counts['dirs'] += 1
                if target is None:
                    walk(full, prefix + ('    ' if last else '│   '))
            else:
                counts['files'] += 1

    walk(real, '')
    d, f = counts['dirs'], counts['files']
    lines += ['', f"{d} director{'y' if d == 1 else 'ies'}, {f} file{'' if f == 1 else 's'}"]
    return lines


def tree(path='.'):
    """`tree PATH`"""
    print('\n'.join(tree_lines(path)))
