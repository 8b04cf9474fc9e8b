"""The chapters as nbgrader source notebooks:

    labkit teacher nbgrader CHAPTER.ipynb... --course DIR [--assignment NAME]

writes DIR/source/NAME/<chapter>.ipynb (NAME: the chapter's stem, e.g. ch03_topics).
In each exercise the TODO stub becomes an autograded answer cell: the stub as the book
ships it, then the book's reference answer between ``### BEGIN SOLUTION`` and
``### END SOLUTION`` (nbgrader's generate_assignment takes it out, autograde grades the
learner's own code); the check cell becomes the answer's tests (locked), worth one point
per checked item, with partial credit: the cell's value is the number of items passed
(the learner's nodes' logs go to stdout during the check: nbgrader gives 0 for stderr).
The book's reference-answer cells and the re-check after them are left out; every other
cell stays as it is, read-only. Set nbgrader's ClearSolutions.code_stub to a comment
(the course's nbgrader_config.py) so a released stub does not raise.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path

ITEM = re.compile(r"^  \[(对|错)\] ", re.M)
TITLE = re.compile(r'Checker\(\s*["\']([^"\']+)["\']')


def _source(cell) -> str:
    src = cell.get("source", "")
    return "".join(src) if isinstance(src, list) else src


def _items(cell) -> int:
    text = "".join("".join(o.get("text", "")) for o in cell.get("outputs", [])
                   if o.get("output_type") == "stream")
    return len(ITEM.findall(text))


def _meta(grade_id, *, solution=False, grade=False, locked=False, points=None):
    meta = {"grade": grade, "grade_id": grade_id, "locked": locked, "schema_version": 3,
            "solution": solution, "task": False}
    if points is not None:
        meta["points"] = points
    return meta


def _slug(title: str) -> str:
    m = re.search(r"(\d+)\.(\d+)", title)
    return f"ex{m.group(1)}_{m.group(2)}" if m else re.sub(r"\W+", "_", title)


def export(nb: dict) -> dict:
    """The nbgrader source version of one chapter notebook (a new dict)."""
    cells = nb["cells"]
    out, skip = [], set()
    answers = {}           # stub index -> reference source
    for i, cell in enumerate(cells):
        if "solution" not in cell.get("metadata", {}).get("tags", []):
            continue
        for j in range(i - 1, -1, -1):
            if cells[j]["cell_type"] == "code" and "Checker(" not in _source(cells[j]) \
                    and "solution" not in cells[j].get("metadata", {}).get("tags", []):
                answers[j] = _source(cell)
                break
        skip.add(i)
        for k in range(i + 1, len(cells)):          # the book's re-check of its answer
            if cells[k]["cell_type"] == "code":
                if "Checker(" in _source(cells[k]):
                    skip.add(k)
                    points = _items(cells[k])
                    answers[j] = (answers[j], points)
                break
            if k > i + 1 and cells[k]["cell_type"] == "markdown":
                break
    check_of = {}
    for j in answers:
        for k in range(j + 1, len(cells)):
            if cells[k]["cell_type"] == "code" and "Checker(" in _source(cells[k]):
                check_of[j] = k
                break
    counter = 0
    for i, cell in enumerate(cells):
        if i in skip:
            continue
        new = json.loads(json.dumps(cell))
        new.setdefault("metadata", {})
        if new["cell_type"] == "code":
            new["outputs"], new["execution_count"] = [], None
            new["metadata"].pop("execution", None)
        if i in answers:
            ref, points = answers[i] if isinstance(answers[i], tuple) else (answers[i], 1)
            title = TITLE.search(_source(cells[check_of[i]])).group(1)
            stub = _source(cell).rstrip("\n")
            new["source"] = f"{stub}\n### BEGIN SOLUTION\n{ref.rstrip()}\n### END SOLUTION\n"
            new["metadata"]["nbgrader"] = _meta(f"{_slug(title)}_answer", solution=True)
        elif i in check_of.values():
            j = next(a for a, k in check_of.items() if k == i)
            points = answers[j][1] if isinstance(answers[j], tuple) else 1
            title = TITLE.search(_source(cell)).group(1)
            # nbgrader scores 0 for any stderr in a tests cell: the logs of the learner's
            # running nodes go to stdout while the check runs
            new["source"] = ("import contextlib as _cl, sys as _sys\n"
                             "_quiet = _cl.redirect_stderr(_sys.stdout)\n_quiet.__enter__()\n" +
                             _source(cell).rstrip("\n") +
                             "\n_quiet.__exit__(None, None, None)\n"
                             f"# nbgrader：每项 1 分，共 {points} 分\n"
                             f"min(len(c.result()['passed_items']), {points})\n")
            new["metadata"]["nbgrader"] = _meta(f"{_slug(title)}_check", grade=True,
                                                locked=True, points=points)
        else:
            counter += 1
            new["metadata"]["nbgrader"] = _meta(f"cell_{counter:03d}", locked=True)
        out.append(new)
    result = dict(nb, cells=out)
    return json.loads(json.dumps(result))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="labkit teacher nbgrader",
                                     description="chapters as nbgrader source notebooks")
    parser.add_argument("notebooks", nargs="+")
    parser.add_argument("--course", required=True, help="the nbgrader course folder")
    parser.add_argument("--assignment", help="assignment name (default: the chapter's stem)")
    args = parser.parse_args(argv)
    for name in args.notebooks:
        path = Path(name)
        if not path.is_file():
            print(f"labkit teacher nbgrader: error: no such notebook: '{name}'", file=sys.stderr)
            return 2
        nb = json.loads(path.read_text(encoding="utf-8"))
        target = Path(args.course) / "source" / (args.assignment or path.stem) / path.name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(json.dumps(export(nb), ensure_ascii=False, indent=1) + "\n",
                          encoding="utf-8")
        print(target)
    return 0
