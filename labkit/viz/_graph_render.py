"""Lay a ViewGraph out with Graphviz `dot` (what rqt_graph uses) and write SVG.

Graphviz only places things; the SVG is written here. Every vertex and cluster
label gets a fixed size computed from its characters, never from the fonts
installed on the machine, and text is centred by us, so the same graph gives
the same SVG bytes on any machine (nbval compares stored SVG). Vertices,
clusters and edges are added in sorted order, so `dot` is deterministic too.
"""
from __future__ import annotations

import base64
import contextlib
import math
import os
import re
import sys
import threading
import unicodedata
import warnings
from xml.sax.saxutils import escape, quoteattr

from labkit.viz._graph_filter import ViewGraph

# Chinese first so CJK labels render; the rest are what readers' systems have.
FONT_FAMILY = ("Noto Sans CJK SC, Source Han Sans SC, PingFang SC, Microsoft YaHei, "
               "WenQuanYi Micro Hei, DejaVu Sans, sans-serif")
FONT_SIZE = 14.0
CLUSTER_FONT_SIZE = 14.0   # as large as the vertices: the book scales wide figures down
EDGE_FONT_SIZE = 14.0

_STYLE = {
    # rqt_graph: nodes are ellipses, topics boxes, grouped topics box3d
    "node": dict(shape="ellipse", fill="white", stroke="black"),
    "topic": dict(shape="box", fill="white", stroke="black"),
    "tf": dict(shape="box3d", fill="white", stroke="black"),
    "service": dict(shape="rounded", fill="#e3effa", stroke="#2f6fa8"),
    "action": dict(shape="box3d", fill="#fdebd3", stroke="#b5651d"),
}
_EDGE = {
    "topic": dict(stroke="black", dash=None, both=False),
    # request and response (or goal, feedback and result) travel both ways
    "service": dict(stroke="#2f6fa8", dash="5,3", both=True),
    "action": dict(stroke="#b5651d", dash="5,3", both=True),
    # services="request_response": one arrow per message, each named
    "request": dict(stroke="#2f6fa8", dash=None, both=False, text="请求"),
    "response": dict(stroke="#2f6fa8", dash="5,3", both=False, text="应答", back=True),
}
_CLUSTER = {"namespace": dict(stroke="#9a9a9a", dash=None),
            "action": dict(stroke="#b5651d", dash="5,3")}


def _char_em(ch: str) -> float:
    """Advance width of one character in em, generous for a sans-serif font."""
    if unicodedata.east_asian_width(ch) in ("W", "F"):
        return 1.0
    if ch in "il.,:;|!'`jI":
        return 0.30
    if ch in "/\\()[]{}-frt ":
        return 0.40
    if ch in "mwMW":
        return 0.90
    if ch.isupper() or ch in "_#%&@":
        return 0.68
    return 0.58


def text_width(text: str, size: float = FONT_SIZE) -> float:
    """Estimated width in points of the widest line of `text`."""
    return max(sum(_char_em(c) for c in line) for line in text.split("\n")) * size


def _vertex_size(kind: str, label: str) -> tuple[float, float]:
    """(width, height) in inches, fixed so that layout never measures fonts."""
    lines = label.count("\n") + 1
    w = text_width(label) + 18.0
    h = lines * FONT_SIZE * 1.25 + 12.0
    if kind == "node":             # an ellipse around the label box
        w, h = w * 1.3, max(h * 1.4, 36.0)
    else:
        h = max(h, 36.0)
    return round(w / 72.0, 3), round(h / 72.0, 3)


def _fixed_label(text: str, size: float) -> str:
    """An HTML-like label with a fixed-size cell, again so fonts never matter."""
    w = int(text_width(text, size)) + 12
    h = int(size * 1.8)
    esc = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return (f'<<TABLE BORDER="0" CELLBORDER="0" CELLPADDING="0" CELLSPACING="0">'
            f'<TR><TD FIXEDSIZE="TRUE" WIDTH="{w}" HEIGHT="{h}">{esc}</TD></TR></TABLE>>')


def _cluster_text(key: str, kind: str) -> str:
    return key if kind == "namespace" else f"{key} (action)"


def display_name(view: ViewGraph, v) -> str:
    """The text drawn in a vertex: its ROS name, except inside an expanded
    action's box, whose title already says the action's name: there the part
    after it (`_action/feedback`), so the figure stays narrow enough to read.
    The hover text always has the whole name."""
    if v.cluster and view.clusters.get(v.cluster[-1]) == "action":
        prefix = v.cluster[-1].rstrip("/") + "/"
        if v.name.startswith(prefix):
            return v.name[len(prefix):]
    return v.name


