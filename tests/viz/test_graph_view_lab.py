"""The graph view in live JupyterLab (`make lab`'s server, LABKIT_TIME=live) in headless
Chromium at 1280 px with the file browser open, as the reader of issue 20 saw it.

- The live view (`GraphView(live=True)`) of a graph wider than the cell is scaled to
  the cell's width: nothing cut at the right, nothing to scroll. The snapshot of the
  same graph (automatic layout: top to bottom when left to right is too wide) fits too,
  and a snapshot too wide even top to bottom is scaled down to the cell.
- In JupyterLab as it comes (no custom.css), the snapshot's output itself fits the cell
  (its text/html face: an <img> with max-width 100%), never scaled up, after save and
  reload, and in a copy JupyterLab never signed (untrusted, sanitized).
- A picture placed in the text (`GraphView()`) is a snapshot: after the notebook has
  started more nodes, the live view shows them and the snapshot still does not."""

from __future__ import annotations

import json
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "book"))

from test_live_lab import NB, _outputs, _run_cell  # noqa: E402
from test_live_lab import chrome, lab  # noqa: E402,F401  (fixtures)
import test_live_lab  # noqa: E402

WIDE = """%load_ext labkit
import rclpy
from std_msgs.msg import String
from labkit.viz.graph_view import GraphView

rclpy.init()
made = [rclpy.create_node(f"pipeline_stage_number_{i}") for i in range(6)]
for i, node in enumerate(made[:-1]):
    node.create_publisher(String, f"/between_stage_{i}_and_stage_{i + 1}", 10)
    made[i + 1].create_subscription(String, f"/between_stage_{i}_and_stage_{i + 1}",
                                    lambda msg: None, 10)"""
LATER = """later = rclpy.create_node("started_after_the_picture")
later.create_publisher(String, "/between_stage_5_and_later", 10)
made[5].create_publisher(String, "/between_stage_5_and_later", 10)
later.create_subscription(String, "/between_stage_0_and_stage_1", lambda msg: None, 10)
labkit_sleep = __import__("labkit").sleep(2.0)"""
WIDEST = """fan = [rclpy.create_node(f"camera_driver_number_{i}") for i in range(10)]
for node in fan:
    node.create_publisher(String, "/all_the_cameras_merged_into_one_stream", 10)
GraphView(rankdir="TB")"""
CELLS = [
    WIDE,
    'live_view = GraphView(rankdir="LR", live=True)\nlive_view',
    "GraphView()",
    LATER,
    "live_view.stop()\nprint(live_view.live)",
    WIDEST,
]

# where the picture of cell i is, and where its output area ends
MEASURE = """((i, sel) => {{
  const cell = {nb}.content.widgets[i].node;
  const svg = cell.querySelector(sel);
  if (!svg) return null;
  const area = cell.querySelector('.jp-OutputArea-output').getBoundingClientRect();
  const r = svg.getBoundingClientRect();
  let box = svg.parentElement, scrolls = false;
  for (; box && box !== cell; box = box.parentElement)
    if (box.scrollWidth > box.clientWidth + 1) scrolls = true;
  return {{right: r.right, width: r.width, natural: svg.tagName === "IMG" ? svg.naturalWidth : svg.viewBox.baseVal.width * 4 / 3,
          area_right: area.right, area_width: area.width, window: window.innerWidth,
          scrolls: scrolls, text: svg.textContent}};
}})"""


@pytest.fixture
def notebook(monkeypatch):
    monkeypatch.setattr(test_live_lab, "CELLS", CELLS)


def _measure(page, index, selector):
    return page.evaluate(MEASURE.format(nb=NB) + f"({index}, {selector!r})")


