"""Stored notebooks hold output as a terminal shows it: whole lines.

A kernel sends a stream in pieces (one per flush); stored as they came, a CLI
line can be cut in two (`Parameter name:` / ` ` / `background_g`), and the HTML
build shows each piece as its own block (and drops one that is only a space).
labkit writes whole lines and `labkit.tools.execute_notebooks` stores adjacent
pieces of a stream as one output; these checks hold every stored notebook, and
the built HTML, to it.
"""
from __future__ import annotations

import re

import nbformat
import pytest

from book_support import BOOK, pages
from labkit.tools import execute_notebooks as ex

NOTEBOOKS = ex.notebooks([str(BOOK)])


def _split_lines(nb):
    """(cell index, why) for every place a stored output cuts a line or a stream."""
    found = []
    for index, cell in enumerate(nb.cells):
        outputs = cell.get("outputs", [])
        for a, b in zip(outputs, outputs[1:]):
            if a.get("output_type") == b.get("output_type") == "stream" \
                    and a.get("name") == b.get("name"):
                found.append((index, f"two adjacent {a['name']} pieces: {a['text'][-40:]!r}"))
        streams = [o for o in outputs if o.get("output_type") == "stream"]
        for i, out in enumerate(streams):
            text = ex._text(out["text"])
            later_same = any(o["name"] == out["name"] for o in streams[i + 1:])
            if later_same and not text.endswith("\n"):
                found.append((index, f"{out['name']} line cut before another output: "
                                     f"{text[-40:]!r}"))
            if not text.strip():
                found.append((index, f"a {out['name']} piece of whitespace only"))
    return found


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_stored_output_is_whole_lines(path):
    nb = nbformat.read(path, as_version=4)
    problems = _split_lines(nb)
    assert not problems, (f"{path.name}: {len(problems)} cut lines (re-execute with "
                          f"`python -m labkit.tools.execute_notebooks`): {problems[:5]}")


def test_the_check_sees_a_cut_line():
    nb = nbformat.v4.new_notebook()
    cell = nbformat.v4.new_code_cell("%ros2 param describe /turtlesim background_g")
    cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=t)
                    for t in ("Parameter name:", " ", "background_g\n")]
    nb.cells.append(cell)
    assert len(_split_lines(nb)) >= 3
    ex.tidy(nb)
    assert _split_lines(nb) == []
    assert [o["text"] for o in cell.outputs] == ["Parameter name: background_g\n"]


def test_tidy_keeps_stream_order_and_static_faces():
    nb = nbformat.v4.new_notebook()
    cell = nbformat.v4.new_code_cell("x")
    view = {"version_major": 2, "version_minor": 0, "model_id": "abc"}
    cell.outputs = [
        nbformat.v4.new_output("stream", name="stdout", text="a\n"),
        nbformat.v4.new_output("stream", name="stdout", text="b\n"),
        nbformat.v4.new_output("stream", name="stderr", text="c\n"),
        nbformat.v4.new_output("stream", name="stdout", text="d\n"),
        nbformat.v4.new_output("display_data", data={
            "image/png": "iVBO", "text/plain": "<pic>", ex.WIDGET_VIEW: view}),
        nbformat.v4.new_output("display_data", data={   # no static face: kept
            "text/plain": "VBox()", ex.WIDGET_VIEW: view}),
    ]
    nb.cells.append(cell)
    ex.tidy(nb)
    assert [(o.get("name"), o.get("text")) for o in cell.outputs[:3]] == [
        ("stdout", "a\nb\n"), ("stderr", "c\n"), ("stdout", "d\n")]
    assert set(cell.outputs[3]["data"]) == {"image/png", "text/plain"}
    assert ex.WIDGET_VIEW in cell.outputs[4]["data"]


_STREAM_BLOCK = re.compile(
    r'<div class="output (stream|stderr)[^"]*"><div class="highlight"><pre><span></span>'
    r'(.*?)</pre></div>\s*</div>', re.S)


def test_html_shows_each_cli_line_whole(book_html):
    """In the built book a stream is one block per run of the same stream: no block
    that is only blanks, no two blocks of one stream in a row (a cut line)."""
    problems = []
    for page in pages(book_html):
        html = page.read_text(encoding="utf-8")
        for output in html.split('<div class="cell_output docutils container">')[1:]:
            output = output.split('<div class="cell docutils container"')[0]
            blocks = list(_STREAM_BLOCK.finditer(output))
            for a, b in zip(blocks, blocks[1:]):
                between = output[a.end():b.start()].strip()
                if a.group(1) == b.group(1) and not between:
                    problems.append((page.name, a.group(2)[-40:], b.group(2)[:40]))
            problems += [(page.name, "blank block", "") for m in blocks
                         if not re.sub(r"<[^>]+>", "", m.group(2)).strip()]
    assert not problems, f"{len(problems)} cut lines in the HTML, e.g. {problems[:5]}"


def test_tidy_keeps_only_the_widget_state_still_shown():
    nb = nbformat.v4.new_notebook()
    view = lambda mid: {"version_major": 2, "version_minor": 0, "model_id": mid}  # noqa: E731
    cell = nbformat.v4.new_code_cell("x")
    cell.outputs = [
        nbformat.v4.new_output("display_data", data={       # a canvas with its PNG
            "image/png": "iVBO", "text/plain": "<c>", ex.WIDGET_VIEW: view("aa")}),
        nbformat.v4.new_output("display_data", data={       # sliders: widget only
            "text/plain": "VBox()", ex.WIDGET_VIEW: view("bb")}),
    ]
    nb.cells.append(cell)
    nb.metadata["widgets"] = {ex.WIDGET_STATE: {"version_major": 2, "version_minor": 0,
                                                "state": {
        "aa": {"state": {"layout": "IPY_MODEL_a1"}}, "a1": {"state": {}},
        "bb": {"state": {"children": ["IPY_MODEL_b1"], "layout": "IPY_MODEL_b2"}},
        "b1": {"state": {"layout": "IPY_MODEL_b3"}}, "b2": {"state": {}},
        "b3": {"state": {}}}}}
    ex.tidy(nb)
    assert set(nb.metadata["widgets"][ex.WIDGET_STATE]["state"]) == {"bb", "b1", "b2", "b3"}
    nb.cells[0].outputs = nb.cells[0].outputs[:1]
    ex.tidy(nb)
    assert "widgets" not in nb.metadata