def to_agraph(view: ViewGraph, *, rankdir: str = "LR"):
    import pygraphviz as pgv

    g = pgv.AGraph(directed=True, strict=False, name="rosgraph")   # rqt_graph: no simplify
    # rqt_graph's defaults: left to right, ranksep 0.2, rank=same, no simplify
    # two-headed (service/action) arrows need a longer shaft to stay readable
    two_way = any(_EDGE[link.kind]["both"] or "text" in _EDGE[link.kind] for link in view.links)
    g.graph_attr.update(rankdir=rankdir, ranksep="0.5" if two_way else "0.2",
                        nodesep="0.25", rank="same",
                        fontname=FONT_FAMILY, fontsize=str(CLUSTER_FONT_SIZE),
                        bgcolor="white", pad="0.1")
    g.node_attr.update(fontname=FONT_FAMILY, fontsize=str(FONT_SIZE), fixedsize="true")
    g.edge_attr.update(arrowsize="0.8", fontname=FONT_FAMILY, fontsize=str(EDGE_FONT_SIZE))

    subgraphs = {(): g}

    def container(path):
        for i in range(len(path)):
            key = path[: i + 1]
            if key not in subgraphs:
                kind = view.clusters.get(key[-1], "namespace")
                subgraphs[key] = subgraphs[key[:-1]].add_subgraph(
                    name="cluster_" + key[-1],
                    label=_fixed_label(_cluster_text(key[-1], kind), CLUSTER_FONT_SIZE))
        return subgraphs[tuple(path)]

    for cluster_path in sorted({v.cluster for v in view.vertices}):
        container(cluster_path)
    for v in view.vertices:
        label = display_name(view, v)
        width, height = _vertex_size(v.kind, label)
        shape = "ellipse" if v.kind == "node" else "box"
        container(v.cluster).add_node(v.id, label=label, shape=shape,
                                      width=str(width), height=str(height))
    for link in view.links:
        # arrowheads at both ends make dot reserve room for them
        extra = dict(dir="both") if _EDGE[link.kind]["both"] else {}
        if _EDGE[link.kind].get("back"):
            extra["dir"] = "back"   # laid out beside the arrow it answers, head at its end
        if link.label or "text" in _EDGE[link.kind]:
            extra["label"] = _fixed_label(link.label or _EDGE[link.kind]["text"], EDGE_FONT_SIZE)
        g.add_edge(*_laid_out_ends(link), key=_edge_key(link), **extra)
    return g


def _edge_key(link) -> str:
    return f"{link.start}|{link.label}|{link.end}"


def _laid_out_ends(link):
    """(tail, head) of the edge dot lays out: a response runs against its request."""
    return (link.end, link.start) if _EDGE[link.kind].get("back") else (link.start, link.end)




# ---------------------------------------------------------------- SVG writing

PAD = 8.0          # points around the drawing
ARROW_LEN = 8.0    # dot's arrowsize 0.8 * 10


def _floats(text: str) -> list[float]:
    return [float(x) for x in text.split(",")]


def _fmt(x: float) -> str:
    return f"{x:.2f}".rstrip("0").rstrip(".") if x != 0 else "0"


class _Canvas:
    """Graphviz coordinates (y up, points) to SVG coordinates (y down)."""

    def __init__(self, bb):
        self.x0, self.y0, x1, y1 = bb
        self.width = x1 - self.x0 + 2 * PAD
        self.height = y1 - self.y0 + 2 * PAD
        self.top = y1

    def pt(self, x, y):
        return x - self.x0 + PAD, self.top - y + PAD

    def xy(self, x, y):
        px, py = self.pt(x, y)
        return f"{_fmt(px)},{_fmt(py)}"


def _text(x, y, label, size, fill="black"):
    # baseline a third of the size below the centre: visually centred, no font metrics needed
    return (f'<text x="{_fmt(x)}" y="{_fmt(y + size * 0.35)}" text-anchor="middle" '
            f'font-size="{_fmt(size)}" fill="{fill}">{escape(label)}</text>')


def _remote(fqn):
    """Is this node in another process (labkit.dds marks the nodes it discovered)?"""
    from labkit.graph.registry import GRAPH
    return any(getattr(n, "remote", False) and n.fqn == fqn for n in list(GRAPH.nodes))


