"""Execute every notebook under a folder in place, in virtual time, so the
stored outputs are the ones nbval will compare against.

    python -m labkit.tools.execute_notebooks book [more paths...]
    python -m labkit.tools.execute_notebooks --tidy-only book   # no kernel: tidy only

What is stored is what a reader should see, as a terminal shows it:
- adjacent pieces of the same stream are one output (a kernel sends a stream in
  pieces as it flushes; a piece that is only a space is dropped by the HTML
  build, splitting a CLI line in two);
- a picture's live widget view is not stored where the output also has a static
  face (PNG, JPEG, SVG, HTML): the widget's model lives in the kernel, so a
  stored view only reads "model not found" when the notebook is reopened; the
  saved widget state keeps only the widgets still shown.
"""
import json
import os
import pathlib
import re
import sys
import time

WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
WIDGET_STATE = "application/vnd.jupyter.widget-state+json"
STATIC_FACES = ("image/png", "image/jpeg", "image/svg+xml", "text/html")


def coalesce_streams(outputs):
    """Adjacent stream outputs of the same name merged into one (order kept)."""
    merged = []
    for out in outputs:
        if (out.get("output_type") == "stream" and merged
                and merged[-1].get("output_type") == "stream"
                and merged[-1].get("name") == out.get("name")):
            merged[-1]["text"] = _text(merged[-1]["text"]) + _text(out["text"])
            continue
        if out.get("output_type") == "stream":
            out["text"] = _text(out["text"])
        merged.append(out)
    return merged


def _text(value):
    return "".join(value) if isinstance(value, list) else value


def drop_live_views(outputs):
    """Remove widget views from outputs that carry a static face as well."""
    for out in outputs:
        data = out.get("data")
        if data and WIDGET_VIEW in data and any(k in data for k in STATIC_FACES):
            del data[WIDGET_VIEW]
    return outputs


def prune_widget_state(nb):
    """Keep the saved widget state of the widgets still shown (and what they refer
    to); a notebook that shows none keeps none (its HTML page loads no widget code)."""
    widgets = nb.metadata.get("widgets", {})
    saved = widgets.get(WIDGET_STATE, {})
    state = saved.get("state")
    if state is None:
        return nb
    wanted = [out["data"][WIDGET_VIEW]["model_id"] for cell in nb.cells
              for out in cell.get("outputs", []) if WIDGET_VIEW in out.get("data", {})]
    keep = set()
    while wanted:
        model_id = wanted.pop()
        if model_id in keep or model_id not in state:
            continue
        keep.add(model_id)
        wanted += re.findall(r"IPY_MODEL_([0-9a-f]+)", json.dumps(state[model_id]))
    saved["state"] = {k: v for k, v in state.items() if k in keep}
    if not keep:
        del widgets[WIDGET_STATE]
        if not widgets:
            del nb.metadata["widgets"]
    return nb


def tidy(nb):
    """What execute() applies to a notebook before storing it; returns the notebook."""
    for cell in nb.cells:
        if cell.get("cell_type") == "code" and cell.get("outputs"):
            cell.outputs = coalesce_streams(drop_live_views(cell.outputs))
    return prune_widget_state(nb)


def execute(path, timeout=600):
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    nbformat.write(tidy(nb), path)


def tidy_file(path):
    import nbformat
    nb = nbformat.read(path, as_version=4)
    before = nbformat.writes(nb)
    after = nbformat.writes(tidy(nb))
    if after != before:
        path.write_text(after + ("" if after.endswith("\n") else "\n"), encoding="utf-8")
        return True
    return False


def notebooks(args):
    paths = []
    for arg in args or ["book"]:
        p = pathlib.Path(arg)
        if p.suffix == ".ipynb":
            paths.append(p)
        else:
            paths += sorted(q for q in p.rglob("*.ipynb")
                            if "_build" not in q.parts and ".ipynb_checkpoints" not in q.parts)
    return paths


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["--tidy-only"]:
        for p in notebooks(argv[1:]):
            if tidy_file(p):
                print(f"tidied {p}")
        return 0
    os.environ["LABKIT_TIME"] = "virtual"
    os.environ.setdefault("TZ", "UTC")
    failed = 0
    for p in notebooks(argv):
        t0 = time.monotonic()
        try:
            execute(p)
            print(f"executed {p} [{time.monotonic() - t0:.1f}s]")
        except Exception as exc:  # report every notebook, fail at the end
            failed += 1
            print(f"FAILED {p}: {str(exc).strip().splitlines()[-1] if str(exc).strip() else exc!r}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
