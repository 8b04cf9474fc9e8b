"""On-demand target: the suite's core on Linux aarch64 (Raspberry Pi OS / Debian 12 on a
Pi 4/5, a Jetson), run here under qemu-user. Not part of `make test` (the root takes ~13
minutes to build and Python runs ~5x slower under emulation); `make arm64` runs it.

    python3 tools/qemu_arm64.py [--keep] [pytest args...]

What it does, and the figures it prints at the end:
  1. qemu-user-static's aarch64 binfmt handler (registered with the F flag, so a chroot
     needs no qemu binary inside it) and mmdebstrap, from Debian's packages when missing;
  2. an arm64 Debian 12 root in .cache/arm64/root (minbase + python3, python3-venv and the
     four shared libraries pygraphviz's manylinux wheel needs on a minimal system),
     built once and reused;
  3. the project's tracked files copied into it (git ls-files: nothing of this machine's
     venvs), a venv made with the root's own Python (3.11.2, as Raspberry Pi OS ships) and
     the `test` set-up installed from requirements.lock with its aarch64 markers (no
     cyclonedds: no wheel exists for aarch64, and labkit says so in one line);
  4. inside the root: `pytest tests/core tests/setup/test_no_cyclonedds.py` and nbval of
     book/part1_basics/ch02_nodes.ipynb (or the pytest arguments given), then the same
     command on this machine, and the ratio between the two.
Every mount it makes (proc, dev, sys) is undone at the end, also on failure.
"""
from __future__ import annotations

import os
import platform
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
from lock import PURE_SDISTS  # noqa: E402  (the sdists the lock allows: no compiler needed)
CACHE = ROOT / ".cache" / "arm64"
RFS = CACHE / "root"
SUITE = "bookworm"
PACKAGES = ["python3", "python3-venv", "ca-certificates",
            "libglib2.0-0", "libx11-6", "libxext6", "libxrender1"]
DEFAULT_TESTS = ["tests/core", "tests/setup/test_no_cyclonedds.py",
                 "book/part1_basics/ch02_nodes.ipynb"]
BINFMT = Path("/proc/sys/fs/binfmt_misc")
HANDLER_CONF = Path("/usr/lib/binfmt.d/qemu-aarch64.conf")
CHROOT = shutil.which("chroot") or "/usr/sbin/chroot"


def say(text):
    print(f"arm64: {text}", flush=True)


def sh(cmd, **kw):
    return subprocess.run([str(c) for c in cmd], check=True, **kw)


def need_tools():
    missing = [pkg for tool, pkg in (("mmdebstrap", "mmdebstrap"),
                                     ("qemu-aarch64-static", "qemu-user-static"))
               if shutil.which(tool) is None]
    if not missing:
        return
    if os.geteuid() != 0 or shutil.which("apt-get") is None:
        sys.exit(f"arm64: needs {' '.join(missing)} (Debian packages) and root")
    say(f"installing {' '.join(missing)} from Debian's packages")
    sh(["apt-get", "update", "-qq"])
    sh(["apt-get", "install", "-y", "-qq", *missing],
       env={**os.environ, "DEBIAN_FRONTEND": "noninteractive"}, stdout=subprocess.DEVNULL)


def need_binfmt():
    """aarch64 ELF files run through qemu: mount binfmt_misc and register the handler."""
    if platform.machine() == "aarch64":
        return
    if not (BINFMT / "register").exists():
        sh(["mount", "-t", "binfmt_misc", "binfmt_misc", BINFMT])
    entry = BINFMT / "qemu-aarch64"
    if entry.exists():
        if "F" not in entry.read_text(encoding="utf-8").split("flags:")[-1].split()[0]:
            sys.exit("arm64: qemu-aarch64 is registered without the F flag: "
                     "a chroot cannot find the interpreter")
        return
    (BINFMT / "register").write_text(HANDLER_CONF.read_text(encoding="utf-8").strip(),
                                     encoding="utf-8")


def build_root():
    if (RFS / "usr" / "bin" / "python3").exists():
        return 0.0
    t0 = time.monotonic()
    tmp = CACHE / "root.tmp"
    shutil.rmtree(tmp, ignore_errors=True)
    CACHE.mkdir(parents=True, exist_ok=True)
    say(f"building an arm64 Debian {SUITE} root (about 13 minutes under qemu)")
    sh(["mmdebstrap", "--arch=arm64", "--variant=minbase",
        f"--include={','.join(PACKAGES)}", SUITE, tmp])
    tmp.rename(RFS)
    return time.monotonic() - t0


def copy_project():
    """The tracked files only, fresh each run (the root's venv lives outside them)."""
    dest = RFS / "project"
    shutil.rmtree(dest, ignore_errors=True)
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, check=True,
                           capture_output=True).stdout.decode("utf-8").split("\0")
    for rel in filter(None, files):
        src = ROOT / rel
        if src.is_file():
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / rel, follow_symlinks=False)


