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
