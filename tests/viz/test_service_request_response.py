"""A service drawn as its two messages: the request client -> service -> server, and
the response back, each its own one-headed arrow with its name (issue 18: ch02's figure
drew a two-headed arrow where the text says client -> server).

GraphView(services="request_response") draws it so; services=True keeps the two-headed
arrow of the other chapters. The stored ch02 figure is checked from its SVG: which end
of each path carries the arrowhead, dashed or not, and the word beside it."""
from __future__ import annotations

import json
import math
import pathlib
import re

import pytest

from labkit.viz.graph_view import GraphView

ROOT = pathlib.Path(__file__).resolve().parents[2]
CH02 = ROOT / "book" / "part1_basics" / "ch02_nodes.ipynb"
SPEC = {"/dashboard": {"clients": {"/enable_autonomy": "std_srvs/srv/SetBool"}},
        "/planner": {"services": {"/enable_autonomy": "std_srvs/srv/SetBool"}}}
COLUMN_PX = 720.0


def _points(text):
    return [tuple(map(float, p.split(","))) for p in re.findall(r"-?[\d.]+,-?[\d.]+", text)]


def _vertices(svg):
    """ROS name -> box of its shape (x0, y0, x1, y1)."""
    found = {}
    for group in re.findall(r'<g class="vertex[^"]*">(.*?)</g>', svg, flags=re.S):
        name = re.search(r"<text[^>]*>([^<]+)</text>", group).group(1)
        shape = group.split("</title>")[-1]

        def num(attr):
            return float(re.search(rf'\b{attr}="([-\d.]+)"', shape).group(1))
        if shape.startswith("<ellipse"):
            cx, cy, rx, ry = num("cx"), num("cy"), num("rx"), num("ry")
            found[name] = (cx - rx, cy - ry, cx + rx, cy + ry)
        elif shape.startswith("<rect"):
            x, y = num("x"), num("y")
            found[name] = (x, y, x + num("width"), y + num("height"))
        else:
            pts = _points(shape.split("<text")[0])
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            found[name] = (min(xs), min(ys), max(xs), max(ys))
    return found


def _gap(p, box):
    """How far point p is from the box (0 inside it)."""
    x0, y0, x1, y1 = box
    return math.hypot(max(x0 - p[0], 0, p[0] - x1), max(y0 - p[1], 0, p[1] - y1))


def _arrows(svg):
    """Every arrow: (kind, from, to, dashed, heads, label), `to` being the vertex its
    head points at (the one nearest the tip), `from` the one nearest the other end."""
    boxes = _vertices(svg)

    def nearest(p):
        return min(boxes, key=lambda name: _gap(p, boxes[name]))
    arrows = []
    for kind, body in re.findall(r'<g class="edge ([^"]+)">(.*?)</g>', svg, flags=re.S):
        path = re.search(r'<path d="([^"]+)"', body).group(1)
        ends = _points(path)
        heads = re.findall(r'<polygon points="([^"]+)"', body)
        label = re.findall(r"<text[^>]*>([^<]+)</text>", body)
        tips = []
        for head in heads:
            corners = _points(head)
            # the tip is the corner farthest from the path's end it sits on
            near = min((ends[0], ends[-1]), key=lambda e: min(math.dist(e, c) for c in corners))
            tips.append(max(corners, key=lambda c: math.dist(c, near)))
        if len(tips) == 1:
            tip = tips[0]
            tail = max((ends[0], ends[-1]), key=lambda e: math.dist(e, tip))
            start, end = nearest(tail), nearest(tip)
        else:
            start = end = None
        arrows.append((kind, start, end, "stroke-dasharray" in path or "stroke-dasharray" in body,
                       len(heads), label[0] if label else ""))
    return arrows


def _service_arrows(svg):
    return sorted(a[:4] + a[5:] for a in _arrows(svg) if a[0] in ("request", "response"))


EXPECTED = [
    ("request", "/dashboard", "/enable_autonomy", False, "请求"),
    ("request", "/enable_autonomy", "/planner", False, "请求"),
    ("response", "/enable_autonomy", "/dashboard", True, "应答"),
    ("response", "/planner", "/enable_autonomy", True, "应答"),
]


def test_request_and_response_are_two_one_headed_arrows():
    view = GraphView(services="request_response", snapshot=SPEC)
    svg = view.svg()
    arrows = _arrows(svg)
    assert all(heads == 1 for *_, heads, _label in arrows), arrows
    assert _service_arrows(svg) == EXPECTED
    # the graph's own account agrees with the picture
    assert view.edges() == sorted({(a, b) for _k, a, b, *_ in EXPECTED})


def test_two_headed_service_arrow_is_still_the_default():
    arrows = _arrows(GraphView(services=True, snapshot=SPEC).svg())
    assert [(kind, heads) for kind, _a, _b, _d, heads, _l in arrows] == [("service", 2)] * 2


def test_unknown_services_style_is_refused():
    with pytest.raises(ValueError, match="services must be"):
        GraphView(services="both_ways", snapshot=SPEC)


def test_nodes_only_keeps_one_arrow_per_service():
    view = GraphView(services="request_response", nodes_only=True, snapshot=SPEC)
    assert view.edges(labels=True) == [("/dashboard", "/enable_autonomy", "/planner")]


def _stored_figure():
    nb = json.loads(CH02.read_text(encoding="utf-8"))
    for index, cell in enumerate(nb["cells"]):
        for out in cell.get("outputs", []):
            svg = "".join(out.get("data", {}).get("image/svg+xml", ""))
            if "/enable_autonomy" in svg:
                following = "".join(nb["cells"][index + 1]["source"])
                return svg, following
    raise AssertionError("ch02 has no stored figure with /enable_autonomy")


def test_ch02_figure_draws_the_request_there_and_the_response_back():
    svg, text = _stored_figure()
    arrows = _arrows(svg)
    assert not [a for a in arrows if a[4] != 1], "an arrow with two heads (or none)"
    assert _service_arrows(svg) == EXPECTED
    # legible in the 720 px column: every word at 10 px or more
    width_pt = float(re.search(r'<svg\b[^>]*\bwidth="([\d.]+)pt"', svg).group(1))
    scale = min(1.0, COLUMN_PX / (width_pt * 4 / 3))
    sizes = [float(s) for s in re.findall(r'font-size="([\d.]+)"', svg)]
    assert min(sizes) * scale >= 10.0, (min(sizes), scale)
    # the text beside it describes what is drawn
    assert "两头都有箭头" not in text
    assert "“请求”的实线箭头" in text and "“应答”的虚线箭头" in text