def _shape(kind, cx, cy, w, h, stroke=None):
    st = dict(_STYLE[kind], stroke=stroke or _STYLE[kind]["stroke"])
    paint = f'fill="{st["fill"]}" stroke="{st["stroke"]}"'
    if st["shape"] == "ellipse":
        return f'<ellipse cx="{_fmt(cx)}" cy="{_fmt(cy)}" rx="{_fmt(w / 2)}" ry="{_fmt(h / 2)}" {paint}/>'
    x, y = cx - w / 2, cy - h / 2
    if st["shape"] == "rounded":
        return (f'<rect x="{_fmt(x)}" y="{_fmt(y)}" width="{_fmt(w)}" height="{_fmt(h)}" '
                f'rx="6" {paint}/>')
    if st["shape"] == "box3d":   # a box with a 4 pt deep top and right side, like dot's box3d
        d = 4.0
        return (f'<rect x="{_fmt(x)}" y="{_fmt(y + d)}" width="{_fmt(w - d)}" height="{_fmt(h - d)}" {paint}/>'
                f'<polyline points="{_fmt(x)},{_fmt(y + d)} {_fmt(x + d)},{_fmt(y)} {_fmt(x + w)},{_fmt(y)} '
                f'{_fmt(x + w)},{_fmt(y + h - d)} {_fmt(x + w - d)},{_fmt(y + h)}" fill="none" '
                f'stroke="{st["stroke"]}"/><line x1="{_fmt(x + w - d)}" y1="{_fmt(y + d)}" '
                f'x2="{_fmt(x + w)}" y2="{_fmt(y)}" stroke="{st["stroke"]}"/>')
    return f'<rect x="{_fmt(x)}" y="{_fmt(y)}" width="{_fmt(w)}" height="{_fmt(h)}" {paint}/>'


def _arrowhead(tip, base, color):
    """A filled triangle from `base` (the end of the spline) to `tip`."""
    dx, dy = tip[0] - base[0], tip[1] - base[1]
    n = math.hypot(dx, dy) or 1.0
    ux, uy = dx / n, dy / n
    half = ARROW_LEN * 0.35
    p1 = (base[0] - uy * half, base[1] + ux * half)
    p2 = (base[0] + uy * half, base[1] - ux * half)
    pts = " ".join(f"{_fmt(a)},{_fmt(b)}" for a, b in (tip, p1, p2))
    return f'<polygon points="{pts}" fill="{color}" stroke="{color}"/>'


def _edge_svg(canvas, pos, style):
    start = end = None
    points = []
    for token in pos.split():
        if token.startswith("e,"):
            end = canvas.pt(*_floats(token[2:]))
        elif token.startswith("s,"):
            start = canvas.pt(*_floats(token[2:]))
        else:
            points.append(canvas.pt(*_floats(token)))
    d = f"M{_fmt(points[0][0])},{_fmt(points[0][1])}"
    for i in range(1, len(points) - 2, 3):
        d += "C" + " ".join(f"{_fmt(x)},{_fmt(y)}" for x, y in points[i:i + 3])
    dash = f' stroke-dasharray="{style["dash"]}"' if style["dash"] else ""
    out = [f'<path d="{d}" fill="none" stroke="{style["stroke"]}"{dash}/>']
    if end is not None:
        out.append(_arrowhead(end, points[-1], style["stroke"]))
    if start is not None:
        out.append(_arrowhead(start, points[0], style["stroke"]))
    return "".join(out)


def _qos_tooltip(v) -> str:
    lines = ["Found qos incompatibilities:", ""]
    lines += [f"- Publisher of node `{pub}` incompatible with subscriptions of nodes "
              f"`{', '.join(subs)}`" for pub, subs in v.qos_incompatible]
    lines += ["", f"Use `ros2 topic info -v {v.name}` to check the qos profiles"]
    return "\n".join(lines)


def _walk_clusters(graph, found):
    for sg in graph.subgraphs():
        found[sg.name[len("cluster_"):]] = sg
        _walk_clusters(sg, found)
    return found


_fontconfig_ready = False
_fontconfig_lock = threading.Lock()


