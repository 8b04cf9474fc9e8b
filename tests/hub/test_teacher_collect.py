"""`labkit teacher collect`: every learner's ch03 re-run in its own sandboxed process
(virtual time, no network, limits), the table as CSV and HTML; same result every run."""
import csv
import subprocess
import sys

from labkit.teacher import collect as teacher
from labkit.teacher.runner import graded_cells
from tests.hub._learners import REPO, load, solved, write


def _homes(tmp_path):
    homes = tmp_path / "home"
    write(load(), homes / "alice" / "book" / "part1_basics" / "ch03_topics.ipynb")
    write(solved(load()), homes / "bob" / "book" / "part1_basics" / "ch03_topics.ipynb")
    # a learner who only got 3.1 right, by hand, in a submissions-style folder
    nb = load()
    for cell in nb["cells"]:
        if "".join(cell["source"]).startswith("# TODO: circle = %ros2"):
            cell["source"] = ('circle = %ros2 topic pub --rate 1 /turtle1/cmd_vel '
                              'geometry_msgs/msg/Twist "{linear: {x: 2.0}, angular: {z: 1.8}}"\n'
                              'labkit.sleep(3.0)\n')
    write(nb, homes / "carol" / "ch03_topics.ipynb")
    (homes / "dave").mkdir()                       # nothing handed in
    return homes


def _table(out):
    with open(out / "exercises.csv", encoding="utf-8", newline="") as f:
        return {(r["learner"], r["exercise"]): r for r in csv.DictReader(f)}


def test_collect_grades_each_learner_and_is_deterministic(tmp_path):
    homes = _homes(tmp_path)
    cmd = [sys.executable, "-m", "labkit", "teacher", "collect", str(homes), "--jobs", "2"]
    first = subprocess.run(cmd + ["--out", str(tmp_path / "a")], capture_output=True,
                           text=True, cwd=REPO, timeout=240)
    assert first.returncode == 0, first.stderr
    assert first.stdout.startswith("3 notebooks of 3 learners graded"), first.stdout
    table = _table(tmp_path / "a")
    verdict = {k: r["passed"] for k, r in table.items()}
    assert verdict == {("alice", "练习 3.1"): "no", ("alice", "练习 3.2"): "no",
                       ("alice", "练习 3.3"): "no", ("bob", "练习 3.1"): "yes",
                       ("bob", "练习 3.2"): "yes", ("bob", "练习 3.3"): "yes",
                       ("carol", "练习 3.1"): "yes", ("carol", "练习 3.2"): "no",
                       ("carol", "练习 3.3"): "no"}
    assert "QoS" in table[("alice", "练习 3.3")]["hints"]
    assert "2 个发布者" in table[("alice", "练习 3.1")]["hints"]
    assert {r["status"] for r in table.values()} == {"ok"}
    page = (tmp_path / "a" / "exercises.html").read_text(encoding="utf-8")
    assert "<th>dave</th>" in page and page.count("未做") == 3
    ok = '<td class="ok">[对]</td>'
    assert f"<th>bob</th>{ok * 3}<td>3/3</td>" in page
    again = subprocess.run(cmd + ["--out", str(tmp_path / "b")], capture_output=True,
                           text=True, cwd=REPO, timeout=240)
    assert again.returncode == 0, again.stderr
    assert (tmp_path / "a" / "exercises.csv").read_bytes() == \
        (tmp_path / "b" / "exercises.csv").read_bytes()


def test_learner_code_has_no_network_and_limits(tmp_path):
    """A cell that opens an internet socket fails in the sandbox; one that eats memory is
    stopped by the address-space limit; one that never ends by the timeout."""
    nb = {"cells": [
        {"cell_type": "code", "metadata": {}, "source":
         "import socket\ns = socket.socket()\n"},
        {"cell_type": "code", "metadata": {}, "source":
         "from labkit.exercises import Checker\nc = Checker('练习 9.9')\n"
         "c.that(True, '这一项对')\nc.report()\n"},
        {"cell_type": "code", "metadata": {}, "source": "big = bytearray(3 * 1024**3)\n"},
    ], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path = write(nb, tmp_path / "x" / "ch99_sandbox.ipynb")
    data = teacher.grade_notebook(path, timeout=60, memory_mb=2048)
    assert data["status"] == "ok", data
    assert [r["exercise"] for r in data["reports"]] == ["练习 9.9"]
    errors = {e["cell"]: e["error"] for e in data["errors"]}
    assert errors[0].startswith("PermissionError"), errors
    assert errors[2].startswith("MemoryError"), errors
    hang = write({"cells": [{"cell_type": "code", "metadata": {}, "source":
                             "import time\nwhile True:\n    time.sleep(1)\n"}],
                  "metadata": {}, "nbformat": 4, "nbformat_minor": 5},
                 tmp_path / "y" / "ch98_hang.ipynb")
    assert teacher.grade_notebook(hang, timeout=5)["status"] == "timeout after 5 s"


def test_reference_answers_are_not_graded():
    cells = dict(graded_cells(load()))
    sources = list(cells.values())
    assert not any(s.startswith("# 参考答案") for s in sources)
    assert sum("Checker(\"练习 3.1\")" in s for s in sources) == 1


def test_bad_folder_one_line(tmp_path):
    res = subprocess.run([sys.executable, "-m", "labkit", "teacher", "collect",
                          str(tmp_path / "nope")], capture_output=True, text=True, cwd=REPO)
    assert res.returncode == 2
    assert res.stderr == f"labkit teacher collect: error: no such folder: '{tmp_path / 'nope'}'\n"
