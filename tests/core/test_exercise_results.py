"""Exercise reports as data (for grading) and checks that never crash."""
import json

import pytest

from labkit import exercises
from labkit.exercises import Checker


def test_result_names_the_exercise_and_each_item(capsys):
    c = Checker("练习 0.3")
    c.that(True, "节点 /a 正在运行", "")
    c.that(False, "", "2 秒里只有 1 条日志：检查定时器的周期")
    r = c.result()
    assert r == {"exercise": "练习 0.3", "passed": False,
                 "passed_items": ["节点 /a 正在运行"],
                 "failed_items": [{"text": "2 秒里只有 1 条日志：检查定时器的周期",
                                   "hint": "检查定时器的周期"}]}
    assert json.loads(json.dumps(r)) == r


def test_every_report_goes_to_the_hooks_and_the_log_file(tmp_path, monkeypatch, capsys):
    log = tmp_path / "reports.jsonl"
    monkeypatch.setenv(exercises.LOG_ENV, str(log))
    monkeypatch.setenv("LABKIT_NOTEBOOK", "ch02_nodes.ipynb")
    seen = []
    monkeypatch.setattr(exercises, "REPORT_HOOKS", [seen.append, lambda r: 1 / 0])
    c = Checker("练习 0.4")
    c.that(True, "对", "")
    assert c.report()
    c.that(False, "", "错")
    assert not c.report()
    lines = [json.loads(x) for x in log.read_text(encoding="utf-8").splitlines()]
    assert [x["passed"] for x in lines] == [True, False] == [x["passed"] for x in seen]
    assert lines[1]["failed_items"] == [{"text": "错", "hint": "错"}]
    assert lines[0]["notebook"] == "ch02_nodes.ipynb" and lines[0]["exercise"] == "练习 0.4"


def test_with_block_turns_an_exception_into_one_failed_line(capsys):
    with Checker("练习 0.5") as c:
        c.that(True, "第一项", "")
        sum(1.5)                                  # what a scalar field would give
    out = capsys.readouterr().out
    assert "Traceback" not in out
    assert "  [错] 检查时出错：TypeError: 'float' object is not iterable\n" in out
    assert not c.passed and c.result()["failed_items"][0]["hint"] == "TypeError: 'float' object is not iterable"


def test_with_block_reports_once_and_lets_keyboard_interrupt_through(capsys):
    with Checker("练习 0.6") as c:
        c.that(True, "一项", "")
        c.report()
    assert capsys.readouterr().out.count("【练习 0.6】") == 1
    with pytest.raises(KeyboardInterrupt):
        with Checker("练习 0.7"):
            raise KeyboardInterrupt


@pytest.fixture
def shell():
    from IPython.core.interactiveshell import InteractiveShell
    sh = InteractiveShell.instance()
    yield sh
    InteractiveShell.clear_instance()


def test_in_a_notebook_cell_an_escaping_exception_is_judged_not_shown(shell, capsys):
    res = shell.run_cell("from labkit.exercises import Checker\n"
                         "c = Checker('练习 0.8')\n"
                         "c.that(True, '有节点', '')\n"
                         "c.that(len(answer) == 3, '三个', '不是三个')\n"
                         "c.report()\n")
    out = capsys.readouterr().out
    assert res.success, "the cell ends normally: Run All goes on"
    assert "Traceback" not in out and "NameError" in out
    assert "  [错] 检查时出错：NameError: name 'answer' is not defined\n" in out
    assert "还差 1 项" in out
    # the guard is gone once the cell ended: a later error is an ordinary traceback again
    res = shell.run_cell("1 / 0\n")
    assert not res.success and isinstance(res.error_in_exec, ZeroDivisionError)


def test_an_error_after_the_report_is_not_the_checks(shell, capsys):
    res = shell.run_cell("from labkit.exercises import Checker\n"
                         "c = Checker('练习 0.9')\n"
                         "c.that(True, '一项', '')\n"
                         "c.report()\n"
                         "raise ValueError('learner code after the check')\n")
    assert not res.success and isinstance(res.error_in_exec, ValueError)


def test_collect_stamped_gives_arrival_times_in_ros_time():
    import labkit
    from labkit import process

    def talker(args=None):
        import labkit.rclpy as rclpy
        from labkit.interfaces import get_type
        rclpy.init(args=args)
        node = rclpy.create_node("ticker")
        pub = node.create_publisher(get_type("std_msgs/msg/Int32"), "/ticks", 10)
        node.create_timer(0.4, lambda: pub.publish(get_type("std_msgs/msg/Int32")(data=1)))
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
            rclpy.try_shutdown()

    job = process.start(main=talker, name="ticker")
    got = exercises.collect("/ticks", "std_msgs/msg/Int32", 2.0, stamped=True)
    gaps = [round(b[0] - a[0], 3) for a, b in zip(got, got[1:])]
    assert len(got) >= 4 and set(gaps) == {0.4}
    job.stop()
    labkit.reset()
