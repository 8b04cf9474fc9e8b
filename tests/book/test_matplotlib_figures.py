"""Every matplotlib figure the book draws keeps its smallest text at 10 px or more
when the book shows it in its 720 px text column.

The figure's cell is run again the way the notebook runs it (the stored cells
before it, in a scratch copy, by tests/book/exercise_fixture_runner.py), with
`plt.show` replaced by a probe that measures every visible text of the figure:
its size in pixels at the figure's dpi, scaled down when the tight-cropped
figure is wider than the column (the inline backend crops it that way)."""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

from book_support import BOOK

COLUMN_PX = 720.0
MIN_TEXT_PX = 10.0
RUNNER = Path(__file__).resolve().parent / "exercise_fixture_runner.py"

PROBE = r'''
import json as _json
import matplotlib.pyplot as _plt
import matplotlib.text as _mtext


def _measure_and_close(*args, **kwargs):
    fig = _plt.gcf()
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    width_px = fig.get_tightbbox(renderer).width * fig.dpi
    scale = min(1.0, 720.0 / width_px)
    sizes = [(round(t.get_fontsize() * fig.dpi / 72 * scale, 2), t.get_text())
             for t in fig.findobj(_mtext.Text) if t.get_visible() and t.get_text().strip()]
    print("FIGURE-PROBE " + _json.dumps({"width_px": round(width_px), "texts": sizes}, ensure_ascii=False))
    _plt.close(fig)


_plt.show = _measure_and_close
'''


def figure_cells():
    """(notebook, cell index) of every stored PNG a matplotlib cell drew."""
    found = []
    for path in sorted(BOOK.rglob("*.ipynb")):
        if "_build" in path.parts or ".ipynb_checkpoints" in path.parts:
            continue
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
        for index, cell in enumerate(cells):
            source = "".join(cell["source"])
            if cell["cell_type"] != "code" or "matplotlib" not in source:
                continue
            if any("image/png" in (o.get("data") or {}) for o in cell.get("outputs", [])):
                found.append((path, index))
    return found


def probe(path: Path, index: int) -> list[dict]:
    with tempfile.TemporaryDirectory(prefix="labkit_figprobe_") as tmp:
        job = {"notebook": str(path), "stub": index, "check": index, "title": "figure",
               "fixtures": [{"name": "probe", "code": PROBE}], "share": False,
               "results": os.path.join(tmp, "results.json")}
        job_path = os.path.join(tmp, "job.json")
        with open(job_path, "w", encoding="utf-8") as f:
            json.dump(job, f, ensure_ascii=False)
        env = dict(os.environ, MPLBACKEND="Agg")
        subprocess.run([sys.executable, str(RUNNER), job_path], env=env, check=True, timeout=300,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(job["results"], encoding="utf-8") as f:
            result = json.load(f)[0]
    lines = re.findall(r"^FIGURE-PROBE (.*)$", result["output"], flags=re.M)
    assert lines, f"the cell drew no figure: {result['output'][-600:]}"
    return [json.loads(line) for line in lines]


CELLS = figure_cells()


def test_the_book_has_matplotlib_figures_to_measure():
    assert CELLS, "no stored matplotlib figure found: the discovery is broken"


@pytest.mark.parametrize("path,index", CELLS, ids=[f"{p.stem}-cell{i}" for p, i in CELLS])
def test_matplotlib_text_is_legible_in_the_column(path, index):
    small = []
    for figure in probe(path, index):
        small += [f"{text!r} at {px} px (figure {figure['width_px']} px wide)"
                  for px, text in figure["texts"] if px < MIN_TEXT_PX]
    assert not small, "; ".join(small[:8])
