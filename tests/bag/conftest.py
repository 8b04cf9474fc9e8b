"""Bag tests run in a temporary folder (bags are written where the command runs)."""
import os
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SEED_PACKAGE = os.path.join(HERE, 'bag_recorder_nodes_py')


@pytest.fixture
def bag_dir(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # `ros2 bag info` prints local times: make them the same everywhere
    monkeypatch.setenv('TZ', 'UTC')
    _tzset()
    yield tmp_path
    monkeypatch.undo()  # TZ back first, then let the C library see it
    _tzset()


def _tzset():
    # POSIX only: Windows' C runtime reads TZ itself (time.tzset does not exist there)
    if hasattr(time, 'tzset'):
        time.tzset()


@pytest.fixture
def hook():
    from labkit import compat, plugins
    plugins.register_all()
    assert compat.activate(quiet=True)
    yield
    compat.deactivate()


@pytest.fixture
def seed_package(hook, monkeypatch):
    """The seed's chapter 20 package, as `colcon build` + `source` would make it runnable."""
    from labkit import executables, plugins
    plugins.register_all()
    monkeypatch.syspath_prepend(SEED_PACKAGE)
    for exe in ('simple_bag_recorder', 'data_generator_node', 'data_generator_executable'):
        monkeypatch.setitem(executables._extra, ('bag_recorder_nodes_py', exe),
                            f'bag_recorder_nodes_py.{exe}:main')
    yield
    for name in [m for m in sys.modules if m.startswith('bag_recorder_nodes_py')]:
        del sys.modules[name]
