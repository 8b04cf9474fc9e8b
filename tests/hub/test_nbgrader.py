"""nbgrader's own generate_assignment and autograde on ch03 exported by
`labkit teacher nbgrader`: a right submission gets every point, a wrong one (the
released stubs, one exercise done) gets only that exercise's points."""
import json
import os
import subprocess
import sys

import pytest

from labkit.teacher.nbgrader_export import export
from tests.hub._learners import CH03, REPO, load

pytest.importorskip("nbgrader")
NBGRADER = [sys.executable, "-m", "nbgrader"]


def _run(course, *args):
    env = dict(os.environ, LABKIT_TIME="virtual", PYTHONPATH=str(REPO), TZ="UTC",
               PATH=os.path.dirname(sys.executable) + os.pathsep + os.environ["PATH"])
    env.pop("LABKIT_EXERCISE_LOG", None)
    res = subprocess.run([*NBGRADER, *args], cwd=course, env=env, capture_output=True,
                         text=True, timeout=300)
    assert res.returncode == 0, res.stdout[-3000:] + res.stderr[-3000:]
    return res


def _solved_answers(source_nb):
    """grade_id -> the answer cell with the reference answer in place of the stub."""
    out = {}
    for cell in source_nb["cells"]:
        meta = cell["metadata"].get("nbgrader", {})
        if meta.get("solution"):
            src = "".join(cell["source"])
            out[meta["grade_id"]] = src.replace("### BEGIN SOLUTION\n", "").replace(
                "### END SOLUTION\n", "")
    return out


def test_export_shape():
    nb = export(load())
    graded = [c["metadata"]["nbgrader"] for c in nb["cells"] if c["metadata"]["nbgrader"]["grade"]]
    assert [(m["grade_id"], m["points"]) for m in graded] == \
        [("ex3_1_check", 4), ("ex3_2_check", 4), ("ex3_3_check", 2)]
    sources = ["".join(c["source"]) for c in nb["cells"]]
    assert not any(s.startswith("# 参考答案") for s in sources)
    assert sum("### BEGIN SOLUTION" in s for s in sources) == 3


def test_generate_assignment_and_autograde(tmp_path):
    course = tmp_path / "course"
    course.mkdir()
    (course / "nbgrader_config.py").write_text(
        "c = get_config()\n"
        "c.CourseDirectory.course_id = 'ros2-class'\n"
        "c.CourseDirectory.db_assignments = [dict(name='ch03_topics')]\n"
        "c.CourseDirectory.db_students = [dict(id='alice'), dict(id='bob')]\n"
        "c.ClearSolutions.code_stub = {'python': '# 在这里写你的代码\\n'}\n"
        "c.ExecutePreprocessor.timeout = 120\n", encoding="utf-8")
    res = subprocess.run([sys.executable, "-m", "labkit", "teacher", "nbgrader", str(CH03),
                          "--course", str(course)], capture_output=True, text=True, cwd=REPO)
    assert res.returncode == 0, res.stderr
    source = json.loads((course / "source" / "ch03_topics" / "ch03_topics.ipynb")
                        .read_text(encoding="utf-8"))
    _run(course, "db", "assignment", "add", "ch03_topics")
    _run(course, "generate_assignment", "ch03_topics", "--force")
    release = json.loads((course / "release" / "ch03_topics" / "ch03_topics.ipynb")
                         .read_text(encoding="utf-8"))
    answers = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
               for c in release["cells"] if c["metadata"].get("nbgrader", {}).get("solution")}
    assert set(answers) == {"ex3_1_answer", "ex3_2_answer", "ex3_3_answer"}
    assert all("# 在这里写你的代码" in s and "参考答案" not in s for s in answers.values())

    solved = _solved_answers(source)
    for student, done in (("alice", set(solved)), ("bob", {"ex3_1_answer"})):
        nb = json.loads(json.dumps(release))
        for cell in nb["cells"]:
            gid = cell["metadata"].get("nbgrader", {}).get("grade_id")
            if gid in done:
                cell["source"] = solved[gid]
        path = course / "submitted" / student / "ch03_topics" / "ch03_topics.ipynb"
        path.parent.mkdir(parents=True)
        path.write_text(json.dumps(nb, ensure_ascii=False, indent=1), encoding="utf-8")
        (path.parent / "timestamp.txt").write_text("2026-11-28 12:00:00 UTC", encoding="utf-8")
    _run(course, "autograde", "ch03_topics", "--force")

    from nbgrader.api import Gradebook
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}") as gb:
        scores = {s: {g.name: g.score for g in
                      gb.find_submission_notebook("ch03_topics", "ch03_topics", s).grades
                      if g.name.endswith("_check")}
                  for s in ("alice", "bob")}
        total = {s: gb.find_submission("ch03_topics", s).score for s in ("alice", "bob")}
    assert scores["alice"] == {"ex3_1_check": 4, "ex3_2_check": 4, "ex3_3_check": 2}
    assert scores["bob"]["ex3_1_check"] == 4
    assert scores["bob"]["ex3_2_check"] < 4 and scores["bob"]["ex3_3_check"] < 2
    assert total["alice"] == 10 and total["bob"] < 10
