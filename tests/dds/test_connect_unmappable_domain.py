"""labkit.connect() / %ros2 connect on a domain DDS cannot map to UDP ports (233+: Fast DDS,
Humble's default rmw, computes 7400 + 250 * domain + offsets > 65535 and refuses the
participant with one line). In a notebook that one line is all the reader sees: no
traceback, nothing joined, no thread left, ROS_DOMAIN_ID untouched. Before, the cell showed
a traceback ending in labkit's own 'Domain id 240 is out of range' sentence."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
LINE = ('Calculated port number is too high. Probably the domainId is over 232 '
        'or portBase is too high.')

# an IPython shell runs the cells as a notebook kernel does (showtraceback included)
NOTEBOOK = r'''
import os, threading
from IPython.core.interactiveshell import InteractiveShell
ip = InteractiveShell.instance(colors='NoColor')
ip.run_cell('import labkit')
ip.run_cell("labkit.set_time_mode('live')")
before = os.environ.get('ROS_DOMAIN_ID')
print('--- cell')
ip.run_cell(CELL)
print('--- after')
from labkit import dds
print('connected', dds.is_connected())
print('threads', sorted(t.name for t in threading.enumerate()
                        if t.name not in ('MainThread', 'IPythonHistorySavingThread')))
print('domain kept', os.environ.get('ROS_DOMAIN_ID') == before)
'''


def _run(cell, **env):
    program = 'CELL = %r\n' % cell + NOTEBOOK
    full = dict(os.environ, PYTHONPATH=str(REPO), LABKIT_DDS='on', LABKIT_TIME='live', **env)
    done = subprocess.run([sys.executable, '-c', program], capture_output=True, text=True,
                          timeout=120, env=full, cwd=REPO)
    assert done.returncode == 0, done.stderr
    return done.stdout.split('--- cell\n', 1)[1]


AFTER = "--- after\nconnected False\nthreads []\ndomain kept True\n"


@pytest.mark.parametrize('cell', ['labkit.connect(domain_id=240)',
                                  'labkit.connect(domain_id=233, localhost_only=True)'])
def test_notebook_connect_refuses_in_one_line(cell):
    assert _run(cell) == LINE + '\n' + AFTER


def test_notebook_connect_with_ros_domain_id_from_the_environment():
    assert _run('labkit.connect()', ROS_DOMAIN_ID='250') == LINE + '\n' + AFTER


def test_ros2_connect_magic_refuses_in_one_line():
    out = _run("r = labkit.ros2('connect 240'); print(r.returncode, repr(r.stdout), "
               "repr(r.stderr))")
    assert out == f"1 '' {LINE + chr(10)!r}\n" + AFTER


def test_domain_232_is_not_refused_by_this_check():
    from labkit import dds
    dds._refuse_unmappable(232)
    dds._refuse_unmappable(0)
    with pytest.raises(dds.UnmappableDomain) as e:
        dds._refuse_unmappable(233)
    assert str(e.value) == LINE and isinstance(e.value, dds.ConfigError)
