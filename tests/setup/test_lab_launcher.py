"""`make lab` / `labkit lab`: JupyterLab opens without the "get notified about official
Jupyter news?" popup (the settings the launcher ships, read back from a running
server), passes --allow-root for root, and runs as a child process (no os.execv)."""
import json
import os
import secrets
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from labkit.tools import lab

ROOT = Path(__file__).resolve().parents[2]
PLUGIN = "@jupyterlab/apputils-extension:notification"


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_shipped_overrides_turn_news_and_update_checks_off():
    data = json.loads((lab.SETTINGS / "overrides.json").read_text(encoding="utf-8"))
    assert data[PLUGIN] == {"fetchNews": "false", "checkForUpdates": False}
    assert f"--LabApp.app_settings_dir={lab.SETTINGS}" in lab.command(Path("x"))


def test_root_gets_allow_root_and_others_do_not(monkeypatch):
    monkeypatch.setattr(lab, "is_root", lambda: True)
    assert lab.command(Path("x")).count("--allow-root") == 1
    assert lab.command(Path("x"), ["--allow-root"]).count("--allow-root") == 1
    monkeypatch.setattr(lab, "is_root", lambda: False)
    assert "--allow-root" not in lab.command(Path("x"))


def test_run_is_a_child_whose_exit_code_is_ours():
    code = "import os,sys; print(os.environ['LABKIT_TIME']); sys.exit(3)"
    env = dict(os.environ, LABKIT_TIME="live")
    assert lab.run([sys.executable, "-c", code], env=env) == 3
    assert "os.execv(" not in Path(lab.__file__).read_text(encoding="utf-8")


def test_running_lab_serves_news_off(tmp_path):
    """The launcher's own command, started for real: the notification plugin's composite
    settings default fetchNews to "false", so JupyterLab never asks."""
    port, token = _free_port(), secrets.token_hex(16)
    env = dict(os.environ, JUPYTER_RUNTIME_DIR=str(tmp_path / "runtime"),
               JUPYTERLAB_SETTINGS_DIR=str(tmp_path / "settings"),
               JUPYTERLAB_WORKSPACES_DIR=str(tmp_path / "workspaces"),
               JUPYTER_CONFIG_DIR=str(tmp_path / "config"))
    (tmp_path / "lab").mkdir()
    log = open(tmp_path / "lab.log", "wb")
    server = subprocess.Popen(
        lab.command(tmp_path / "lab", ["--no-browser", f"--port={port}", "--port-retries=0",
                                       f"--IdentityProvider.token={token}"]),
        env=env, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}/lab/api/settings/{PLUGIN}?token={token}"
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                with urllib.request.urlopen(url, timeout=5) as reply:
                    settings = json.loads(reply.read())
                break
            except OSError:
                if server.poll() is not None or time.monotonic() > deadline:
                    log.flush()
                    pytest.fail("JupyterLab did not start:\n" +
                                (tmp_path / "lab.log").read_text(errors="replace")[-2000:])
                time.sleep(0.3)
        # overrides become the schema's defaults, which the page composes with the
        # (empty) user settings: the popup shows only while fetchNews is "none"
        props = settings["schema"]["properties"]
        assert settings["settings"] == {}
        assert props["fetchNews"]["default"] == "false"
        assert props["checkForUpdates"]["default"] is False
    finally:
        server.terminate()
        try:
            server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()
        log.close()


def test_custom_css_is_installed_beside_the_learners_own_rules(tmp_path):
    """`labkit lab` loads custom.css (--LabApp.custom_css=True) and puts its rule for
    wide SVG pictures there, keeping the learner's own rules and never doubling."""
    assert "--LabApp.custom_css=True" in lab.command(tmp_path)
    mine = "body { font-size: 15px; }\n"
    (tmp_path / "custom").mkdir()
    (tmp_path / "custom" / "custom.css").write_text(mine, encoding="utf-8")
    path = lab.install_custom_css(tmp_path)
    lab.install_custom_css(tmp_path)
    text = path.read_text(encoding="utf-8")
    assert text.startswith(mine)
    assert text.count(lab.CSS_BEGIN) == 1 and text.count(lab.CSS_END) == 1
    assert ".jp-RenderedSVG img" in text and "max-width: 100%" in text
    fresh = lab.install_custom_css(tmp_path / "elsewhere")
    assert fresh.read_text(encoding="utf-8").startswith(lab.CSS_BEGIN)
