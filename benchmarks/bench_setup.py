"""Set-up figures: the learner's environment against the full `make setup`.

    python benchmarks/bench_setup.py [--cold-full]

Prints, on this machine:
  learner, warm cache  fresh venv + `pip install -c requirements.lock ".[lab]"`
                       (what `make lab` / `pip install "labkit[lab]"` installs), with
                       pip's own cache as it is
  learner, cold cache  the same with an empty temporary cache (every file downloaded)
  full, warm cache     what `make setup` installed before tools/make.py: every pin of
                       requirements.lock + labkit, and .venv-rosref (real rclpy) where
                       it can exist; --cold-full also times it with an empty cache
and the size on disk of each environment. Everything happens in a temporary folder
outside the repository, removed at the end; nothing of .venv is touched.
"""
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import make  # noqa: E402


def base_python():
    """The machine's Python that made .venv (not .venv's own)."""
    return getattr(sys, "_base_executable", None) or shutil.which("python3") or sys.executable


def size_mb(path):
    total = 0
    for dirpath, _, files in os.walk(path):
        for name in files:
            try:
                total += os.lstat(os.path.join(dirpath, name)).st_size
            except OSError:
                pass
    return total / 1e6


def pip(python, *args, cache=None):
    env = dict(os.environ)
    if cache is not None:
        env["PIP_CACHE_DIR"] = str(cache)
    subprocess.run([str(python), "-m", "pip", "--disable-pip-version-check", "-q", *args],
                   check=True, cwd=ROOT, env=env)


def learner(tmp, cache=None):
    venv = tmp / "learner"
    start = time.perf_counter()
    subprocess.run([base_python(), "-m", "venv", str(venv)], check=True)
    python = make.venv_python(venv)
    pip(python, "install", "-c", str(make.LOCK), ".[lab]", cache=cache)
    seconds = time.perf_counter() - start
    check = subprocess.run([str(python), "-c", "import labkit, jupyterlab, jupyterlab_myst, "
                            "ipywidgets; print('ok')"], capture_output=True, text=True)
    assert check.stdout.strip() == "ok", check.stderr
    mb = size_mb(venv)
    shutil.rmtree(venv)
    return seconds, mb


def full(tmp, cache=None):
    venv, ref = tmp / "full", tmp / "full-rosref"
    start = time.perf_counter()
    subprocess.run([base_python(), "-m", "venv", str(venv)], check=True)
    python = make.venv_python(venv)
    pip(python, "install", "-r", str(make.LOCK), cache=cache)
    pip(python, "install", "--no-deps", ".", cache=cache)
    ref_python, why = make.rosref_python()
    if ref_python is not None:
        subprocess.run([ref_python, "-m", "venv", str(ref)], check=True)
        pip(make.venv_python(ref), "install", "-r", str(make.ROSREF_LOCK), cache=cache)
    seconds = time.perf_counter() - start
    mb = size_mb(venv) + (size_mb(ref) if ref.exists() else 0.0)
    shutil.rmtree(venv)
    shutil.rmtree(ref, ignore_errors=True)
    return seconds, mb, why


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    print(f"machine: {platform.system()} {platform.machine()}, Python "
          f"{platform.python_version()}, {os.cpu_count()} cores")
    with tempfile.TemporaryDirectory(prefix="bench_setup_") as tmp:
        tmp = Path(tmp)
        s, mb = learner(tmp)
        print(f"learner set-up (labkit[lab]), warm pip cache: {s:6.1f} s, {mb:6.0f} MB")
        s, mb = learner(tmp, cache=tmp / "empty-cache")
        print(f"learner set-up (labkit[lab]), cold pip cache: {s:6.1f} s, {mb:6.0f} MB")
        shutil.rmtree(tmp / "empty-cache", ignore_errors=True)
        s, mb, why = full(tmp)
        extra = f" (.venv-rosref skipped: {why})" if why else " (incl. .venv-rosref)"
        print(f"full make setup (every pin){extra}, warm pip cache: {s:6.1f} s, {mb:6.0f} MB")
        if "--cold-full" in argv:
            s, mb, _ = full(tmp, cache=tmp / "empty-cache2")
            print(f"full make setup, cold pip cache: {s:6.1f} s, {mb:6.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
