"""The repository's jobs, one implementation for every OS: the Makefile calls this, and
on Windows (no make, no bash) PowerShell calls it directly.

    python3 tools/make.py book      # set up what the HTML book needs, then build it
    python3 tools/make.py test      # set up everything the suite needs, then run it
    python3 tools/make.py lab       # set up the learner's environment, then JupyterLab
    python3 tools/make.py setup     # only set up (what `test` needs)
    python3 tools/make.py unit | nbval | book-exec | bench
    py tools\\make.py book           # the same on Windows

Standard library only: it runs on the machine's Python (3.10-3.13), before .venv exists.

Set-up fits the job, each from the one lock (requirements.lock, environment markers):
  lab   .venv with labkit + JupyterLab + what the notebooks need (the `lab` extra)
  book  lab + jupyter-book and jieba (the `book` extra); tools/book_build.py adds node
  test  every pin of the lock (as CI always installed it), requirements-hub.lock when it
        exists (Linux), and .venv-rosref, the real rclpy that tests/dds and the
        benchmarks compare against, where its wheels exist (Linux x86_64, CPython
        3.11/3.12); elsewhere one line says it is skipped, and so do those tests.
A job already set up from the same lock and pyproject.toml is not installed again
(stamp .venv/.installed). The venv's python is .venv/bin/python, or
.venv\\Scripts\\python.exe on Windows.
"""
import hashlib
import os
import platform
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
VENV = ROOT / ".venv"
ROSREF = ROOT / ".venv-rosref"
LOCK = ROOT / "requirements.lock"
HUB_LOCK = ROOT / "requirements-hub.lock"
ROSREF_LOCK = ROOT / "requirements-rosref.lock"
LEVELS = ("lab", "book", "test")         # each includes the one before
SUPPORTED = ((3, 10), (3, 13))
ROSREF_PYTHONS = ("3.11", "3.12")


def venv_python(venv=VENV, windows=None):
    windows = os.name == "nt" if windows is None else windows
    return venv / ("Scripts/python.exe" if windows else "bin/python")


def say(text):
    print(f"setup: {text}", flush=True)


def run(cmd, **kw):
    return subprocess.run([str(c) for c in cmd], check=True, cwd=ROOT, **kw)


def _digest(*paths):
    h = hashlib.sha256()
    for p in paths:
        h.update(p.name.encode("utf-8"))
        h.update(p.read_bytes() if p.exists() else b"-")
    return h.hexdigest()


def _stamp(venv):
    return venv / ".installed"


def _done_level(venv, digest):
    """The job level .venv was set up for from these inputs, or -1."""
    try:
        level, stored = _stamp(venv).read_text(encoding="utf-8").split()
    except (OSError, ValueError):
        return -1
    return LEVELS.index(level) if stored == digest and level in LEVELS else -1


def check_python():
    if not SUPPORTED[0] <= sys.version_info[:2] <= SUPPORTED[1]:
        raise SystemExit(f"setup: Python {platform.python_version()} is not supported "
                         f"(labkit needs Python 3.10 to 3.13)")


def pip(python, *args):
    run([python, "-m", "pip", "--disable-pip-version-check", "-q", *args])


def setup_venv(job):
    """.venv for `job` (lab, book or test)."""
    check_python()
    level = LEVELS.index(job)
    digest = _digest(LOCK, ROOT / "pyproject.toml",
                     *([HUB_LOCK] if job == "test" and sys.platform == "linux" else []))
    if _done_level(VENV, digest) >= level:
        return venv_python()
    python = venv_python()
    if not python.exists():
        say(f"creating {VENV.name} with Python {platform.python_version()}")
        run([sys.executable, "-m", "venv", VENV])
    pip(python, "install", "--upgrade", "pip")
    say(f"installing the {job} environment from {LOCK.name}")
    if job == "test":
        # every pin, exactly as CI has always installed them, then labkit itself
        pip(python, "install", "-r", LOCK)
        pip(python, "install", "--no-deps", "-e", ".")
        if HUB_LOCK.exists() and sys.platform == "linux":
            pip(python, "install", "-r", HUB_LOCK)
    else:
        # only what the job needs, at the lock's versions
        pip(python, "install", "-c", LOCK, "-e", f".[{job}]")
    _stamp(VENV).write_text(f"{job} {digest}\n", encoding="utf-8")
    return python


