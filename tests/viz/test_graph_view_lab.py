"""The graph view in live JupyterLab (`make lab`'s server, LABKIT_TIME=live) in headless
Chromium at 1280 px with the file browser open, as the reader of issue 20 saw it.

- The live view (`GraphView(live=True)`) of a graph wider than the cell is scaled to
  the cell's width: nothing cut at the right, nothing to scroll. The snapshot of the
  same graph (automatic layout: top to bottom when left to right is too wide) fits too,
  and a snapshot too wide even top to bottom is scaled down to the cell (custom.css).
- A picture placed in the text (`GraphView()`) is a snapshot: after the notebook has
  started more nodes, the live view shows them and the snapshot still does not."""

from __future__ import annotations

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
    live_sel, snap_sel = ".labkit-graph-fit svg", ".jp-RenderedSVG img"
    chrome.wait_for(f"{NB}.content.widgets[1].node.querySelector({live_sel!r}) !== null", 30)
    chrome.wait_for(f"{NB}.content.widgets[2].node.querySelector({snap_sel!r}) !== null", 30)
    live, snap = _measure(chrome, 1, live_sel), _measure(chrome, 2, snap_sel)
    # the live view: left to right the graph is far wider than the cell, scaled to fit it
    assert live["natural"] > live["area_width"] + 50, live
    # the snapshot: JupyterLab draws an SVG output as an <img> at its own size (no
    # max-width), so it fits because the automatic layout wraps it top to bottom
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
    # `make lab`'s custom.css scales it down to the cell, as the live view is
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
