"""The book in live JupyterLab, as a learner uses it: `make lab`'s server
(labkit.tools.lab, LABKIT_TIME=live) on 127.0.0.1, a short notebook run cell by
cell in headless Chromium, and what the learner then sees in each cell.

A background job's lines (`%ros2 topic pub --rate`), and those of a node the
notebook starts itself (`process.start`), belong to their own output areas in
the cells that started them: the next cells show only what they print
themselves, also while the others go on printing; `.stop()` stops them.
Everything is stopped at the end (kernel, server, browser)."""

from __future__ import annotations

import json
import os
import secrets
import socket
import subprocess
import sys
import time
import urllib.request

import pytest

from book_support import ROOT, missing

# Every cell the learner runs. The job prints 20 lines a second, the node the
# notebook starts itself logs 20 lines a second; the cells after them must not
# get any of those lines.
NODE = """import rclpy
from rclpy.node import Node
from labkit import process


class Chatty(Node):
    def __init__(self):
        super().__init__("chatty")
        self.create_timer(0.05, lambda: self.get_logger().info("tick"))


def main():
    rclpy.init()
    node = Chatty()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


chatty = process.start(main=main, name="chatty")"""
CELLS = [
    "%load_ext labkit\nimport labkit",
    'pub = %ros2 topic pub --rate 20 /chatter std_msgs/msg/String "{data: hello}"',
    NODE,
    'labkit.sleep(1.0)\nprint("the next cell")',
    "pub.stop()\nchatty.stop()\nprint(pub.state, chatty.running)",
]
WIDGET = "application/vnd.jupyter.widget-view+json"

NB = ("(() => { const a = window.jupyterapp; if (!a) return null;"
      " for (const w of a.shell.widgets('main'))"
      "   if (w.context && w.context.path === 'live.ipynb') return w;"
      " return null; })()")


def _notebook(cells):
    return {"nbformat": 4, "nbformat_minor": 5,
            "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3",
                                        "language": "python"}},
            "cells": [{"cell_type": "code", "id": f"c{i}", "metadata": {}, "source": src,
                       "outputs": [], "execution_count": None}
                      for i, src in enumerate(cells)]}


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _api(url, method="GET"):
    req = urllib.request.Request(url, method=method)
    with urllib.request.urlopen(req, timeout=10) as reply:
        body = reply.read()
    return json.loads(body) if body else None


