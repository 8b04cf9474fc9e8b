"""Stored notebooks hold output as a terminal shows it: whole lines.

A kernel sends a stream in pieces (one per flush); stored as they came, a CLI
line can be cut in two (`Parameter name:` / ` ` / `background_g`), and the HTML
build shows each piece as its own block (and drops one that is only a space).
labkit writes whole lines and `labkit.tools.execute_notebooks` stores adjacent
pieces of a stream as one output; these checks hold every stored notebook, and
the built HTML, to it.
"""
from __future__ import annotations

import html as html_module
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
_ANSI = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")


def _html_lines(block):
    text = html_module.unescape(re.sub(r"<[^>]+>", "", block))
    return [line.rstrip() for line in text.split("\n")]


def _cut_lines_in_html(page_html, nb):
    """Lines the notebook's streams print (pieces joined as a terminal shows them) that
    the page does not show whole; and blank or doubled stream blocks."""
    blocks = list(_STREAM_BLOCK.finditer(page_html))
    shown = {line for m in blocks for line in _html_lines(m.group(2))}
    problems = []
    for cell in nb.cells:
        for name in ("stdout", "stderr"):
            text = "".join(ex._text(o["text"]) for o in cell.get("outputs", [])
                           if o.get("output_type") == "stream" and o.get("name") == name)
            for line in _ANSI.sub("", text).replace("\r\n", "\n").split("\n"):
                line = line.rstrip()
                if "\r" in line or "\b" in line:
                    continue            # a progress line the terminal rewrites
                if line.strip() and line not in shown:
                    problems.append(line)
    for output in page_html.split('<div class="cell_output docutils container">')[1:]:
        output = output.split('<div class="cell docutils container"')[0]
        cell_blocks = list(_STREAM_BLOCK.finditer(output))
        for a, b in zip(cell_blocks, cell_blocks[1:]):
            if a.group(1) == b.group(1) and not output[a.end():b.start()].strip():
                problems.append(f"two {a.group(1)} blocks in a row")
        problems += ["a blank block" for m in cell_blocks if not "".join(_html_lines(m.group(2))).strip()]
    return problems, len(blocks)


def test_html_shows_each_cli_line_whole(book_html):
    """In the built book every line a cell's output printed shows whole (the book merges
    a cell's stream pieces; myst-nb joins them line by line, so a line stored in pieces
    came out cut: `Parameter name:` / `background_g`)."""
    problems, seen = [], 0
    for page in pages(book_html):
        source = BOOK / page.relative_to(book_html).with_suffix(".ipynb")
        if not source.exists():
            continue
        found, blocks = _cut_lines_in_html(page.read_text(encoding="utf-8"),
                                           nbformat.read(source, as_version=4))
        seen += blocks
        problems += [(page.name, p) for p in found]
    assert seen > 200, f"only {seen} output blocks found: has the HTML's layout changed?"
    assert not problems, f"{len(problems)} lines cut in the HTML, e.g. {problems[:5]}"


def test_the_html_check_sees_a_cut_line():
    nb = nbformat.v4.new_notebook()
    cell = nbformat.v4.new_code_cell("%ros2 param describe /turtlesim background_g")
    cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=t)
                    for t in ("Parameter name:", " ", "background_g\n")]
    nb.cells.append(cell)
    block = ('<div class="cell_output docutils container"><div class="output stream '
             'highlight-myst-ansi notranslate"><div class="highlight"><pre><span></span>'
             '{}</pre></div>\n</div>')
    cut = block.format("Parameter name:\nbackground_g\n")
    assert _cut_lines_in_html(cut, nb)[0] == ["Parameter name: background_g"]
    assert _cut_lines_in_html(block.format("Parameter name: background_g\n"), nb) == ([], 1)
