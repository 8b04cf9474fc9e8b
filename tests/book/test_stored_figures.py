"""Every SVG figure stored in a notebook keeps its smallest label at 10 px or
more when the book scales it into its 720 px text column."""
from __future__ import annotations

import json
import re

import pytest

from book_support import BOOK

COLUMN_PX = 720.0
MIN_LABEL_PX = 10.0


def notebooks():
    return sorted(p for p in BOOK.rglob("*.ipynb")
                  if "_build" not in p.parts and ".ipynb_checkpoints" not in p.parts)


def stored_svgs(path):
    """(cell index, svg text) of every SVG in the notebook's stored outputs."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    for index, cell in enumerate(nb["cells"]):
        for output in cell.get("outputs", []):
            data = output.get("data") or {}
            for mime in ("image/svg+xml", "text/html"):
                text = data.get(mime)
                if not text:
                    continue
                text = "".join(text) if isinstance(text, list) else text
                for svg in re.findall(r"<svg\b.*?</svg>", text, flags=re.S):
                    yield index, svg


def smallest_label_px(svg: str) -> float | None:
    """None for an SVG with no fixed width (it takes the column's width as is)."""
    head = re.match(r"<svg\b[^>]*>", svg).group(0)
    m = re.search(r'\bwidth="([\d.]+)(pt|px)?"', head)
    if not m:
        return None
    width_px = float(m.group(1)) * (4 / 3 if m.group(2) == "pt" else 1)
    fonts = [float(x) for x in re.findall(r'font-size="([\d.]+)(?:px|pt)?"', svg)]
    if not fonts:
        return None
    return min(fonts) * min(1.0, COLUMN_PX / width_px)


@pytest.mark.parametrize("path", notebooks(), ids=lambda p: str(p.relative_to(BOOK)))
def test_figure_labels_are_legible_in_the_column(path):
    small = []
    for index, svg in stored_svgs(path):
        px = smallest_label_px(svg)
        if px is not None and px < MIN_LABEL_PX:
            small.append(f"cell {index}: smallest label {px:.1f} px")
    assert not small, "; ".join(small)


def test_the_measure_sees_a_too_wide_figure():
    wide = '<svg width="1637pt" height="100pt"><text font-size="14">a</text></svg>'
    fits = '<svg width="500pt" height="100pt"><text font-size="14">a</text></svg>'
    assert smallest_label_px(wide) < MIN_LABEL_PX <= smallest_label_px(fits)
