"""Re-run one learner's notebook for grading, inside the sandbox `collect` made for it:

    python -m labkit.teacher.runner NOTEBOOK RESULTS.json

Already in its own process (resource limits set by the parent before exec; network
namespace unshared where the machine allows it). Here: no internet sockets at all
(`_block_network`), virtual time, an in-process IPython shell; every code cell in
order except the book's reference answers (tagged ``solution``) and the check cell
repeated right after one. Every report of `labkit.exercises` is recorded; the last
report of an exercise is its result. RESULTS.json: {"reports": [...], "errors": [...]}.
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import socket
import sys

os.environ["LABKIT_TIME"] = "virtual"
os.environ["LABKIT_DDS"] = "off"
os.environ.setdefault("TZ", "UTC")
os.environ.pop("LABKIT_EXERCISE_LOG", None)


def _block_network() -> None:
    """Refuse every internet socket (AF_INET/AF_INET6); local pipes still work."""
    refused = (socket.AF_INET, socket.AF_INET6)
    real_init = socket.socket.__init__

    def guarded(self, family=-1, type=-1, proto=-1, fileno=None):
        if family in refused or (family == -1 and fileno is None):
            raise PermissionError(1, "Operation not permitted (no network while grading)")
        real_init(self, family, type, proto, fileno)
    socket.socket.__init__ = guarded
    socket.create_connection = _refuse
    socket.getaddrinfo = _refuse


def _refuse(*args, **kwargs):
    raise PermissionError(1, "Operation not permitted (no network while grading)")


def graded_cells(nb: dict) -> list[tuple[int, str]]:
    """(index, source) of the code cells a grading run executes."""
    out, after_solution = [], False
    for i, cell in enumerate(nb.get("cells", [])):
        if cell.get("cell_type") != "code":
            continue
        tags = cell.get("metadata", {}).get("tags", [])
        source = "".join(cell.get("source", ""))
        if "solution" in tags:
            after_solution = True
            continue
        if after_solution and "Checker(" in source:
            after_solution = False          # the book's own re-check of its answer
            continue
        after_solution = False
        out.append((i, source))
    return out


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    nb_path, results_path = argv[0], argv[1]
    with open(nb_path, encoding="utf-8") as f:
        nb = json.load(f)
    os.chdir(os.path.dirname(os.path.abspath(nb_path)))
    _block_network()
    from IPython.core.interactiveshell import InteractiveShell
    from labkit import exercises

    reports: list = []
    exercises.REPORT_HOOKS.append(lambda result: reports.append(result))
    shell = InteractiveShell.instance()
    errors = []
    for index, source in graded_cells(nb):
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(buf):
            res = shell.run_cell(source)
            sys.stdout.flush()
        exc = res.error_in_exec or res.error_before_exec
        if exc is not None:
            errors.append({"cell": index, "error": f"{type(exc).__name__}: {exc}"[:300]})
    with contextlib.suppress(Exception):
        import labkit
        labkit.reset()
    with open(results_path, "w", encoding="utf-8") as f:
        json.dump({"reports": reports, "errors": errors}, f, ensure_ascii=False)
    return 0


if __name__ == "__main__":
    sys.exit(main())
