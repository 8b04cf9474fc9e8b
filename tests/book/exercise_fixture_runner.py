"""Run exercise fixtures as a learner's cells run: one fresh Python process per
batch, an in-process IPython shell in virtual time, in a scratch copy of the
chapter's folder; the cells before the exercise's stub as stored, then, for each
fixture, the fixture's code in place of the stub and the stored check cell.

    python exercise_fixture_runner.py <job.json>   (writes a JSON list to job["results"])

job.json: {"notebook": path, "stub": index, "check": index, "title": "练习 2.2",
           "fixtures": [{"name": ..., "code": ...}], "share": false}

With "share": true the fixtures run one after another after a single prefix
(only for exercises whose fixtures leave nothing running that the next one could
see: predictions, variables, pure computations); the shell's namespace is put
back between them. Otherwise the job has one fixture.
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import shutil
import sys
import tempfile

os.environ["LABKIT_TIME"] = "virtual"
os.environ.setdefault("TZ", "UTC")


def _run(shell, source: str):
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(buf):
        res = shell.run_cell(source)
        # whole lines of background processes that wait for the cell's end
        sys.stdout.flush()
    return res, buf.getvalue()


def main(job_path: str) -> int:
    with open(job_path, encoding="utf-8") as f:
        job = json.load(f)
    src_nb = os.path.abspath(job["notebook"])
    folder = os.path.dirname(src_nb)
    scratch = tempfile.mkdtemp(prefix="labkit_exfx_")
    try:
        copy = os.path.join(scratch, os.path.basename(folder))
        shutil.copytree(folder, copy, ignore=shutil.ignore_patterns(
            "_build", "_work", ".labkit_tmp", ".ipynb_checkpoints", "*.exercises.yaml"))
        # a chapter that runs real rclpy finds the reference environment beside book/
        # ('../.venv-rosref' from the top of the book), as it does in the work tree
        rosref = os.path.join(os.path.dirname(folder), ".venv-rosref")
        if os.path.isdir(rosref):
            os.symlink(rosref, os.path.join(scratch, ".venv-rosref"))
        os.chdir(copy)
        with open(src_nb, encoding="utf-8") as f:
            nb = json.load(f)
        cells = nb["cells"]

        from IPython.core.interactiveshell import InteractiveShell
        from labkit import exercises

        shell = InteractiveShell.instance()
        prefix_errors = []
        for i, cell in enumerate(cells[: job["stub"]]):
            if cell["cell_type"] == "code":
                res, out = _run(shell, "".join(cell["source"]))
                if not res.success:
                    prefix_errors.append(f"cell {i}: {type(res.error_in_exec).__name__}: {res.error_in_exec}")
        check_src = "".join(cells[job["check"]]["source"])
        between = [("".join(c["source"])) for c in cells[job["stub"] + 1: job["check"]]
                   if c["cell_type"] == "code"]
        from labkit import process

        saved_ns, saved_cwd = dict(shell.user_ns), os.getcwd()
        results = []
        for n, fx in enumerate(job["fixtures"]):
            before = set(map(id, process.processes()))
            if n and job.get("share"):
                shell.user_ns.clear()
                shell.user_ns.update(saved_ns)
                os.chdir(saved_cwd)
            reports = []
            exercises.REPORT_HOOKS[:] = [reports.append]
            _, fx_out = _run(shell, fx["code"])
            for src in between:
                _run(shell, src)
            res, out = _run(shell, check_src)
            mine = [r for r in reports if r["exercise"] == job["title"]]
            results.append({
                "name": fx["name"],
                "report": mine[-1] if mine else None,
                "check_ok": bool(res.success),
                "traceback": "Traceback" in out,
                "output": out[-3000:],
                "fixture_output": fx_out[-1500:],
                "prefix_errors": prefix_errors,
            })
            with open(job["results"], "w", encoding="utf-8") as f:
                json.dump(results, f, ensure_ascii=False)
            if job.get("share"):
                # what this fixture started ends with it (the next one starts from the prefix)
                for proc in process.processes():
                    if id(proc) not in before and proc.running:
                        proc.stop()
    finally:
        try:
            import labkit
            labkit.reset()
        except Exception:
            pass
        shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
