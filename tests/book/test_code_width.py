"""No code line of the built book is cut at the column: at a 1280 px window
(a ~690 px column) no <pre> of any page scrolls sideways. Code inputs wrap
(book/_static/labkit_book.css); before, ch03's `topic pub` YAML and many
comment lines stopped at the column's edge."""

from __future__ import annotations

from book_support import pages

WIDE_PRES = """(() => Array.from(document.querySelectorAll('.bd-article pre'))
  .filter(p => p.getClientRects().length && p.scrollWidth > p.clientWidth + 1)
  .map(p => p.scrollWidth + '>' + p.clientWidth + ': '
       + (p.innerText.split('\\n').sort((a, b) => b.length - a.length)[0] || '').slice(0, 60)))()"""


def test_no_code_block_scrolls_sideways(page, served, book_html):
    problems, measured = [], 0
    for html in pages(book_html):
        rel = html.relative_to(book_html).as_posix()
        if rel in ("index.html", "search.html", "genindex.html"):
            continue
        page.open(served("book", rel))
        # Open the collapsed cells too: a reader may.
        page.evaluate("document.querySelectorAll('details').forEach(d => d.open = true)")
        measured += page.evaluate("document.querySelectorAll('.bd-article pre').length")
        problems += [f"{rel}: {w}" for w in page.evaluate(WIDE_PRES)]
    assert measured > 100
    assert not problems, "\n".join(problems)
