"""Shared by the benchmarks: run a worker under labkit or under the real-rclpy reference.

A benchmark file is a plain rclpy program when started with `--worker`: it prints one
JSON line of figures. The front end runs it twice, `python -m labkit exec FILE --worker`
and, when the reference venv exists, `<reference python> FILE --worker`.
"""
import json
import os
import random
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
# the reference venv `make setup` builds where real rclpy's wheels exist (benchmarks/README.md)
DEFAULT_REFERENCE = str(REPO / '.venv-rosref' / ('Scripts/python.exe' if os.name == 'nt'
                                                 else 'bin/python'))


def reference_python():
    """The real-rclpy interpreter ($ROSREF_PYTHON, else the default venv), or None."""
    python = os.environ.get('ROSREF_PYTHON', DEFAULT_REFERENCE)
    return python if Path(python).exists() else None


def run_worker(argv, env_extra=None, timeout=300):
    env = dict(os.environ, PYTHONUNBUFFERED='1', **(env_extra or {}))
    result = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=timeout)
    for line in reversed(result.stdout.splitlines()):
        if line.startswith('{'):
            return json.loads(line)
    raise RuntimeError(f'worker failed ({result.returncode}):\n{result.stderr[-2000:]}')


def run_labkit(script, time_mode='live', args=()):
    return run_worker([sys.executable, '-m', 'labkit', 'exec', '--time', time_mode,
                       str(script), '--worker', *args],
                      {'PYTHONPATH': str(REPO), 'LABKIT_TIME': time_mode})


def run_reference(script, args=()):
    python = reference_python()
    if python is None:
        return None
    return run_worker([python, str(script), '--worker', *args], {
        'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',  # DDS stays on this host
        'ROS_DOMAIN_ID': str(random.randint(1, 100)),
        'PYTHONPATH': '',
    })


def emit(figures):
    print(json.dumps(figures))


def percentile(values, fraction):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(fraction * (len(ordered) - 1))))]