def _graphviz_errors_only():
    """Graphviz prints warnings (e.g. a label cell smaller than its text as this
    machine's fonts measure it) to file descriptor 2, which Jupyter shows in the
    cell and nbval compares. Our sizes are deliberate: keep errors, drop warnings
    (cgraph's agseterr(AGERR), on the libcgraph pygraphviz loaded)."""
    import ctypes
    import ctypes.util
    path = None
    try:
        with open("/proc/self/maps", encoding="utf-8") as maps:
            path = next((line.split()[-1] for line in maps if "libcgraph" in line), None)
    except OSError:
        pass
    path = path or ctypes.util.find_library("cgraph")
    if path:
        try:
            ctypes.CDLL(path).agseterr(1)   # AGERR
        except (OSError, AttributeError):
            pass


@contextlib.contextmanager
def _quiet_first_layout():
    """Graphviz's bundled fontconfig may complain about this machine's newer
    config files when it starts; the complaint goes to file descriptor 2, which
    Jupyter shows in the cell. It starts once per process: hide that one time."""
    global _fontconfig_ready
    with _fontconfig_lock:
        if _fontconfig_ready:
            yield
            return
        _fontconfig_ready = True
        _graphviz_errors_only()
        try:
            sys.stderr.flush()
            saved = os.dup(2)
        except (OSError, ValueError, AttributeError):
            yield
            return
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, 2)
            os.close(devnull)
            yield
        finally:
            os.dup2(saved, 2)
            os.close(saved)


# The book's text column is 720 CSS px wide; a figure wider than that is scaled
# down, and its labels with it. A label must stay at least this many px tall.
COLUMN_PX = 720.0
MIN_LABEL_PX = 10.0


def _empty_svg() -> str:
    return (f'<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n'
            f'<svg xmlns="http://www.w3.org/2000/svg" width="120pt" height="40pt" '
            f'viewBox="0 0 120 40" font-family={quoteattr(FONT_FAMILY)} class="labkit-rosgraph">\n'
            f'<rect width="120" height="40" fill="white"/>\n{_text(60, 20, "(no nodes)", 12, "#777777")}\n</svg>\n')


def _laid_out(view: ViewGraph, rankdir: str):
    g = to_agraph(view, rankdir=rankdir)
    with warnings.catch_warnings(), _quiet_first_layout():
        # "cell size too small": the fixed label cells are deliberate
        warnings.simplefilter("ignore")
        g.layout(prog="dot")
    return g


def label_px_in_column(width_pt: float, smallest_font: float) -> float:
    """How tall (CSS px) the smallest label of a figure `width_pt` wide is in the column."""
    width_px = width_pt * 4.0 / 3.0
    return smallest_font * min(1.0, COLUMN_PX / width_px)


def _smallest_font(view: ViewGraph) -> float:
    sizes = [FONT_SIZE]
    if view.clusters or any(v.cluster for v in view.vertices):
        sizes.append(CLUSTER_FONT_SIZE)
    if any(link.label for link in view.links):
        sizes.append(EDGE_FONT_SIZE)
    return min(sizes)


def layout(view: ViewGraph, rankdir: str = "auto"):
    """The laid out graph. rankdir "auto": rqt_graph's left-to-right, unless that
    makes the figure so wide that its labels shrink below MIN_LABEL_PX in the
    book's column; then top-to-bottom when that reads better."""
    if rankdir != "auto":
        return _laid_out(view, rankdir)
    smallest = _smallest_font(view)
    best, best_px = None, -1.0
    for direction in ("LR", "TB"):
        g = _laid_out(view, direction)
        px = label_px_in_column(_Canvas(_floats(g.graph_attr["bb"])).width, smallest)
        if px > best_px + 1e-9:
            best, best_px = g, px
        if px >= MIN_LABEL_PX:
            break
    return best