def rosref_python():
    """A CPython that real rclpy's wheels exist for, or None (with the reason)."""
    if sys.platform != "linux" or platform.machine() not in ("x86_64", "AMD64"):
        return None, (f"its wheels exist only for Linux x86_64 "
                      f"(this is {platform.system()} {platform.machine()})")
    for version in ROSREF_PYTHONS:
        found = shutil.which(f"python{version}")
        if found:
            return found, ""
    if f"{sys.version_info[0]}.{sys.version_info[1]}" in ROSREF_PYTHONS:
        return sys.executable, ""
    return None, "its wheels need CPython 3.11 or 3.12, and neither is installed"


def setup_rosref():
    python, why = rosref_python()
    if python is None:
        say(f"{ROSREF.name} (real rclpy for tests/dds and benchmarks) skipped: {why}")
        return None
    digest = _digest(ROSREF_LOCK)
    stamp = _stamp(ROSREF)
    if stamp.exists() and stamp.read_text(encoding="utf-8").split() == ["test", digest]:
        return venv_python(ROSREF)
    if not venv_python(ROSREF).exists():
        run([python, "-m", "venv", ROSREF])
    pip(venv_python(ROSREF), "install", "--upgrade", "pip")
    say(f"installing {ROSREF.name} from {ROSREF_LOCK.name}")
    pip(venv_python(ROSREF), "install", "-r", ROSREF_LOCK)
    stamp.write_text(f"test {digest}\n", encoding="utf-8")
    return venv_python(ROSREF)


def ensure_node_modules(root=ROOT):
    """`npm ci` when node_modules is missing or older than package-lock.json: the book's
    offline assets and configurable-http-proxy (the JupyterHub tests) come from npm."""
    stamp = root / "node_modules" / ".package-lock.json"   # written by npm ci
    lock = root / "package-lock.json"
    if stamp.is_file() and stamp.stat().st_mtime >= lock.stat().st_mtime:
        return True
    npm = shutil.which("npm")
    if npm is None:
        say("node_modules is missing and `npm` is not installed (install Node.js, then run "
            "`npm ci` in the repository root)")
        return False
    say("npm ci")
    subprocess.run([npm, "ci", "--ignore-scripts", "--no-audit", "--no-fund"], cwd=root, check=True)
    return True


def follow(cmd, env=None):
    """Run a job's command to its end; Ctrl+C reaches it through the terminal (pytest
    prints its summary, JupyterLab asks or stops), so we wait for it instead of killing."""
    child = subprocess.Popen([str(c) for c in cmd], cwd=ROOT, env=env)
    while True:
        try:
            return child.wait()
        except KeyboardInterrupt:
            continue


def job_env():
    env = dict(os.environ)
    env.setdefault("LABKIT_TIME", "virtual")
    env.setdefault("TZ", "UTC")     # dates printed by tools must not depend on the machine
    return env


JOBS = {
    # job: (set-up level, command after the venv's python)
    "setup": ("test", None),
    "lab": ("lab", ["-m", "labkit.tools.lab"]),
    "book": ("book", ["tools/book_build.py"]),
    "test": ("test", ["-m", "pytest", "-q", "tests", "book"]),
    "unit": ("test", ["-m", "pytest", "-q", "tests"]),
    "nbval": ("test", ["-m", "pytest", "-q", "book"]),
    "book-exec": ("test", ["-m", "labkit.tools.execute_notebooks", "book"]),
}


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] not in (*JOBS, "bench", "-h", "--help"):
        print(__doc__)
        return 0 if argv[:1] in (["-h"], ["--help"]) else 2
    job, extra = argv[0], argv[1:]
    if job in ("-h", "--help"):
        print(__doc__)
        return 0
    level = "test" if job == "bench" else JOBS[job][0]
    python = setup_venv(level)
    if level == "test":
        setup_rosref()
        ensure_node_modules()
    if job == "setup":
        return 0
    if job == "bench":
        failed = []             # every benchmark runs; the ones that failed are named at the end
        for script in sorted((ROOT / "benchmarks").glob("*.py")):
            if script.name.startswith("_"):
                continue
            print(f"== {script.relative_to(ROOT).as_posix()}", flush=True)
            if follow([python, script], env=job_env()):
                failed.append(script.name)
        if failed:
            print("benchmarks that failed: " + ", ".join(failed), flush=True)
        return 1 if failed else 0
    cmd = [python, *JOBS[job][1], *extra]
    # labkit.tools.lab sets live time itself
    return follow(cmd, env=None if job == "lab" else job_env())


if __name__ == "__main__":
    sys.exit(main())