class Mounts:
    def __init__(self):
        self.done = []

    def __enter__(self):
        for kind, target in (("proc", "proc"), ("bind", "dev"), ("bind", "sys")):
            where = RFS / target
            where.mkdir(exist_ok=True)
            if kind == "proc":
                sh(["mount", "-t", "proc", "proc", where])
            else:
                sh(["mount", "--rbind", f"/{target}", where])
                sh(["mount", "--make-rslave", where])
            self.done.append(where)
        shutil.copy2("/etc/resolv.conf", RFS / "etc" / "resolv.conf")
        # the CA bundle this machine's pip trusts (a proxy's own CA, where there is one)
        bundle = os.environ.get("PIP_CERT") or os.environ.get("SSL_CERT_FILE")
        if bundle and Path(bundle).is_file():
            shutil.copy2(bundle, RFS / "etc" / "ssl" / "certs" / "host-ca-bundle.crt")
        return self

    def __exit__(self, *exc):
        for where in reversed(self.done):
            subprocess.run(["umount", "-R", "-l", str(where)], check=False)


def in_root(script, env=None):
    """Run a shell script inside the root; returns (seconds, exit status)."""
    base = {"PATH": "/venv/bin:/usr/bin:/bin", "HOME": "/root", "LANG": "C.UTF-8",
            "PIP_DEFAULT_TIMEOUT": "180",
            "LABKIT_TIME": "virtual", "TZ": "UTC", "PYTHONDONTWRITEBYTECODE": "1"}
    if (RFS / "etc" / "ssl" / "certs" / "host-ca-bundle.crt").exists():
        base["PIP_CERT"] = base["SSL_CERT_FILE"] = "/etc/ssl/certs/host-ca-bundle.crt"
    t0 = time.monotonic()
    rc = subprocess.run([CHROOT, str(RFS), "/bin/sh", "-ec", script],
                        env={**base, **(env or {})}).returncode
    return time.monotonic() - t0, rc


def _terminated(signum, frame):
    raise SystemExit(f"arm64: stopped by signal {signum}")   # the mounts are undone


def main(argv):
    signal.signal(signal.SIGTERM, _terminated)
    keep = "--keep" in argv
    tests = [a for a in argv if a != "--keep"] or DEFAULT_TESTS
    if os.geteuid() != 0:
        sys.exit("arm64: needs root (chroot, mounts, binfmt_misc)")
    need_tools()
    need_binfmt()
    build_s = build_root()
    copy_project()
    figures = {}
    with Mounts():
        probe = subprocess.run([CHROOT, str(RFS), "/usr/bin/python3", "-c",
                                "import platform;print(platform.machine(),"
                                "platform.python_version())"],
                               capture_output=True, text=True, check=True).stdout.split()
        say(f"inside: {probe[0]}, Python {probe[1]}")
        stamp = RFS / "venv" / ".installed"
        lock_id = (ROOT / "requirements.lock").read_bytes() + (ROOT / "pyproject.toml").read_bytes()
        if not stamp.exists() or stamp.read_bytes() != lock_id:
            say("installing the test set-up from requirements.lock (aarch64 markers)")
            secs, rc = in_root(
                "rm -rf /venv; python3 -m venv /venv; cd /project;"
                " pip install -q --disable-pip-version-check --upgrade pip;"
                " pip install -q --disable-pip-version-check --only-binary=:all:"
                f" --no-binary={','.join(PURE_SDISTS)} -r requirements.lock;"
                " pip install -q --disable-pip-version-check --no-deps -e .")
            if rc:
                sys.exit(f"arm64: installing the lock failed (exit {rc})")
            stamp.write_bytes(lock_id)
            figures["install the lock"] = secs
        cmd = ["python", "-m", "pytest", "-q", *tests]
        say("inside the root: " + " ".join(cmd))
        secs, rc = in_root("cd /project; " + " ".join(cmd))
        figures["tests under qemu aarch64"] = secs
    say("the same tests on this machine")
    t0 = time.monotonic()
    host = subprocess.run([str(ROOT / ".venv" / "bin" / "python"), *cmd[1:]], cwd=ROOT,
                          env={**os.environ, "LABKIT_TIME": "virtual", "TZ": "UTC"},
                          stdout=subprocess.DEVNULL).returncode
    figures[f"tests on this machine ({platform.machine()})"] = time.monotonic() - t0
    if build_s:
        figures["build the arm64 root"] = build_s
    print("\nfigures (seconds):")
    for name, secs in figures.items():
        print(f"  {name:<40} {secs:8.1f}")
    host_s = figures[f"tests on this machine ({platform.machine()})"]
    print(f"  {'qemu / native ratio':<40} {figures['tests under qemu aarch64'] / host_s:8.1f}x")
    if not keep:
        shutil.rmtree(RFS / "project", ignore_errors=True)
    print(f"arm64: tests {'passed' if rc == 0 else f'FAILED (exit {rc})'}"
          f"; on this machine {'passed' if host == 0 else f'failed (exit {host})'}")
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
