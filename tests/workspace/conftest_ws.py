"""Workspace fixtures, shared by tests/workspace and tests/launch.

A throw-away workspace folder, and everything `source` changes put back afterwards.
"""
import sys

import pytest


WORKSPACE_MODULES = ('facer_', 'ws_')


@pytest.fixture
def clean_env(monkeypatch):
    """Undo what sourcing a workspace does: env vars, sys.path, executables, interfaces."""
    from labkit import plugins
    plugins.register_all()      # ament_index_python, launch names; magics; ros2 launch
    from labkit import compat, executables
    from labkit.interfaces import registry
    for var in ('AMENT_PREFIX_PATH', 'PYTHONPATH', 'COLCON_PREFIX_PATH'):
        monkeypatch.delenv(var, raising=False)
    was_active = compat.is_active()
    compat.activate()
    saved_path = list(sys.path)
    saved_exe = dict(executables._extra)
    saved_overlaid = set(executables._overlaid)
    saved_roots = registry.share_paths()
    yield
    sys.path[:] = saved_path
    executables._extra.clear()
    executables._extra.update(saved_exe)
    executables._overlaid.clear()
    executables._overlaid.update(saved_overlaid)
    for root in registry.share_paths():
        if root not in saved_roots:
            registry.remove_share_path(root)
    for key in [k for k in sys.modules if k.startswith(WORKSPACE_MODULES)]:
        del sys.modules[key]
    if not was_active:
        compat.deactivate()


@pytest.fixture
def ws(tmp_path, monkeypatch, clean_env):
    """An empty workspace folder as the current directory."""
    folder = tmp_path / 'ros2_ws'
    (folder / 'src').mkdir(parents=True)
    monkeypatch.chdir(folder)
    return folder


@pytest.fixture
def facer(ws):
    import facer_ws
    facer_ws.facer_workspace(str(ws))
    return ws