@pytest.fixture
def lab(tmp_path):
    """`make lab`'s JupyterLab on a folder holding one notebook; yields (base url, token)."""
    from labkit.tools import lab as lab_tool

    root = tmp_path / "lab"
    root.mkdir()
    (root / "live.ipynb").write_text(json.dumps(_notebook(CELLS)), encoding="utf-8")
    port, token = _free_port(), secrets.token_hex(16)
    env = dict(os.environ, LABKIT_TIME="live", JUPYTER_RUNTIME_DIR=str(tmp_path / "runtime"),
               JUPYTERLAB_SETTINGS_DIR=str(tmp_path / "settings"),
               JUPYTERLAB_WORKSPACES_DIR=str(tmp_path / "workspaces"),
               JUPYTER_CONFIG_DIR=str(tmp_path / "config"))
    log = open(tmp_path / "lab.log", "wb")
    lab_tool.install_custom_css(tmp_path / "config")       # as `make lab` does
    # `make lab`'s own server command (labkit.tools.lab), on a folder of our own
    server = subprocess.Popen(
        lab_tool.command(root, [
            "--no-browser", f"--port={port}", "--port-retries=0",
            f"--IdentityProvider.token={token}", "--allow-root",
            # lets the check read the notebook model, as the learner's eyes would
            "--LabApp.expose_app_in_browser=True"]),
        cwd=ROOT, env=env, stdout=log, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 40
        while True:
            try:
                _api(f"{base}/api/status?token={token}")
                break
            except OSError:
                if server.poll() is not None or time.monotonic() > deadline:
                    log.flush()
                    pytest.fail("JupyterLab did not start:\n" +
                                (tmp_path / "lab.log").read_text(errors="replace")[-2000:])
                time.sleep(0.3)
        yield base, token
    finally:
        try:
            for kernel in _api(f"{base}/api/kernels?token={token}") or []:
                _api(f"{base}/api/kernels/{kernel['id']}?token={token}", "DELETE")
        except OSError:
            pass
        server.terminate()
        try:
            server.wait(timeout=15)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()
        log.close()


@pytest.fixture
def chrome(tmp_path):
    from book_cdp import Browser, find_chromium

    binary = find_chromium()
    if binary is None:
        missing("chromium is not installed (Debian: apt-get install chromium "
                "fonts-noto-cjk; .ci/run does this in CI)")
    profile = tmp_path / "chromium" / "profile"
    profile.mkdir(parents=True)
    browser = Browser(binary, profile)
    page = browser.page()
    yield page
    page.close()
    browser.close()


def _run_cell(page, index, timeout=60.0):
    """Select cell `index` and run it as Shift+Enter does; wait until it is done."""
    page.evaluate(f"""(() => {{ const w = {NB}; window.jupyterapp.shell.activateById(w.id);
        w.content.activeCellIndex = {index};
        const c = w.content.model.cells.get({index}); window.__started = false;
        const f = (_, a) => {{ if (a.name === 'executionState' && a.newValue === 'running') {{
            window.__started = true; c.stateChanged.disconnect(f); }} }};
        c.stateChanged.connect(f);
        return window.jupyterapp.commands.execute('notebook:run-cell-and-select-next'); }})()""")
    page.wait_for(f"""(() => {{ const w = {NB}; const c = w.content.model.cells.get({index});
        return window.__started && c.executionCount !== null && c.executionState === 'idle'
            && w.sessionContext.session.kernel.status === 'idle'; }})()""", timeout)


def _outputs(page, index):
    return page.evaluate(f"{NB}.content.model.cells.get({index}).outputs.toJSON()")


def _text(outputs):
    return "".join(str(o.get("text", "")) for o in outputs if o["output_type"] == "stream")


def test_background_job_output_stays_in_its_own_cell(chrome, lab):
    base, token = lab
    # a headless page has no window focus: emulate it, as JupyterLab follows focus
    chrome.call("Emulation.setFocusEmulationEnabled", enabled=True)
    chrome.open(f"{base}/lab/tree/live.ipynb?token={token}")
    chrome.wait_for(f"""(() => {{ const w = {NB}; return w && w.context.isReady
        && w.content.model.cells.length === {len(CELLS)} && w.sessionContext.session
        && w.sessionContext.session.kernel
        && w.sessionContext.session.kernel.status === 'idle'; }})()""", 60)

    for i in range(3):
        _run_cell(chrome, i)
    areas = {i: _outputs(chrome, i) for i in (1, 2)}
    for i, outputs in areas.items():
        assert any(WIDGET in o.get("data", {}) for o in outputs), \
            f"cell {i}: no output area of its own: {outputs}"
    _run_cell(chrome, 3)
    assert _text(_outputs(chrome, 3)) == "the next cell\n", _outputs(chrome, 3)
    # while no cell runs, the job and the node go on printing: into their own areas only
    time.sleep(1.0)
    assert _text(_outputs(chrome, 3)) == "the next cell\n", _outputs(chrome, 3)
    for i, pattern in ((1, "publishing #"), (2, r"\[chatty\]: tick")):
        assert _outputs(chrome, i) == areas[i]
        chrome.wait_for(f"(() => {{ const t = {NB}.content.widgets[{i}].node.innerText;"
                        f" return (t.match(/{pattern}/g) || []).length >= 10; }})()", 10)

    _run_cell(chrome, 4)
    assert _text(_outputs(chrome, 4)) == "stopped False\n", _outputs(chrome, 4)
    chrome.wait_for(f"{NB}.content.widgets[1].node.innerText.includes('stopped ros2 topic pub')",
                    10)
    chrome.wait_for(f"{NB}.content.widgets[2].node.innerText.includes('stopped chatty')", 10)
    errors = [o for i in range(len(CELLS)) for o in _outputs(chrome, i)
              if o["output_type"] == "error"]
    assert not errors, errors
