"""The one lock (requirements.lock, uv's universal resolution with environment markers)
installs on every target the README promises, from wheels only (or the two pure-Python
sdists), on Python 3.10-3.13. Offline: the files each pin has on the index were recorded
at lock time in requirements-dists.json (`python tools/lock.py dists`)."""
import json
import re
import sys
from pathlib import Path

import pytest
from packaging import tags
from packaging.markers import Marker
from packaging.specifiers import SpecifierSet
from packaging.utils import parse_wheel_filename

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lock  # noqa: E402

PYTHONS = ["3.10.0", "3.10.12", "3.11.0", "3.11.2", "3.11.9", "3.12.0", "3.13.0"]


def _manylinux(arch, glibc_minor):
    plats = [f"manylinux_2_{m}_{arch}" for m in range(glibc_minor, 4, -1)]
    legacy = {17: "manylinux2014", 12: "manylinux2010", 5: "manylinux1"}
    return plats + [f"{name}_{arch}" for m, name in legacy.items() if m <= glibc_minor]


# (name, marker environment, platform tags): the oldest OS each README section promises
# (macOS 12 Monterey on both Macs: scipy has no older arm64 wheel)
TARGETS = {
    # Ubuntu 22.04 (glibc 2.35; Humble's own platform, WSL2's default)
    "linux-x86_64": ({"sys_platform": "linux", "platform_system": "Linux", "os_name": "posix",
                      "platform_machine": "x86_64"}, _manylinux("x86_64", 35)),
    # Raspberry Pi OS / Debian 12 (glibc 2.36), Ubuntu 22.04 on a Jetson or a Pi (2.35)
    "linux-aarch64": ({"sys_platform": "linux", "platform_system": "Linux", "os_name": "posix",
                       "platform_machine": "aarch64"}, _manylinux("aarch64", 35)),
    "macos-arm64": ({"sys_platform": "darwin", "platform_system": "Darwin", "os_name": "posix",
                     "platform_machine": "arm64"}, list(tags.mac_platforms((12, 0), "arm64"))),
    "macos-x86_64": ({"sys_platform": "darwin", "platform_system": "Darwin", "os_name": "posix",
                      "platform_machine": "x86_64"}, list(tags.mac_platforms((12, 0), "x86_64"))),
    "windows-amd64": ({"sys_platform": "win32", "platform_system": "Windows", "os_name": "nt",
                       "platform_machine": "AMD64"}, ["win_amd64"]),
}


def _supported(py, platforms):
    major, minor = (int(x) for x in py.split(".")[:2])
    interp = f"cp{major}{minor}"
    return set(tags.cpython_tags((major, minor), abis=[interp, "abi3", "none"],
                                 platforms=platforms)) | \
        set(tags.compatible_tags((major, minor), interp, platforms))


def _env(target, py):
    env = dict(TARGETS[target][0], implementation_name="cpython",
               platform_python_implementation="CPython",
               python_version=".".join(py.split(".")[:2]), python_full_version=py)
    return env


def pins_for(target, py):
    env = _env(target, py)
    return [(n, v) for n, v, m in lock.read_lock() if not m or Marker(m).evaluate(env)]


def installable(files, name, py, supported):
    for f in files:
        if f["yanked"]:
            continue
        if f["requires_python"] and not SpecifierSet(f["requires_python"]).contains(py):
            continue
        if f["file"].endswith(".whl"):
            if set(parse_wheel_filename(f["file"])[3]) & supported:
                return True
        elif name in lock.PURE_SDISTS:
            return True
    return False


@pytest.fixture(scope="module")
def dists():
    return json.loads(lock.DISTS.read_text(encoding="utf-8"))


def _hub_pins():
    return lock.read_lock(lock.HUB_LOCK) if lock.HUB_LOCK.exists() else []


def test_dists_cover_every_pin_and_name_no_host(dists):
    pins = {f"{n}=={v}" for n, v, _ in lock.read_lock() + _hub_pins()}
    assert pins == set(dists), "re-run python tools/lock.py dists after a re-lock"
    text = lock.DISTS.read_text(encoding="utf-8")
    assert not re.search(r"https?:|//|\.org\b|\.io\b", text)


@pytest.mark.parametrize("py", PYTHONS)
@pytest.mark.parametrize("target", sorted(TARGETS))
def test_every_pin_installs_on_every_target(dists, target, py):
    supported = _supported(py, TARGETS[target][1])
    missing = [f"{n}=={v}" for n, v in pins_for(target, py)
               if not installable(dists[f"{n}=={v}"], n, py, supported)]
    assert not missing, f"{target} Python {py}: no installable file for {missing}"


def test_platform_only_dependencies_are_in_the_lock():
    """jupyter's Windows and macOS extras: the lock is closed there too."""
    assert ("colorama", "pywinpty") <= tuple(sorted(
        n for n, v in pins_for("windows-amd64", "3.11.9") if n in ("colorama", "pywinpty")))
    assert "appnope" in {n for n, v in pins_for("macos-arm64", "3.12.0")}
    assert "appnope" not in {n for n, v in pins_for("linux-x86_64", "3.11.9")}
    # no DDS wheel exists for Linux aarch64: left out there, kept elsewhere
    assert "cyclonedds" not in {n for n, v in pins_for("linux-aarch64", "3.11.9")}
    assert "cyclonedds" in {n for n, v in pins_for("linux-x86_64", "3.11.9")}


def test_requires_python_says_the_truth():
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert re.search(r'^requires-python = ">=3.10,<3.14"$', text, re.M)
    assert 'classifiers' not in text or "3.14" not in text


def test_ci_linux_keeps_the_versions_the_outputs_were_made_with():
    """Linux x86_64 / Python 3.11 (CI) installs the versions the stored notebook outputs
    were executed with."""
    pins = dict(pins_for("linux-x86_64", "3.11.9"))
    assert pins["numpy"] == "2.4.6" and pins["opencv-python-headless"] == "4.14.0.94"
    assert pins["matplotlib"] == "3.11.2" and pins["scipy"] == "1.17.1"
    assert pins["pillow"] == "13.0.0" and pins["pygraphviz"] == "2.0.4"


@pytest.mark.skipif(not lock.HUB_LOCK.exists(), reason="no requirements-hub.lock")
@pytest.mark.parametrize("py", ["3.11.2", "3.11.9", "3.12.0"])
def test_hub_lock_installs_on_linux(dists, py):
    """requirements-hub.lock (JupyterHub/grading tests, Linux only) installs beside the
    lock on Linux x86_64."""
    env = _env("linux-x86_64", py)
    supported = _supported(py, TARGETS["linux-x86_64"][1])
    missing = [f"{n}=={v}" for n, v, m in _hub_pins() if not m or Marker(m).evaluate(env)
               if not installable(dists.get(f"{n}=={v}", []), n, py, supported)]
    assert not missing, f"linux-x86_64 Python {py}: no installable file for {missing}"
