"""Execute every notebook under a folder in place, in virtual time, so the
stored outputs are the ones nbval will compare against.

    python -m labkit.tools.execute_notebooks book [more paths...]
"""
import os
import pathlib
import sys
import time


def execute(path, timeout=600):
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    nbformat.write(nb, path)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    os.environ["LABKIT_TIME"] = "virtual"
    os.environ.setdefault("TZ", "UTC")
    paths = []
    for arg in argv or ["book"]:
        p = pathlib.Path(arg)
        if p.suffix == ".ipynb":
            paths.append(p)
        else:
            paths += sorted(q for q in p.rglob("*.ipynb")
                            if "_build" not in q.parts and ".ipynb_checkpoints" not in q.parts)
    failed = 0
    for p in paths:
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
