"""A collapsed reference solution hides its output too (the output gives the
answer away): in JupyterLab (metadata jupyter.outputs_hidden next to
source_hidden) and in the HTML book (tag hide-output: one toggle 显示参考答案
for code and output). Before, ch03's 练习 3.1 showed `publishing #1: ...`
under the closed toggle."""

from __future__ import annotations

import json
import sys

import pytest

from book_support import BOOK, ROOT

sys.path.insert(0, str(ROOT / "tools"))
import exercise_cells  # noqa: E402

NOTEBOOKS = list(exercise_cells.notebooks([BOOK]))


def solution_cells(nb):
    return [(i, c) for i, c in enumerate(nb["cells"])
            if "solution" in c.get("metadata", {}).get("tags", [])]


def test_there_are_solutions():
    assert sum(len(solution_cells(json.loads(p.read_text(encoding="utf-8"))))
               for p in NOTEBOOKS) >= 20


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_solution_outputs_are_hidden_with_the_solution(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    for i, cell in solution_cells(nb):
        meta = cell["metadata"]
        assert meta.get("jupyter", {}).get("outputs_hidden") is True, f"cell {i}: output open in JupyterLab"
        assert "hide-output" in meta["tags"], f"cell {i}: output open in the HTML book"


def test_normalize_hides_a_new_solutions_output():
    cell = {"cell_type": "code", "metadata": {"tags": ["solution"]}, "source": "print(1)\n",
            "outputs": []}
    assert exercise_cells.normalize_cell(cell)
    assert cell["metadata"]["jupyter"] == {"source_hidden": True, "outputs_hidden": True}
    assert {"hide-input", "hide-output"} <= set(cell["metadata"]["tags"])
    assert not exercise_cells.normalize_cell(cell)  # idempotent


VISIBLE_SOLUTION_OUTPUTS = """(() => Array.from(document.querySelectorAll('.tag_solution'))
  .map(c => ({outputs: Array.from(c.querySelectorAll('.cell_output'))
                .filter(o => o.getClientRects().length && o.innerText.trim()).length,
              cells: 1}))
  .reduce((a, b) => ({outputs: a.outputs + b.outputs, cells: a.cells + b.cells}),
          {outputs: 0, cells: 0}))()"""


def test_html_solution_output_stays_closed_until_opened(page, served):
    page.open(served("book", "part1_basics/ch03_topics.html"))
    closed = page.evaluate(VISIBLE_SOLUTION_OUTPUTS)
    assert closed["cells"] >= 3
    assert closed["outputs"] == 0, closed
    page.evaluate("document.querySelectorAll('.tag_solution details').forEach(d => d.open = true)")
    opened = page.evaluate(VISIBLE_SOLUTION_OUTPUTS)
    assert opened["outputs"] >= 1, opened  # 练习 3.1 prints what it publishes
