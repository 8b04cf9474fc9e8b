"""`%ros2 topic echo /x > file`: a background job's stdout keeps going to the file."""
import pytest

import labkit
from labkit import compat


@pytest.fixture
def shell():
    from IPython.core.interactiveshell import InteractiveShell
    ip = InteractiveShell.instance()
    if 'labkit' not in ip.extension_manager.loaded:
        ip.run_line_magic('load_ext', 'labkit')
    labkit.reset()
    yield ip
    labkit.reset()
    compat.deactivate()


def test_background_job_output_goes_to_the_file(shell, tmp_path, capsys):
    shell.run_line_magic('ros2', 'run turtlesim turtlesim_node')
    target = tmp_path / 'pose.txt'
    shell.run_line_magic('ros2', f'topic echo /turtle1/pose > {target}')
    capsys.readouterr()
    labkit.sleep(0.2)                      # the echo prints ~12 poses meanwhile
    shown = capsys.readouterr().out
    assert target.read_text().count('---') >= 5
    assert 'theta:' not in shown           # nothing of it reaches the notebook
