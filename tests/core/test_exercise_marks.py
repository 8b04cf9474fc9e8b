"""Exercise reports mark each check with characters the book's fonts have (no emoji)."""
import unicodedata

from labkit.exercises import Checker


def test_report_marks_are_plain_cjk_text(capsys):
    c = Checker("练习 0.1")
    c.that(True, "对的一项", "")
    c.that(False, "", "错的一项")
    assert c.report() is False
    lines = capsys.readouterr().out.splitlines()
    assert lines[1] == "  [对] 对的一项" and lines[2] == "  [错] 错的一项"
    for ch in "".join(lines):
        # nothing from the emoji/symbol blocks a reader's font may lack
        assert unicodedata.category(ch) != "So", f"symbol {ch!r} (U+{ord(ch):04X})"
