"""The book's exercises, as stored: each one is first checked against the
learner's stub (the report fails, with a hint), then against the collapsed
reference solution (the report passes). So CI proves both halves."""
from __future__ import annotations

import json
import re

import pytest

from book_support import BOOK

TITLE = re.compile(r"^【(练习 [^】]+)】$", re.M)
PASSED, FAILED = "全部正确！", "还差"
# the chapters, and the appendix notebooks (connect_real_ros has exercises too)
CHAPTERS = sorted(BOOK.glob("part*/ch*.ipynb")) + sorted(BOOK.glob("*.ipynb"))


def cell_text(cell) -> str:
    return "".join("".join(o.get("text", "")) for o in cell.get("outputs", [])
                   if o.get("output_type") == "stream")


def reports(path):
    """[(cell index, exercise title, passed)] of every Checker report, in order."""
    nb = json.loads(path.read_text(encoding="utf-8"))
    found = []
    for index, cell in enumerate(nb["cells"]):
        if cell["cell_type"] != "code":
            continue
        text = cell_text(cell)
        for m in TITLE.finditer(text):
            rest = text[m.end():]
            nxt = TITLE.search(rest)
            body = rest[: nxt.start()] if nxt else rest
            found.append((index, m.group(1), PASSED in body and FAILED not in body))
    return nb, found


def solution_cells(nb) -> list[int]:
    return [i for i, c in enumerate(nb["cells"])
            if "solution" in c.get("metadata", {}).get("tags", [])]


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_each_exercise_fails_on_the_stub_and_passes_with_the_solution(path):
    nb, found = reports(path)
    solutions = solution_cells(nb)
    for title in dict.fromkeys(t for _, t, _ in found):
        runs = [(i, ok) for i, t, ok in found if t == title]
        first_fail = next((i for i, ok in runs if not ok), None)
        assert first_fail is not None, f"{title}: no stored report shows the stub failing"
        later_pass = next((i for i, ok in runs if ok and i > first_fail), None)
        assert later_pass is not None, f"{title}: no passing report after the failing one"
        assert any(first_fail < s < later_pass for s in solutions), \
            f"{title}: no collapsed solution cell between the failing and the passing check"
        assert runs[-1][1], f"{title}: the last stored report does not pass"


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_solution_cells_are_collapsed_everywhere(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    for i in solution_cells(nb):
        meta = nb["cells"][i]["metadata"]
        assert meta.get("jupyter", {}).get("source_hidden") is True, f"cell {i}: open in JupyterLab"
        assert "hide-input" in meta["tags"], f"cell {i}: open in the HTML book"
        assert meta.get("mystnb", {}).get("code_prompt_show") == "显示参考答案", f"cell {i}: toggle label"
