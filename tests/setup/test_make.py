"""tools/make.py: the one implementation of set-up and of the jobs that the Makefile and
Windows' `py tools\\make.py` both call."""
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import make  # noqa: E402


def test_venv_python_per_os():
    v = Path("venv")
    assert make.venv_python(v, windows=True) == v / "Scripts" / "python.exe"
    assert make.venv_python(v, windows=False) == v / "bin" / "python"


@pytest.mark.parametrize("plat,machine", [("darwin", "arm64"), ("win32", "AMD64"),
                                          ("linux", "aarch64")])
def test_rosref_skipped_with_one_line_where_no_wheels(monkeypatch, capsys, plat, machine):
    monkeypatch.setattr(make.sys, "platform", plat)
    monkeypatch.setattr(make.platform, "machine", lambda: machine)
    assert make.setup_rosref() is None
    out = capsys.readouterr().out
    assert out.count("\n") == 1 and out.startswith("setup: .venv-rosref (real rclpy")
    assert "skipped: its wheels exist only for Linux x86_64" in out


def test_rosref_needs_cpython_311_or_312(monkeypatch):
    monkeypatch.setattr(make.sys, "platform", "linux")
    monkeypatch.setattr(make.platform, "machine", lambda: "x86_64")
    monkeypatch.setattr(make.shutil, "which", lambda name: None)
    monkeypatch.setattr(make.sys, "version_info", (3, 13, 0))
    assert make.rosref_python() == (None, "its wheels need CPython 3.11 or 3.12, and "
                                          "neither is installed")
    monkeypatch.setattr(make.shutil, "which",
                        lambda name: "/x/python3.12" if name == "python3.12" else None)
    assert make.rosref_python() == ("/x/python3.12", "")


def test_stamp_levels_and_inputs(tmp_path):
    (tmp_path / ".installed").write_text("book abc\n", encoding="utf-8")
    assert make._done_level(tmp_path, "abc") == make.LEVELS.index("book")
    assert make._done_level(tmp_path, "changed") == -1
    (tmp_path / ".installed").write_text("", encoding="utf-8")   # the old Makefile's stamp
    assert make._done_level(tmp_path, "abc") == -1


def test_jobs_need_only_their_set_up():
    assert make.JOBS["lab"][0] == "lab" and make.JOBS["book"][0] == "book"
    assert make.JOBS["test"][0] == "test"


def test_unsupported_python_says_so_in_one_line(monkeypatch):
    monkeypatch.setattr(make.sys, "version_info", (3, 9, 18))
    with pytest.raises(SystemExit) as exc:
        make.check_python()
    assert str(exc.value).startswith("setup: Python ") and "3.10 to 3.13" in str(exc.value)


def test_makefile_delegates_every_job_to_make_py():
    text = (ROOT / "Makefile").read_text(encoding="utf-8")
    for job in ("setup", "test", "book", "lab", "unit", "nbval", "book-exec", "bench"):
        assert f"tools/make.py {job}" in text, job
    assert "pip install" not in text
