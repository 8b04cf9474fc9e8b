"""`labkit teacher collect FOLDER`: every learner's exercises in one table.

FOLDER holds one sub-folder per learner: the hub's home folders (/home/<learner>) or a
folder of submissions (<learner>/.../chNN_*.ipynb, e.g. nbgrader's submitted/). Each
chapter notebook found is copied with its folder into a scratch place and re-run in its
own process (labkit.teacher.runner): virtual time, so the same notebook gives the same
result every run; resource limits (address space, CPU seconds, file size, no core
files); no network (a new network namespace where the machine allows it, `unshare -n`,
and internet sockets refused inside Python in any case); a wall-clock timeout.

Writes OUT/exercises.csv (learner, notebook, exercise, passed, passed items, failed
items, hints) and OUT/exercises.html (learner x exercise, the hints under each failed
one). Grading guards against mistakes, not against a learner who sets out to forge a
result inside their own notebook's process.
"""
from __future__ import annotations

import argparse
import concurrent.futures
import csv
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

CHAPTER = re.compile(r"^ch\d\d_[A-Za-z0-9_]+\.ipynb$")
SKIP_DIRS = {".ipynb_checkpoints", "_build", "_work", ".labkit_tmp", "__pycache__", ".git",
             "node_modules", ".cache", ".local", ".venv"}
EXERCISE_ORDER = re.compile(r"(\d+)\.(\d+)")


def find_notebooks(learner_dir: Path, chapters: set[str] | None) -> list[Path]:
    found = []
    for root, dirs, files in os.walk(learner_dir):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
        for name in sorted(files):
            if CHAPTER.match(name) and (not chapters or name[:-6] in chapters):
                found.append(Path(root) / name)
    return found


def _limits(memory_mb: int, cpu_s: int):
    def apply():                     # runs in the child before exec
        import resource
        os.setsid()
        for what, value in ((resource.RLIMIT_AS, memory_mb * 1024 * 1024),
                            (resource.RLIMIT_CPU, cpu_s),
                            (resource.RLIMIT_FSIZE, 256 * 1024 * 1024),
                            (resource.RLIMIT_CORE, 0)):
            try:
                resource.setrlimit(what, (value, value))
            except (ValueError, OSError):
                pass
    return apply


_UNSHARE: list | None = None


def _unshare_prefix() -> list:
    """['unshare', '-n'] where a new network namespace can be made here, else []."""
    global _UNSHARE
    if _UNSHARE is None:
        _UNSHARE = []
        tool = shutil.which("unshare")
        if tool:
            try:
                ok = subprocess.run([tool, "-n", "true"], capture_output=True, timeout=10)
                if ok.returncode == 0:
                    _UNSHARE = [tool, "-n"]
            except (OSError, subprocess.TimeoutExpired):
                pass
    return _UNSHARE


def grade_notebook(path: Path, *, timeout: float = 300, memory_mb: int = 4096) -> dict:
    """Re-run one notebook in a sandboxed process; its reports and errors."""
    scratch = Path(tempfile.mkdtemp(prefix="labkit_grade_"))
    try:
        work = scratch / "work"
        shutil.copytree(path.parent, work, symlinks=True,
                        ignore=shutil.ignore_patterns(*SKIP_DIRS, "*.ipynb"))
        shutil.copy2(path, work / path.name)
        results = scratch / "results.json"
        env = {k: v for k, v in os.environ.items()
               if k in ("PATH", "LANG", "LC_ALL", "TZ", "PYTHONPATH", "SYSTEMROOT")}
        env.update(HOME=str(scratch), LABKIT_TIME="virtual", LABKIT_DDS="off",
                   LABKIT_NO_WINDOW="1", PYTHONDONTWRITEBYTECODE="1",
                   PYTHONPATH=os.pathsep.join(p for p in (str(Path(__file__).parents[2]),
                                                          env.get("PYTHONPATH")) if p),
                   MPLBACKEND="Agg")
        cmd = [*_unshare_prefix(), sys.executable, "-m", "labkit.teacher.runner",
               str(work / path.name), str(results)]
        try:
            proc = subprocess.run(cmd, cwd=work, env=env, capture_output=True, text=True,
                                  encoding="utf-8", errors="replace", timeout=timeout,
                                  preexec_fn=_limits(memory_mb, int(timeout) + 5))
            status = "ok" if proc.returncode == 0 else f"exit {proc.returncode}"
            tail = proc.stderr.strip().splitlines()[-1:] if proc.returncode else []
        except subprocess.TimeoutExpired:
            status, tail = f"timeout after {timeout:g} s", []
        data = {"reports": [], "errors": []}
        if results.exists():
            data = json.loads(results.read_text(encoding="utf-8"))
        data["status"] = status
        if tail:
            data["errors"].append({"cell": None, "error": tail[0][:300]})
        return data
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def _last_per_exercise(reports: list) -> dict:
    out = {}
    for r in reports:
        out[r["exercise"]] = r
    return out


def _order(title: str):
    m = EXERCISE_ORDER.search(title)
    return (int(m.group(1)), int(m.group(2)), title) if m else (999, 0, title)


