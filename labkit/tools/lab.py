"""`make lab`: the book in JupyterLab, live, on a working copy.

    python -m labkit.tools.lab [--root lab] [jupyterlab options...]

JupyterLab saves (and autosaves) the notebooks it has open. So that a learner's
checkout stays clean, the book's files are copied once into a working folder
(`lab/`, ignored by git) and JupyterLab opens that: run, change, break and save
freely there; delete a file (or the whole folder) to get the book's version back
on the next `make lab`. Files already in the working copy are never overwritten.

Saving also drops the live widget views from outputs: their models live in the
kernel, so after a reload they would only read "Error displaying widget: model
not found"; the static face stored beside them (the PNG of a canvas, the picture
of a keypad, a job's command line) is what a reopened notebook shows.
"""
import os
import pathlib
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
BOOK = ROOT / "book"
SKIP = {"_build", "_work", ".ipynb_checkpoints", "__pycache__"}
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def working_copy(book=BOOK, target=ROOT / "lab"):
    """Copy the book's files that the working copy does not have yet; returns the
    list of files copied."""
    copied = []
    for src in sorted(book.rglob("*")):
        rel = src.relative_to(book)
        if any(part in SKIP for part in rel.parts) or not src.is_file():
            continue
        dst = target / rel
        if dst.exists():
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dst)
        copied.append(rel)
    return copied


def strip_live_views(model, **kwargs):
    """jupyter_server pre-save hook: no widget view is saved where the output has
    another face to show."""
    if model.get("type") != "notebook":
        return
    for cell in model["content"].get("cells", []):
        for out in cell.get("outputs", []) or []:
            data = out.get("data")
            if data and WIDGET_VIEW in data and len(data) > 1:
                del data[WIDGET_VIEW]


def command(root, extra=()):
    return [sys.executable, "-m", "jupyterlab", "--ip=127.0.0.1",
            f"--notebook-dir={root}",
            "--ContentsManager.pre_save_hook=labkit.tools.lab.strip_live_views",
            *extra]


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    root = ROOT / "lab"
    if argv[:1] == ["--root"]:
        root = pathlib.Path(argv[1]).resolve()
        argv = argv[2:]
    copied = working_copy(BOOK, root)
    if copied:
        print(f"labkit: {len(copied)} files of the book copied to {root.name}/ "
              "(your working copy; the book itself stays as shipped)")
    os.environ["LABKIT_TIME"] = "live"
    cmd = command(root, argv)
    os.execv(cmd[0], cmd)


if __name__ == "__main__":
    main()
