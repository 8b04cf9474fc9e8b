"""Fixtures for launch tests: tests/workspace's workspaces, and the ch.21 launch_tutorial."""
import os
import shutil
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), 'workspace'))

from conftest_ws import clean_env, facer, ws  # noqa: E402,F401


def install_launch_tutorial(prefix):
    """The ch.21 package as colcon installs it: launch files in share/<pkg>/launch/,
    the YAML in share/<pkg>/config/, and the ament index marker."""
    share = os.path.join(prefix, 'share', 'launch_tutorial')
    shutil.copytree(os.path.join(HERE, 'seed21', 'launch'), os.path.join(share, 'launch'),
                    ignore=shutil.ignore_patterns('__pycache__'))
    shutil.copytree(os.path.join(HERE, 'seed21', 'config'), os.path.join(share, 'config'))
    marker = os.path.join(prefix, 'share', 'ament_index', 'resource_index', 'packages')
    os.makedirs(marker)
    open(os.path.join(marker, 'launch_tutorial'), 'w').close()
    return share


@pytest.fixture
def tutorial(ws, monkeypatch):
    """launch_tutorial installed in the workspace and sourced (AMENT_PREFIX_PATH)."""
    prefix = ws / 'install' / 'launch_tutorial'
    share = install_launch_tutorial(str(prefix))
    monkeypatch.setenv('AMENT_PREFIX_PATH', str(prefix))
    monkeypatch.setenv('USER', 'student')
    return share
