"""The built book in headless Chromium, served from 127.0.0.1: every page
renders Chinese text, its pictures load, the console stays clean and no
request leaves this machine. Screenshots go to book/_build/screenshots/."""

from __future__ import annotations

import re
from urllib.parse import urlsplit

from book_support import SCREENSHOTS, pages

LOCAL_HOSTS = {"127.0.0.1", "localhost"}
# Ask the page itself what it shows.
PAGE_STATE = """(() => {
  const article = document.querySelector('main, article, .bd-article');
  return {
    title: document.title,
    text: document.body.innerText,
    articleHeight: article ? article.getBoundingClientRect().height : 0,
    brokenImages: Array.from(document.images)
        .filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.currentSrc || i.src),
    images: document.images.length,
  };
})()"""


def remote_requests(urls: list[str]) -> list[str]:
    out = []
    for url in urls:
        parts = urlsplit(url)
        if parts.scheme in ("data", "blob", "about"):
            continue
        if parts.hostname not in LOCAL_HOSTS:
            out.append(url)
    return out


def check_page(page, url: str, shot_name: str) -> list[str]:
    """Open a page; return what is wrong with it (empty when fine)."""
    page.open(url)
    state = page.evaluate(PAGE_STATE)
    page.screenshot(SCREENSHOTS / f"{shot_name}.png")
    problems = []
    if not re.search(r"[\u4e00-\u9fff]", state["text"]):
        problems.append("no Chinese text")
    if state["articleHeight"] < 50:
        problems.append(f"article not laid out (height {state['articleHeight']})")
    if state["brokenImages"]:
        problems.append(f"images not loaded: {state['brokenImages']}")
    problems += page.errors()
    remote = remote_requests(page.requested_urls())
    if remote:
        problems.append(f"requests leave the machine: {remote}")
    return [f"{shot_name}: {p}" for p in problems]


def test_every_book_page_renders_offline(page, served, book_html):
    problems = []
    opened = 0
    for html in pages(book_html):
        rel = html.relative_to(book_html).as_posix()
        if rel == "index.html":  # a redirect to intro.html
            continue
        problems += check_page(page, served("book", rel), "book_" + rel[:-5].replace("/", "__"))
        opened += 1
    assert opened >= 6
    assert not problems, "\n".join(problems)


def test_intro_shows_its_chinese_headings(page, served):
    page.open(served("book", "intro.html"))
    headings = page.evaluate(
        "Array.from(document.querySelectorAll('article h2')).map(h => h.innerText)")
    assert any("两种读法" in h for h in headings), headings
    # The sidebar lists the three parts.
    nav = page.evaluate("document.querySelector('.bd-sidebar-primary').innerText")
    for part in ("第一部分", "第二部分", "第三部分"):
        assert part in nav


def search(page, served, query: str) -> list[str]:
    """Titles of the pages the book's search page finds for a query."""
    page.open(served("book", f"search.html?q={query}"))
    page.wait_for("!!document.querySelector('#search-results p.search-summary')")
    return page.evaluate(
        "Array.from(document.querySelectorAll('ul.search li a')).map(a => a.innerText)")


def test_search_finds_chinese_words(page, served):
    found = search(page, served, "话题")
    page.screenshot(SCREENSHOTS / "book_search_topic.png")
    assert "基础篇导读" in found
    assert not page.errors()
    assert not remote_requests(page.requested_urls())
    # A query written as one run of characters is cut into the index's words
    # (工作空间 + 的 + 话题) by _static/labkit_search.js.
    compound = search(page, served, "工作空间的话题")
    assert "开发篇导读：人脸识别机器人 facer" in compound
    assert "从本书走向真实的 ROS 2" in compound
    assert search(page, served, "量子纠缠") == []


def test_saved_widgets_render_offline(page, served):
    page.open(served("widgets", "part1_basics/widget_page.html"))
    # The ipywidgets HTML manager draws the slider from the saved state ...
    page.wait_for("!!document.querySelector('.widget-slider')")
    # ... and the ipycanvas view, whose module is served from _static.
    page.wait_for("!!document.querySelector('.cell_output canvas')")
    # MathJax typesets both formulas from the local copy.
    page.wait_for("document.querySelectorAll('mjx-container svg').length >= 2")
    page.settle()
    page.screenshot(SCREENSHOTS / "widgets_widget_page.png")
    state = page.evaluate(PAGE_STATE)
    assert "speed" in state["text"]
    # The icon font of the buttons loaded from _static (no 404, no CDN).
    fonts = [u for u in page.requested_urls() if re.search(r"\.(woff2?|ttf|eot)$", u)]
    assert any("/_static/vendor/jupyter-widgets/" in u for u in fonts), fonts
    # The two-faced output shows its static picture, not the live button.
    buttons = page.evaluate(
        "Array.from(document.querySelectorAll('.cell_output button')).map(b => b.innerText)")
    assert "live face" not in buttons
    widths = page.evaluate(
        "Array.from(document.querySelectorAll('.cell_output img')).map(i => i.naturalWidth)")
    assert 120 in widths
    assert not state["brokenImages"]
    assert not page.errors(), page.errors()
    assert not remote_requests(page.requested_urls())
    # Every widget module came from our own server.
    assert any(u.endswith("/vendor/widgets/ipycanvas/index.js") for u in page.requested_urls())