def test_live_graph_fits_its_cell_and_the_snapshot_stays(notebook, chrome, lab):
    base, token = lab
    chrome.call("Emulation.setFocusEmulationEnabled", enabled=True)
    chrome.open(f"{base}/lab/tree/live.ipynb?token={token}")
    chrome.wait_for(f"""(() => {{ const w = {NB}; return w && w.context.isReady
        && w.content.model.cells.length === {len(CELLS)} && w.sessionContext.session
        && w.sessionContext.session.kernel
        && w.sessionContext.session.kernel.status === 'idle'; }})()""", 60)
    # the file browser open beside the notebook, as the reader had it
    chrome.evaluate("window.jupyterapp.shell.activateById('filebrowser')")
    chrome.wait_for("window.jupyterapp.shell.leftCollapsed === false", 10)

    for i in range(3):
        _run_cell(chrome, i)
    live_sel, snap_sel = ".labkit-graph-fit svg", ".jp-OutputArea-output img"
    chrome.wait_for(f"{NB}.content.widgets[1].node.querySelector({live_sel!r}) !== null", 30)
    chrome.wait_for(f"{NB}.content.widgets[2].node.querySelector({snap_sel!r}) !== null", 30)
    live, snap = _measure(chrome, 1, live_sel), _measure(chrome, 2, snap_sel)
    # the live view: left to right the graph is far wider than the cell, scaled to fit it
    assert live["natural"] > live["area_width"] + 50, live
    # the snapshot: fits because the automatic layout wraps it top to bottom
    for face in (live, snap):
        assert face["right"] <= face["area_right"] + 0.5, face     # nothing cut at the right
        assert face["right"] <= face["window"], face
        assert not face["scrolls"], face
    assert live["width"] >= 0.9 * live["area_width"], live          # scaled, not shrunk away
    assert "/pipeline_stage_number_0" in live["text"]
    assert _outputs(chrome, 1)[0]["data"].keys() >= {
        "application/vnd.jupyter.widget-view+json", "image/svg+xml"}
    assert "application/vnd.jupyter.widget-view+json" not in _outputs(chrome, 2)[0]["data"]

    _run_cell(chrome, 3)        # the notebook runs on: a node started after the pictures
    chrome.wait_for(f"""(() => {{ const s = {NB}.content.widgets[1].node.querySelector(
        {live_sel!r}); return s && s.textContent.includes('/started_after_the_picture'); }})()""",
                    20)
    # the snapshot (JupyterLab draws an SVG output as an <img> of the stored data)
    (stored,) = _outputs(chrome, 2)
    assert "/pipeline_stage_number_5" in stored["data"]["image/svg+xml"]
    assert "/started_after_the_picture" not in stored["data"]["image/svg+xml"]
    assert _measure(chrome, 2, snap_sel) == snap
    later = _measure(chrome, 1, live_sel)
    assert later["right"] <= later["area_right"] + 0.5 and not later["scrolls"], later
    _run_cell(chrome, 4)
    # a snapshot too wide for the cell even top to bottom (ten publishers side by side):
    # scaled down to the cell, as the live view is
    _run_cell(chrome, 5)
    chrome.wait_for(f"{NB}.content.widgets[5].node.querySelector({snap_sel!r}) !== null", 30)
    chrome.wait_for(f"{NB}.content.widgets[5].node.querySelector({snap_sel!r}).complete", 10)
    widest = _measure(chrome, 5, snap_sel)
    assert widest["natural"] > widest["area_width"] + 50, widest
    assert widest["right"] <= widest["area_right"] + 0.5 and not widest["scrolls"], widest
    assert widest["width"] >= 0.9 * widest["area_width"], widest
    errors = [o for i in range(len(CELLS)) for o in _outputs(chrome, i)
              if o["output_type"] == "error"]
    assert not errors, errors
    assert "False" in "".join(o.get("text", "") for o in _outputs(chrome, 4))


# -- a snapshot wider than its cell, in JupyterLab as it comes (no custom.css):
# the output itself makes it fit, live, after save and reload, and untrusted
FIT_CELLS = [
    """%load_ext labkit
import rclpy
from std_msgs.msg import String
from labkit.viz.graph_view import GraphView

rclpy.init()
fan = [rclpy.create_node(f"camera_driver_number_{i}") for i in range(10)]
for node in fan:
    node.create_publisher(String, "/all_the_cameras_merged_into_one_stream", 10)
GraphView(rankdir="TB")""",
    'GraphView(snapshot={"/talker": {"publishers": {"/chatter": "std_msgs/msg/String"}},\n'
    '                    "/listener": {"subscribers": {"/chatter": "std_msgs/msg/String"}}})',
]
COPY = NB.replace("'live.ipynb'", "'copy.ipynb'")
# the snapshot's picture, however JupyterLab draws it (an <img> either way)
PICTURE = ".jp-OutputArea-output img"


