"""A collapsed reference solution must not show its answer in JupyterLab.

JupyterLab 4 draws a collapsed cell (`source_hidden`) as its first source line
followed by "•••": a solution whose first line is `%ros2 run turtlesim
draw_square` or `prediction = 'ABORTED'` gives the answer away in plain sight.
So the first line of every solution cell says what the cell is (a comment
starting with 参考答案) — or it is a cell magic (`%%writefile <file>`), which
must stay first and names only the file the exercise asked for.
"""
from __future__ import annotations

import json

import pytest

from book_support import BOOK

PREFIX = "# 参考答案"
# tools/exercise_cells.py writes that first line into every solution cell.

CHAPTERS = sorted(p for part in ("part1_basics", "part2_facer", "part3_tools")
                  for p in (BOOK / part).glob("ch*.ipynb")) + sorted(BOOK.glob("*.ipynb"))


def revealing_first_lines(nb) -> list[str]:
    found = []
    for i, cell in enumerate(nb["cells"]):
        if "solution" not in cell.get("metadata", {}).get("tags", []):
            continue
        source = "".join(cell["source"])
        first = source.split("\n", 1)[0]
        if not (first.startswith(PREFIX) or first.startswith("%%")):
            found.append(f"cell {i}: {first!r}")
    return found


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_collapsed_solution_shows_no_answer(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    assert not revealing_first_lines(nb), \
        f"start each solution with a line '{PREFIX}（…）':\n" + "\n".join(revealing_first_lines(nb))


def test_the_rule_catches_an_answer_on_the_first_line():
    nb = {"cells": [
        {"cell_type": "code", "metadata": {"tags": ["hide-input", "solution"]},
         "source": ["%ros2 run turtlesim draw_square\n"]},
        {"cell_type": "code", "metadata": {"tags": ["hide-input", "solution"]},
         "source": [PREFIX + "（折叠着）\n", "%ros2 run turtlesim draw_square\n"]},
        {"cell_type": "code", "metadata": {"tags": ["hide-input", "solution"]},
         "source": ["%%writefile hello.py\n", "print('hi')\n"]},
        {"cell_type": "code", "metadata": {}, "source": ["x = 1\n"]},
    ]}
    assert revealing_first_lines(nb) == ["cell 0: '%ros2 run turtlesim draw_square'"]
