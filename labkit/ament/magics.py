"""`%colcon ...`, `%source ...`, `%rosdep ...` in a notebook (registered by labkit.ament)."""
import sys


def _emit(result):
    from labkit.commands import emit
    emit(result)


def colcon_magic(line):
    """%colcon build [options]: build the workspace in the current folder."""
    from labkit.ament.colcon import run_command
    _emit(run_command(line))


def source_magic(line):
    """%source install/setup.bash: make a built workspace visible."""
    from labkit.ament.source import run
    path = line.strip()
    if not path:
        print('bash: source: filename argument required', file=sys.stderr)
        return
    run(path)


def rosdep_magic(line):
    """%rosdep install --from-paths src -y --ignore-src"""
    from labkit.ament.rosdep import run_command
    _emit(run_command(line))


MAGICS = {'colcon': colcon_magic, 'source': source_magic, 'rosdep': rosdep_magic}
