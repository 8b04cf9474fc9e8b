"""Make the one lock, requirements.lock, for every target, and record what it can install.

    python tools/lock.py compile [--uv PATH]   requirements.lock from pyproject.toml (all extras)
    python tools/lock.py dists                 requirements-dists.json: the files of every pin

`compile` runs uv's universal resolution (`uv pip compile --universal`): one file with
environment markers that covers Linux x86_64/aarch64, macOS arm64/x86_64 and Windows
amd64 on Python 3.10-3.13 (pyproject's requires-python), wheels only except the two
pure-Python sdists (jieba, urdf_parser_py). The pins already in requirements.lock are
uv's preferences, so a re-lock keeps the versions the stored notebook outputs were made
with. uv is not a dependency of the project: install it in a throwaway venv outside
the repo (`python -m venv /tmp/uv && /tmp/uv/bin/pip install uv`) and pass --uv.

`dists` asks pip's default index (the same one `pip install` uses), through the
standard JSON simple API, for the files of each pinned version, and stores their names,
Requires-Python and yanked flags -- no addresses -- in requirements-dists.json. The
test tests/setup/test_lock.py reads that file offline and fails when some target x
Python version cannot install some pin from it.
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import urllib.request

ROOT = pathlib.Path(__file__).resolve().parents[1]
LOCK = ROOT / "requirements.lock"
DISTS = ROOT / "requirements-dists.json"
HUB_LOCK = ROOT / "requirements-hub.lock"     # the JupyterHub/grading tests' pins (Linux)
PURE_SDISTS = ("jieba", "urdf-parser-py", "flake8-quotes")   # build with no compiler
# Pins chosen for targets where the newest release has no wheel:
OVERRIDES = [
    # 26.x has no macOS x86_64 wheel; 25.1.0 has universal2 wheels, same API
    "argon2-cffi-bindings==25.1.0",
    # 4.12+ wheels need macOS 13 (arm64) / 14 (x86_64); 4.10.0.84 has macOS 11 arm64 and
    # 12 x86_64 wheels. Elsewhere the version the stored outputs were made with.
    "opencv-python-headless==4.14.0.94 ; sys_platform != 'darwin'",
    "opencv-python-headless==4.10.0.84 ; sys_platform == 'darwin'",
]


def norm(name):
    return re.sub(r"[-_.]+", "-", name).lower()


def read_lock(path=LOCK):
    """[(name, version, marker or '')] from requirements.lock."""
    pins = []
    for line in path.read_text(encoding="utf-8").splitlines():
        line = line.split(" #", 1)[0].strip()
        if not line or line.startswith(("#", "-")):
            continue
        req, _, marker = line.partition(";")
        name, _, version = req.strip().partition("==")
        pins.append((norm(name), version.strip(), marker.strip()))
    return pins


def compile_lock(uv):
    with tempfile.TemporaryDirectory() as tmp:
        overrides = pathlib.Path(tmp) / "overrides.txt"
        overrides.write_text("\n".join(OVERRIDES) + "\n", encoding="utf-8")
        cmd = [uv, "pip", "compile", str(ROOT / "pyproject.toml"), "--all-extras", "--no-python-downloads",
               "--universal", "--python-version", "3.10",
               "--only-binary", ":all:", *sum((["--no-binary", p] for p in PURE_SDISTS), []),
               "--overrides", str(overrides), "--no-emit-package", "labkit",
               "--no-header", "--no-annotate", "-o", str(LOCK)]
        subprocess.run(cmd, check=True, cwd=ROOT)


def index_url():
    from pip._internal.models.index import PyPI
    return PyPI.simple_url


def files_of(name, version, base):
    req = urllib.request.Request(f"{base}/{name}/",
                                 headers={"Accept": "application/vnd.pypi.simple.v1+json"})
    with urllib.request.urlopen(req, timeout=60) as reply:
        data = json.loads(reply.read())
    out = []
    for f in data["files"]:
        fn = f["filename"]
        if fn.endswith(".whl"):
            fver = fn.split("-")[1]
        else:
            stem = re.sub(r"\.(tar\.gz|zip|tar\.bz2)$", "", fn)
            fver = stem.rsplit("-", 1)[-1] if "-" in stem else ""
        if norm(fver) != norm(version) and fver.replace("_", "-") != version:
            continue
        out.append({"file": fn, "requires_python": f.get("requires-python") or "",
                    "yanked": bool(f.get("yanked"))})
    return sorted(out, key=lambda d: d["file"])


def record_dists():
    base = index_url().rstrip("/")
    result = {}
    pins = read_lock() + (read_lock(HUB_LOCK) if HUB_LOCK.exists() else [])
    for name, version, _ in pins:
        key = f"{name}=={version}"
        if key in result:
            continue
        result[key] = files_of(name, version, base)
        print(f"{key}: {len(result[key])} files", flush=True)
    DISTS.write_text(json.dumps(result, indent=1, sort_keys=True) + "\n", encoding="utf-8")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="tools/lock.py")
    sub = parser.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("compile")
    p.add_argument("--uv", default="uv")
    sub.add_parser("dists")
    args = parser.parse_args(argv)
    if args.cmd == "compile":
        compile_lock(args.uv)
    else:
        record_dists()


if __name__ == "__main__":
    sys.exit(main())
