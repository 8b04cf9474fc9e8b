"""The book's own node listings on real rclpy: every `%%writefile ....py` cell of a
notebook that defines `main` and imports only what the real wheels in .venv-rosref have
(rclpy, std_msgs, geometry_msgs, sensor_msgs, std_srvs, rcl_interfaces, the standard
library) runs under real rclpy and under `labkit exec` (book_listing_probe.py: spin for a
moment, report, then Ctrl+C) and makes the same nodes, topics, services and parameters,
and logs and prints the same first lines. New listings are picked up by themselves.

Jazzy vs Humble (the wheels are Jazzy; labkit is Humble), taken out before comparing:
- Jazzy nodes offer `~/get_type_description` and declare `start_type_description_service`
  (REP 2011 type descriptions, not in Humble).
"""
import glob
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ROSREF = Path(os.environ.get('ROSREF_PYTHON', REPO / '.venv-rosref' / 'bin' / 'python'))
PROBE = Path(__file__).with_name('book_listing_probe.py')
SECONDS = 1.5
REAL_MODULES = ('rclpy', 'std_msgs', 'geometry_msgs', 'sensor_msgs', 'std_srvs',
                'rcl_interfaces', 'builtin_interfaces')
STDLIB = set(getattr(sys, 'stdlib_module_names', ()))
JAZZY_ONLY_SERVICES = ('/get_type_description',)
JAZZY_ONLY_PARAMETERS = ('start_type_description_service',)


def _listings():
    found = []
    for path in sorted(glob.glob(str(REPO / 'book' / '*' / '*.ipynb'))):
        with open(path, encoding='utf-8') as f:
            cells = json.load(f)['cells']
        for index, cell in enumerate(cells):
            source = ''.join(cell['source'])
            m = re.match(r'%%writefile\s+(\S+\.py)\s*\n', source)
            if cell['cell_type'] != 'code' or not m or 'def main' not in source:
                continue
            body = source[m.end():]
            imports = {name.split('.')[0] for name in
                       re.findall(r'^\s*(?:from|import)\s+([\w.]+)', body, re.M)}
            if 'rclpy' in imports and all(i in REAL_MODULES or i in STDLIB for i in imports):
                found.append(pytest.param(body, id=f'{Path(path).stem}-{index}-'
                                                    f'{Path(m.group(1)).stem}'))
    return found


LISTINGS = _listings()
_domains = iter(range(150 + os.getpid() % 40, 233))
LOG = re.compile(r'^\[(\w+)\] \[[\d.]+\] \[([^\]]+)\]: (.*)$')


def _start(python_cmd, listing, env):
    return subprocess.Popen([*python_cmd, str(PROBE), str(listing), str(SECONDS)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            cwd=str(listing.parent))


def _result(proc):
    out, err = proc.communicate(timeout=60)
    probe = [json.loads(line[6:]) for line in out.splitlines() if line.startswith('PROBE ')]
    prints = [line for line in out.splitlines() if not line.startswith('PROBE ')]
    logs = [LOG.match(line).groups() for line in err.splitlines() if LOG.match(line)]
    return probe[0] if probe else None, prints, logs, err


def _humble(report):
    for node in report:
        node['services'] = [s for s in node['services'] if not s.endswith(JAZZY_ONLY_SERVICES)]
        node['parameters'] = [p for p in node['parameters']
                              if p not in JAZZY_ONLY_PARAMETERS]
    return report


@pytest.mark.skipif(not ROSREF.exists(), reason='no real-ROS reference venv (make rosref)')
@pytest.mark.parametrize('body', LISTINGS)
def test_listing_behaves_as_on_real_rclpy(tmp_path, body):
    listing = tmp_path / 'listing.py'
    listing.write_text(body, encoding='utf-8')
    base = {k: v for k, v in os.environ.items() if not k.startswith(('LABKIT_', 'ROS_'))}
    real_env = dict(base, ROS_DOMAIN_ID=str(next(_domains)),
                    ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', PYTHONUNBUFFERED='1')
    real_env.pop('PYTHONPATH', None)
    labkit_env = dict(base, LABKIT_TIME='live', LABKIT_DDS='off', PYTHONUNBUFFERED='1',
                      PYTHONPATH=str(REPO))
    started = time.monotonic()
    real = _start([str(ROSREF)], listing, real_env)
    ours = _start([sys.executable, '-m', 'labkit', 'exec'], listing, labkit_env)
    real_report, real_prints, real_logs, real_err = _result(real)
    our_report, our_prints, our_logs, our_err = _result(ours)
    assert real_report is not None, real_err
    assert our_report is not None, our_err
    assert _humble(real_report) == our_report
    # what a timer printed depends on how long each ran: the first lines must agree
    for real_lines, our_lines in ((real_prints, our_prints), (real_logs, our_logs)):
        n = min(len(real_lines), len(our_lines), 3)
        assert our_lines[:n] == real_lines[:n]
        assert bool(real_lines) == bool(our_lines), (real_lines, our_lines)
    assert time.monotonic() - started < 30


def test_listings_are_found():
    assert len(LISTINGS) >= 5