@pytest.fixture
def as_it_comes(monkeypatch):
    """JupyterLab without labkit's custom.css: the fit must come from the output."""
    monkeypatch.setattr(test_live_lab, "CELLS", FIT_CELLS)
    monkeypatch.setattr("labkit.tools.lab.install_custom_css", lambda *a, **k: None)


def _open(page, base, token, path, nb, cells):
    page.open(f"{base}/lab/tree/{path}?token={token}")
    page.wait_for(f"""(() => {{ const w = {nb}; return w && w.context.isReady
        && w.content.model.cells.length >= {cells}; }})()""", 60)
    page.evaluate("window.jupyterapp.shell.activateById('filebrowser')")
    page.wait_for("window.jupyterapp.shell.leftCollapsed === false", 10)


def _pictures(page, nb):
    for i in range(len(FIT_CELLS)):
        page.wait_for(f"""(() => {{ const s = {nb}.content.widgets[{i}].node.querySelector(
            {PICTURE!r}); return s !== null && s.complete && s.naturalWidth > 0; }})()""", 30)
    return [page.evaluate(MEASURE.format(nb=nb) + f"({i}, {PICTURE!r})")
            for i in range(len(FIT_CELLS))]


def _fits(wide, small):
    # ten publishers side by side: far wider than the cell, scaled down to it, not cut
    assert wide["natural"] > wide["area_width"] + 50, wide
    assert wide["right"] <= wide["area_right"] + 0.5 and not wide["scrolls"], wide
    assert wide["width"] >= 0.9 * wide["area_width"], wide
    # a small graph keeps its own size: never scaled up to the cell
    assert small["natural"] < 0.5 * small["area_width"], small
    assert abs(small["width"] - small["natural"]) <= 1, small


def test_wide_snapshot_fits_its_cell_in_jupyterlab_as_it_comes(as_it_comes, chrome, lab,
                                                               tmp_path):
    base, token = lab
    chrome.call("Emulation.setFocusEmulationEnabled", enabled=True)
    _open(chrome, base, token, "live.ipynb", NB, len(FIT_CELLS))
    chrome.wait_for(f"""(() => {{ const w = {NB}; return w.sessionContext.session
        && w.sessionContext.session.kernel
        && w.sessionContext.session.kernel.status === 'idle'; }})()""", 60)
    for i in range(len(FIT_CELLS)):
        _run_cell(chrome, i)
    _fits(*_pictures(chrome, NB))
    errors = [o for i in range(len(FIT_CELLS)) for o in _outputs(chrome, i)
              if o["output_type"] == "error"]
    assert not errors, errors

    # saved and opened again: the stored output fits as well
    chrome.evaluate(f"{NB}.context.save()")
    chrome.wait_for(f"{NB}.context.model.dirty === false", 20)
    _open(chrome, base, token, "live.ipynb", NB, len(FIT_CELLS))
    _fits(*_pictures(chrome, NB))

    # a copy JupyterLab never signed (as the book's notebooks are on a reader's machine):
    # untrusted, its HTML is sanitized, and the picture still fits
    saved = json.loads((tmp_path / "lab" / "live.ipynb").read_text(encoding="utf-8"))
    saved["metadata"]["copied"] = True
    (tmp_path / "lab" / "copy.ipynb").write_text(json.dumps(saved), encoding="utf-8")
    _open(chrome, base, token, "copy.ipynb", COPY, len(FIT_CELLS))
    assert chrome.evaluate(f"{COPY}.content.model.cells.get(0).trusted") is False
    _fits(*_pictures(chrome, COPY))
