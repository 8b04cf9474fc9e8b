"""A graph picture placed beside a text is a snapshot of that moment; the live view
is asked for (live=True) and scales to its cell's width.

ch03 showed `GraphView().show()` in §3.3; in live JupyterLab the widget went on
following the graph, so after the chapter's exercise had started its nodes the
§3.3 picture showed those nodes, not the ones the text describes."""
import base64
import threading
import xml.etree.ElementTree as ET

import pytest

from labkit import rclpy
from labkit.interfaces import get_type
from labkit.viz import graph_view
from labkit.viz._graph_render import fit_svg
from labkit.viz.graph_view import GraphView

String = get_type("std_msgs/msg/String")
WIDGET = "application/vnd.jupyter.widget-view+json"


@pytest.fixture
def shown(monkeypatch):
    """What the views display (MIME bundles), instead of a notebook's output."""
    bundles = []
    monkeypatch.setattr("labkit.viz.display.display", lambda obj, **kw: bundles.append(obj))
    monkeypatch.setattr(graph_view, "POLL_PERIOD_S", 0.01)
    return bundles


@pytest.fixture
def nodes():
    ctx = rclpy.context.Context()
    rclpy.init(args=[], context=ctx)
    made = []

    def make(name):
        made.append(rclpy.create_node(name, context=ctx))
        return made[-1]
    yield make
    for n in made:
        n.destroy_node()
    ctx.try_shutdown()


def _pollers():
    return [t for t in threading.enumerate() if t.name == "labkit-graph-view"]


def _talker_listener(nodes, prefix):
    nodes(f"{prefix}_talker").create_publisher(String, f"{prefix}_chatter", 10)
    nodes(f"{prefix}_listener").create_subscription(String, f"{prefix}_chatter", lambda m: None, 10)


def test_shown_picture_is_a_snapshot_after_later_nodes_start(live_time, shown, nodes, until):
    _talker_listener(nodes, "text")
    view = GraphView()
    view.show()
    (bundle,) = shown
    assert WIDGET not in bundle          # nothing that could change later: one static picture
    picture = bundle["image/svg+xml"]
    assert "/text_talker" in picture and "/text_chatter" in picture
    assert not _pollers()                # nobody follows the graph for it
    _talker_listener(nodes, "exercise")  # the chapter runs on
    assert until(lambda: "/exercise_talker" in GraphView().svg())
    assert shown == [bundle] and bundle["image/svg+xml"] == picture
    assert "/exercise_talker" not in picture
    # the same view shown again later is a new snapshot of that moment
    view.show()
    assert "/exercise_talker" in shown[-1]["image/svg+xml"]


def test_last_line_of_a_cell_is_a_snapshot_too(live_time, shown, nodes):
    _talker_listener(nodes, "text")
    GraphView()._ipython_display_()
    assert [WIDGET in b for b in shown] == [False]
    assert not _pollers()


def test_live_view_is_opt_in_and_follows(live_time, shown, nodes, until):
    view = GraphView(live=True)
    try:
        view._ipython_display_()
        (bundle,) = shown
        assert WIDGET in bundle and "image/svg+xml" in bundle
        assert view.live
        widget = view.widget()
        assert 'class="labkit-graph-fit"' in widget.value
        _talker_listener(nodes, "later")
        assert until(lambda: "/later_talker" in widget.value)
    finally:
        view.stop()
    assert not view.live


def test_fit_svg_scales_down_only():
    svg = GraphView(snapshot={}).svg()
    root = ET.fromstring(svg)
    natural_w = root.get("width")
    fitted = ET.fromstring(fit_svg(svg))
    assert fitted.get("width") is None and fitted.get("height") is None
    style = fitted.get("style")
    assert "width:100%" in style and f"max-width:{natural_w}" in style and "height:auto" in style
    assert fitted.get("viewBox") == root.get("viewBox")


def test_snapshot_carries_a_picture_that_fits_its_cell(live_time, shown, nodes):
    """JupyterLab draws an image/svg+xml output as an <img> at the SVG's own size, cut
    off in a narrower cell; the output's text/html face (which JupyterLab and the book
    prefer) is an <img> of the same SVG scaled down to the cell, never up."""
    _talker_listener(nodes, "text")
    GraphView().show()
    (bundle,) = shown
    img = ET.fromstring(bundle["text/html"])
    assert img.tag == "img" and img.get("width") is None and img.get("height") is None
    style = dict(part.split(":") for part in img.get("style").split(";"))
    assert style["max-width"] == "100%" and style["height"] == "auto"
    prefix = "data:image/svg+xml;base64,"
    assert img.get("src").startswith(prefix)
    assert base64.b64decode(img.get("src")[len(prefix):]).decode("utf-8") == bundle["image/svg+xml"]
    assert img.get("alt") == bundle["text/plain"]
