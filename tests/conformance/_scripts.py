"""Shared by record.py and test_conformance.py: where the scripts are and how to call them."""
import shlex
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCRIPTS = HERE / 'scripts'
EXPECTED = HERE / 'expected'
JAZZY = EXPECTED / 'jazzy'      # raw stdout of the Jazzy reference, before Humble edits
REFSHIM = HERE / 'refshim'      # reference-only stand-ins for packages Jazzy's wheels lack


def scripts():
    return sorted(p for p in SCRIPTS.glob('*.py') if not p.name.startswith('_'))


def script_args(path):
    """Command-line arguments a script wants, from an 'ARGS: ...' line in its docstring."""
    for line in Path(path).read_text(encoding='utf-8').splitlines():
        if line.startswith('ARGS:'):
            return shlex.split(line[len('ARGS:'):])
    return []


def script_env(path):
    """Extra environment from 'ENV: NAME=value' lines in a script's docstring."""
    env = {}
    for line in Path(path).read_text(encoding='utf-8').splitlines():
        if line.startswith('ENV:'):
            name, _, value = line[len('ENV:'):].strip().partition('=')
            env[name] = value
    return env


def merges_stderr(path):
    """'STREAMS: merged': the script's stderr (ROS log lines) is compared too."""
    return 'STREAMS: merged' in Path(path).read_text(encoding='utf-8')


def run(argv, path, env, timeout):
    """Run one script; returns (returncode, compared output, stderr)."""
    import subprocess
    merged = merges_stderr(path)
    result = subprocess.run(argv, env={**env, **script_env(path), 'PYTHONUNBUFFERED': '1'},
                            stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT if merged else subprocess.PIPE,
                            text=True, timeout=timeout, cwd=path.parent)
    return result.returncode, result.stdout, result.stderr or ''