def collect(folder: Path, out: Path, *, chapters=None, jobs: int = 2, timeout: float = 300,
            memory_mb: int = 4096) -> list[dict]:
    """Grade every learner under `folder`; write out/exercises.csv and .html; the rows."""
    folder = Path(folder)
    learners = sorted(p for p in folder.iterdir() if p.is_dir() and not p.name.startswith("."))
    work = [(p.name, nb) for p in learners for nb in find_notebooks(p, chapters)]
    rows: list[dict] = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = {pool.submit(grade_notebook, nb, timeout=timeout, memory_mb=memory_mb):
                   (learner, nb) for learner, nb in work}
        graded = {futures[f]: f.result() for f in concurrent.futures.as_completed(futures)}
    for (learner, nb), data in sorted(graded.items()):
        for title, r in _last_per_exercise(data["reports"]).items():
            rows.append({"learner": learner, "notebook": nb.stem, "exercise": title,
                         "passed": bool(r["passed"]), "passed_items": r["passed_items"],
                         "failed_items": [f["text"] for f in r["failed_items"]],
                         "hints": [f["hint"] for f in r["failed_items"]],
                         "status": data["status"]})
        if not data["reports"]:
            rows.append({"learner": learner, "notebook": nb.stem, "exercise": "",
                         "passed": False, "passed_items": [], "failed_items": [],
                         "hints": [e["error"] for e in data["errors"][-1:]],
                         "status": data["status"]})
    out.mkdir(parents=True, exist_ok=True)
    _write_csv(out / "exercises.csv", rows)
    _write_html(out / "exercises.html", rows, [p.name for p in learners])
    return rows


def _write_csv(path: Path, rows: list[dict]) -> None:
    with open(path, "w", encoding="utf-8", newline="") as f:
        w = csv.writer(f)
        w.writerow(["learner", "notebook", "exercise", "passed", "passed_items",
                    "failed_items", "hints", "status"])
        for r in rows:
            w.writerow([r["learner"], r["notebook"], r["exercise"], "yes" if r["passed"] else "no",
                        len(r["passed_items"]), len(r["failed_items"]), " | ".join(r["hints"]),
                        r["status"]])


def _write_html(path: Path, rows: list[dict], learners: list[str]) -> None:
    titles = sorted({r["exercise"] for r in rows if r["exercise"]}, key=_order)
    cell = {(r["learner"], r["exercise"]): r for r in rows}
    e = html.escape
    parts = ["<!DOCTYPE html>", '<html lang="zh-CN"><head><meta charset="utf-8">',
             "<title>练习结果</title><style>body{font-family:sans-serif}"
             "table{border-collapse:collapse}td,th{border:1px solid #999;padding:4px 8px;"
             "vertical-align:top}.ok{background:#dfd}.no{background:#fdd}"
             ".none{color:#888}ul{margin:0;padding-left:1.2em}</style></head><body>",
             "<h1>练习结果</h1>", f"<p>{len(learners)} 名学员，{len(titles)} 道练习。</p>",
             "<table><tr><th>学员</th>" + "".join(f"<th>{e(t)}</th>" for t in titles)
             + "<th>通过</th></tr>"]
    for learner in learners:
        tds, passed = [], 0
        for t in titles:
            r = cell.get((learner, t))
            if r is None:
                tds.append('<td class="none">未做</td>')
            elif r["passed"]:
                passed += 1
                tds.append('<td class="ok">[对]</td>')
            else:
                hints = "".join(f"<li>{e(h)}</li>" for h in r["hints"])
                tds.append(f'<td class="no">[错]<ul>{hints}</ul></td>')
        parts.append(f"<tr><th>{e(learner)}</th>{''.join(tds)}<td>{passed}/{len(titles)}</td></tr>")
    parts += ["</table>", "</body></html>", ""]
    path.write_text("\n".join(parts), encoding="utf-8")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="labkit teacher collect",
                                     description="Re-run every learner's exercises; CSV + HTML.")
    parser.add_argument("folder", help="one sub-folder per learner (home folders or submissions)")
    parser.add_argument("--out", default="grades", help="where exercises.csv/.html go")
    parser.add_argument("--chapter", action="append", help="only this chapter (e.g. ch03_topics)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=300, help="seconds per notebook")
    parser.add_argument("--memory", type=int, default=4096, help="MB of address space")
    args = parser.parse_args(argv)
    folder = Path(args.folder)
    if not folder.is_dir():
        print(f"labkit teacher collect: error: no such folder: '{args.folder}'", file=sys.stderr)
        return 2
    rows = collect(folder, Path(args.out), chapters=set(args.chapter or ()) or None,
                   jobs=args.jobs, timeout=args.timeout, memory_mb=args.memory)
    graded = {(r["learner"], r["notebook"]) for r in rows}
    print(f"{len(graded)} notebooks of {len({r['learner'] for r in rows})} learners graded: "
          f"{Path(args.out) / 'exercises.csv'}, {Path(args.out) / 'exercises.html'}")
    return 0
