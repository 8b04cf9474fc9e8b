"""The 3D views of the built book, as a reader sees them in Chromium at 1280 px: each
static view (the notebook's stored `<iframe srcdoc>`, kept verbatim by the build) is
framed for the reader: camera above the floor grid looking down, the model a good share
of the view and not cut off, no two frame names on each other. tests/viz/
test_meshcat_framing.py measures the same views straight from the notebooks."""

from __future__ import annotations

import meshcat_measure
from book_support import pages


def views(book_html):
    return [p for p in pages(book_html)
            if 'title="meshcat"' in p.read_text(encoding="utf-8", errors="replace")]


def test_every_3d_view_of_the_book_is_framed_for_the_reader(page, served, book_html):
    found = views(book_html)
    names = {p.stem for p in found}
    assert {"ch22_tf2", "ch23_urdf"} <= names, names
    problems = []
    for html in found:
        rel = html.relative_to(book_html).as_posix()
        page.open(served("book", rel))
        count = meshcat_measure.count(page)
        assert count >= 1, rel
        for k in range(count):
            problems += [f"{rel} view {k + 1}: {p}" for p in meshcat_measure.problems(page, k)]
        problems += [f"{rel}: {e}" for e in page.errors()]
    assert not problems, "\n".join(problems)
