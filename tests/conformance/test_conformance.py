"""Each conformance script, run on labkit, prints exactly what real rclpy printed.

The expected files were recorded on the real rclpy reference (record.py) and hold
Humble's behaviour where Humble and Jazzy differ (each script's docstring says where).
Every script runs in both time modes: virtual (the book's CI) and live (a reader's lab).
"""
import difflib
import os
import subprocess
import sys

import pytest

from _scripts import EXPECTED, HERE, JAZZY, run, script_args, scripts

SCRIPTS = scripts()
REPO = HERE.parents[1]
TIMEOUT_S = 30  # each script takes at most a few seconds on real rclpy


def run_on_labkit(path, time_mode):
    env = dict(os.environ, LABKIT_TIME=time_mode)
    # this tree's labkit (not whatever an editable install points at), never the
    # reference-only shim: labkit bundles example_interfaces itself
    env['PYTHONPATH'] = str(REPO)
    try:
        return run([sys.executable, '-m', 'labkit', 'exec', '--time', time_mode, str(path),
                    *script_args(path)], path, env, TIMEOUT_S)
    except subprocess.TimeoutExpired as e:  # run() has killed it
        out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or '')
        return 'timeout', out, f'still running after {TIMEOUT_S} s: killed'


def test_every_script_has_an_expected_file():
    assert SCRIPTS, 'no conformance scripts found'
    missing = [p.stem for p in SCRIPTS if not (EXPECTED / f'{p.stem}.txt').exists()]
    assert not missing


def test_humble_edits_are_documented():
    """An expected file may differ from the raw Jazzy recording only where its script
    says how Humble and Jazzy differ."""
    undocumented = []
    for path in SCRIPTS:
        raw = JAZZY / f'{path.stem}.txt'
        if not raw.exists():
            undocumented.append(f'{path.stem}: no Jazzy recording')
        elif raw.read_text(encoding='utf-8') != (EXPECTED / f'{path.stem}.txt').read_text(
                encoding='utf-8') and 'Humble/Jazzy' not in path.read_text(encoding='utf-8'):
            undocumented.append(path.stem)
    assert not undocumented


@pytest.mark.parametrize('time_mode', ['virtual', 'live'])
@pytest.mark.parametrize('path', SCRIPTS, ids=[p.stem for p in SCRIPTS])
def test_script_output_matches_real_rclpy(path, time_mode):
    expected = (EXPECTED / f'{path.stem}.txt').read_text(encoding='utf-8')
    returncode, output, stderr = run_on_labkit(path, time_mode)
    diff = '\n'.join(difflib.unified_diff(
        expected.splitlines(), output.splitlines(), 'real rclpy (Humble)', 'labkit',
        lineterm=''))
    if output != expected or returncode != 0:
        pytest.fail(f'exit code {returncode}\n{diff}\n--- stderr (tail) ---\n'
                    + '\n'.join(stderr.splitlines()[-25:]), pytrace=False)
