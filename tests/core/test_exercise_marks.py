"""Exercise reports mark each check with characters the book's fonts have (no emoji)."""
import unicodedata

from labkit.exercises import Checker


def test_report_marks_are_plain_cjk_text(capsys):
    c = Checker("练习 0.1")
    c.that(True, "对的一项", "")
    c.that(False, "", "错的一项")
    assert not c.report()
    lines = capsys.readouterr().out.splitlines()
    assert lines[1] == "  [对] 对的一项" and lines[2] == "  [错] 错的一项"
    for ch in "".join(lines):
        # nothing from the emoji/symbol blocks a reader's font may lack
        assert unicodedata.category(ch) != "So", f"symbol {ch!r} (U+{ord(ch):04X})"


def test_report_adds_nothing_to_the_cell_output_but_is_still_a_verdict():
    from IPython.core.formatters import DisplayFormatter

    c = Checker("练习 0.2")
    c.that(True, "对的一项", "")
    verdict = c.report()
    assert verdict and verdict == True  # noqa: E712  (compares like the bool it stands for)
    shown, _ = DisplayFormatter().format(verdict)
    assert shown == {}            # IPython displays nothing for it
    c.that(False, "", "错的一项")
    assert not c.report()


def test_checker_looks_at_the_domain_the_notebook_is_on_now(monkeypatch, capsys):
    """After labkit.connect(domain_id=N) the process's ROS_DOMAIN_ID is N, but the default
    context keeps the domain it started on (as in ROS): the checker follows N."""
    import labkit
    import labkit.rclpy as rclpy

    labkit.reset()
    monkeypatch.delenv("ROS_DOMAIN_ID", raising=False)
    rclpy.init()                                   # the notebook's default context: domain 0
    here = rclpy.create_node("here")
    far_ctx = rclpy.Context()
    far_ctx.init(args=[], domain_id=7)
    far = rclpy.create_node("far", context=far_ctx)
    assert Checker("练习 0.3").node("/here") and not Checker("练习 0.3").node("/far")
    monkeypatch.setenv("ROS_DOMAIN_ID", "7")       # what connect(domain_id=7) does
    assert Checker("练习 0.4").node("/far")
    assert not Checker("练习 0.4").node("/here")
    monkeypatch.setenv("ROS_DOMAIN_ID", "0")
    assert Checker("练习 0.5").node("/here")
    far.destroy_node()
    here.destroy_node()
    labkit.reset()
