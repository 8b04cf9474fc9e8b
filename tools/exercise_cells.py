"""Give every reference-solution cell of the book its collapsed form.

A cell tagged ``solution`` is collapsed in JupyterLab (``source_hidden`` and
``outputs_hidden``) and in the HTML book (tags ``hide-input`` and ``hide-output``:
one toggle for code and output, whose output would give the answer away), and its toggle says 显示参考答案 /
隐藏参考答案 instead of the generic 显示代码. JupyterLab still shows a collapsed
cell's first line, so that line is a comment saying what the cell is (unless
the cell is a ``%%`` cell magic, which must stay first). Run after editing notebooks:

    python tools/exercise_cells.py book            # rewrite in place
    python tools/exercise_cells.py --check book    # exit 1 if anything is off
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

SHOW, HIDE = "显示参考答案", "隐藏参考答案"
FIRST_LINE = "# 参考答案（折叠着：先自己做，做不出来再展开）"


def notebooks(paths):
    for arg in paths:
        p = Path(arg)
        if p.suffix == ".ipynb":
            yield p
        else:
            yield from sorted(q for q in p.rglob("*.ipynb")
                              if "_build" not in q.parts and ".ipynb_checkpoints" not in q.parts)


def normalize_cell(cell: dict) -> bool:
    """Set the solution metadata on one cell; True if it changed."""
    meta = cell.setdefault("metadata", {})
    if "solution" not in meta.get("tags", []):
        return False
    before = json.dumps(meta, sort_keys=True)
    # The output goes with the code: it would give the answer away.
    meta.setdefault("jupyter", {}).update(source_hidden=True, outputs_hidden=True)
    for tag in ("hide-input", "hide-output"):
        if tag not in meta["tags"]:
            meta["tags"].append(tag)
    meta.setdefault("mystnb", {}).update(code_prompt_show=SHOW, code_prompt_hide=HIDE)
    changed = json.dumps(meta, sort_keys=True) != before
    source = cell["source"] if isinstance(cell["source"], str) else "".join(cell["source"])
    if not (source.startswith("# 参考答案") or source.startswith("%%")):
        lines = (FIRST_LINE + "\n" + source).splitlines(keepends=True)
        cell["source"] = lines if isinstance(cell["source"], list) else "".join(lines)
        changed = True
    return changed


def normalize(path: Path, write: bool = True) -> bool:
    text = path.read_text(encoding="utf-8")
    nb = json.loads(text)
    changed = False
    for cell in nb["cells"]:
        changed |= normalize_cell(cell)
    if changed and write:
        # nbformat's own layout: one space indent, keys sorted, a final newline
        path.write_text(json.dumps(nb, indent=1, sort_keys=True, ensure_ascii=False) + "\n",
                        encoding="utf-8")
    return changed


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    ap.add_argument("paths", nargs="*", default=["book"])
    args = ap.parse_args(argv)
    off = [p for p in notebooks(args.paths) if normalize(p, write=not args.check)]
    for p in off:
        print(("needs solution metadata: " if args.check else "updated: ") + str(p))
    return 1 if (off and args.check) else 0


if __name__ == "__main__":
    sys.exit(main())