def render_svg(view: ViewGraph, *, rankdir: str = "auto") -> str:
    """The SVG document (UTF-8 text) of the laid out view."""
    if not view.vertices:
        return _empty_svg()
    g = layout(view, rankdir)
    canvas = _Canvas(_floats(g.graph_attr["bb"]))
    w, h = canvas.width, canvas.height
    out = ['<?xml version="1.0" encoding="UTF-8" standalone="no"?>',
           f'<svg xmlns="http://www.w3.org/2000/svg" width="{_fmt(w)}pt" height="{_fmt(h)}pt" '
           f'viewBox="0 0 {_fmt(w)} {_fmt(h)}" font-family={quoteattr(FONT_FAMILY)} '
           f'class="labkit-rosgraph">',
           f'<rect width="{_fmt(w)}" height="{_fmt(h)}" fill="white"/>']
    clusters = _walk_clusters(g, {})
    for key in sorted(clusters):   # parents sort before children: drawn underneath
        sg, kind = clusters[key], view.clusters.get(key, "namespace")
        x0, y0, x1, y1 = _floats(sg.graph_attr["bb"])
        (ax, ay), (bx, by) = canvas.pt(x0, y1), canvas.pt(x1, y0)
        st = _CLUSTER[kind]
        dash = f' stroke-dasharray="{st["dash"]}"' if st["dash"] else ""
        lx, ly = canvas.pt(*_floats(sg.graph_attr["lp"]))
        label = _cluster_text(key, kind)
        out.append(f'<g class="cluster {kind}"><title>{escape(label)}</title>'
                   f'<rect x="{_fmt(ax)}" y="{_fmt(ay)}" width="{_fmt(bx - ax)}" height="{_fmt(by - ay)}" '
                   f'rx="6" fill="none" stroke="{st["stroke"]}"{dash}/>'
                   f'{_text(lx, ly, label, CLUSTER_FONT_SIZE, "#555555")}</g>')
    by_id = {v.id: v for v in view.vertices}
    for link in view.links:
        edge = g.get_edge(*_laid_out_ends(link), key=_edge_key(link))
        title = f"{by_id[link.start].name} \u2192 {by_id[link.end].name}"
        label = ""
        if link.label:
            title = f"{by_id[link.start].name} \u2192 {link.label} \u2192 {by_id[link.end].name}"
        if link.label or "text" in _EDGE[link.kind]:
            lx, ly = canvas.pt(*_floats(edge.attr["lp"]))
            label = _text(lx, ly, link.label or _EDGE[link.kind]["text"], EDGE_FONT_SIZE)
        if "text" in _EDGE[link.kind]:
            title += f" ({_EDGE[link.kind]['text']})"
        out.append(f'<g class="edge {link.kind}"><title>{escape(title)}</title>'
                   f'{_edge_svg(canvas, edge.attr["pos"], _EDGE[link.kind])}{label}</g>')
    for v in view.vertices:
        n = g.get_node(v.id)
        cx, cy = canvas.pt(*_floats(n.attr["pos"]))
        vw, vh = float(n.attr["width"]) * 72.0, float(n.attr["height"]) * 72.0
        tip = "\n".join((v.name,) + v.types)   # hover: the name and its interface types
        stroke, css = None, v.kind
        if v.qos_incompatible:   # rqt_graph: a red topic, the details on hover
            stroke, css = "red", v.kind + " qos-incompatible"
            tip += "\n\n" + _qos_tooltip(v)
        if v.kind == "node" and _remote(v.name):   # another process's node, seen over DDS
            stroke, css = "#2e7d32", "node remote"
            tip += "\n(remote: over DDS)"
        out.append(f'<g class="vertex {css}"><title>{escape(tip)}</title>'
                   f'{_shape(v.kind, cx, cy, vw, vh, stroke)}{_text(cx, cy, display_name(view, v), FONT_SIZE)}</g>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def inline_svg(svg: str) -> str:
    """The <svg> element alone, for embedding in HTML (no XML prolog)."""
    start = svg.find("<svg")
    return svg[start:] if start >= 0 else svg


def fit_svg(svg: str) -> str:
    """The <svg> element for HTML that must fit its container: drawn at its own size
    when there is room, scaled down (aspect kept by the viewBox) when there is not."""
    element = inline_svg(svg)
    head_end = element.find(">")
    head = element[:head_end]
    m = re.search(r' width="([0-9.]+)pt" height="([0-9.]+)pt"', head)
    if m is None:
        return element
    style = (f' style="display:block;width:100%;max-width:{m.group(1)}pt;height:auto"'
             ' preserveAspectRatio="xMinYMin meet"')
    return element[:m.start()] + style + element[m.end():]


def img_html(svg: str, alt: str = "") -> str:
    """The SVG as an HTML <img> that fits its container: drawn at its own size when
    there is room, scaled down (aspect kept) when there is not, never scaled up. A
    notebook output's text/html face: JupyterLab draws an image/svg+xml output as an
    <img> at the SVG's own size however narrow the cell, but this one as written, after
    save and reload too (even untrusted: its sanitizer keeps <img> and these styles),
    and so does the HTML book."""
    data = base64.b64encode(svg.encode("utf-8")).decode("ascii")
    return (f'<img class="labkit-graph-snapshot" alt={quoteattr(alt)} '
            'style="display:block;max-width:100%;height:auto" '
            f'src="data:image/svg+xml;base64,{data}"/>')
