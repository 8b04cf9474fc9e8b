"""Graph figures stay legible in the book's 720 px column: a long pipeline that
rqt_graph would lay out in one row is turned top-to-bottom instead."""
import re

from labkit.viz._graph_render import COLUMN_PX, MIN_LABEL_PX, label_px_in_column
from labkit.viz.graph_view import GraphView

STD = {"/rosout": "rcl_interfaces/msg/Log", "/parameter_events": "rcl_interfaces/msg/ParameterEvent"}


def pipeline(stages: int) -> dict:
    """stage_0 -> /link_0 -> stage_1 -> /link_1 -> ... : a long chain of nodes."""
    nodes = {}
    for i in range(stages):
        spec = {"publishers": dict(STD)}
        if i + 1 < stages:
            spec["publishers"][f"/link_{i}"] = "std_msgs/msg/String"
        if i:
            spec["subscribers"] = {f"/link_{i - 1}": "std_msgs/msg/String"}
        nodes[f"/long_stage_name_{i}"] = spec
    return nodes


def figure(svg: str) -> tuple[float, float]:
    m = re.search(r'width="([\d.]+)pt" height="([\d.]+)pt"', svg)
    return float(m.group(1)), float(m.group(2))


def smallest_label_px(svg: str) -> float:
    width_pt, _ = figure(svg)
    fonts = [float(x) for x in re.findall(r'font-size="([\d.]+)"', svg)]
    return label_px_in_column(width_pt, min(fonts))


def test_long_chain_is_turned_top_to_bottom_and_stays_legible():
    snapshot = pipeline(6)
    wide = GraphView(snapshot=snapshot, rankdir="LR").svg()
    auto = GraphView(snapshot=snapshot).svg()
    # rqt_graph's own direction would shrink the labels below the limit ...
    assert smallest_label_px(wide) < MIN_LABEL_PX
    # ... the default picks the direction that keeps them readable
    assert smallest_label_px(auto) >= MIN_LABEL_PX
    w, h = figure(auto)
    assert h > w


def test_small_graph_keeps_rqt_graph_direction():
    snapshot = pipeline(2)
    assert GraphView(snapshot=snapshot).svg() == GraphView(snapshot=snapshot, rankdir="LR").svg()


def test_label_px_scales_only_figures_wider_than_the_column():
    assert label_px_in_column(COLUMN_PX * 3 / 4, 14) == 14          # exactly the column: no scaling
    assert abs(label_px_in_column(COLUMN_PX * 3 / 2, 14) - 7) < 1e-9  # twice the column: half size
