"""`%colcon ...`, `%source ...`, `%rosdep ...` in a notebook (registered by labkit.ament)."""
import sys


def _emit(result):
    from labkit.commands import emit
    emit(result)


def _words(line):
    """The line's words as bash splits them: quotes, and a `#` that begins a word starts
    a comment (`a#b` and `"# x"` are kept, as bash keeps them)."""
    from labkit import oslayer
    return oslayer.split_args(line, comments=True)


def colcon_magic(line):
    """%colcon build [options]: build the workspace in the current folder."""
    from labkit.ament.colcon import run_command
    _emit(run_command(_words(line)))


def source_magic(line):
    """%source install/setup.bash: make a built workspace visible."""
    from labkit.ament.source import run
    words = _words(line)
    if not words:
        print('bash: source: filename argument required', file=sys.stderr)
        return
    run(words[0])


def rosdep_magic(line):
    """%rosdep install --from-paths src -y --ignore-src"""
    from labkit.ament.rosdep import run_command
    _emit(run_command(_words(line)))


MAGICS = {'colcon': colcon_magic, 'source': source_magic, 'rosdep': rosdep_magic}
