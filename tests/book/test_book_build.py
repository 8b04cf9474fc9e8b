"""The offline book build: table of contents, no CDN, widget scripts, MIME
priority, Chinese search index. (The browser check is test_browser.py.)"""

from __future__ import annotations

import html as html_lib
import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest
import yaml

from book_support import BOOK, pages

CJK = re.compile(r"[\u4e00-\u9fff]")
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


class _Resources(HTMLParser):
    """Collects the URLs a page makes the browser fetch, and inline scripts."""

    FETCHED = {"script": "src", "img": "src", "iframe": "src", "source": "src",
               "video": "src", "audio": "src", "embed": "src"}

    def __init__(self):
        super().__init__()
        self.urls: list[str] = []
        self.inline_scripts: list[tuple[str, str]] = []  # (type, body)
        self._script_type = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag in self.FETCHED and a.get(self.FETCHED[tag]):
            self.urls.append(a[self.FETCHED[tag]])
        if tag == "link" and a.get("href") and a.get("rel") in (
                "stylesheet", "preload", "icon", "shortcut icon", "modulepreload"):
            self.urls.append(a["href"])
        if tag == "script" and not a.get("src"):
            self._script_type = a.get("type", "text/javascript")

    def handle_data(self, data):
        if self._script_type is not None:
            self.inline_scripts.append((self._script_type, data))

    def handle_endtag(self, tag):
        if tag == "script":
            self._script_type = None


def parse(page: Path) -> _Resources:
    p = _Resources()
    p.feed(page.read_text(encoding="utf-8"))
    return p


def is_remote(url: str) -> bool:
    return bool(re.match(r"^([a-z][a-z0-9+.-]*:)?//", url, re.I)) and not url.startswith("data:")


# -- sources ---------------------------------------------------------------

def test_toc_lists_only_existing_files():
    toc = yaml.safe_load((BOOK / "_toc.yml").read_text(encoding="utf-8"))
    files = [toc["root"]]
    globs = []
    for part in toc["parts"]:
        for entry in part["chapters"]:
            files += [entry["file"]] if "file" in entry else []
            globs += [entry["glob"]] if "glob" in entry else []
    for name in files:
        assert any((BOOK / f"{name}{ext}").is_file() for ext in (".md", ".ipynb")), name
    assert {g.split("/")[0] for g in globs} >= {"part1_basics", "part2_facer", "part3_tools"}
    assert [p["caption"][:4] for p in toc["parts"][:3]] == ["第一部分", "第二部分", "第三部分"]


def test_config_is_offline_and_chinese():
    config = yaml.safe_load((BOOK / "_config.yml").read_text(encoding="utf-8"))
    sphinx = config["sphinx"]["config"]
    assert config["language"] == "zh_CN" and sphinx["language"] == "zh_CN"
    assert config["execute"]["execute_notebooks"] == "off"
    assert "sphinx_thebe" not in sphinx["extensions"]
    assert config["launch_buttons"]["thebe"] is False
    assert not is_remote(sphinx["mathjax_path"])
    assert list(sphinx["nb_ipywidgets_js"]) == [
        "vendor/require.js", "vendor/labkit_widgets.js", "vendor/jupyter-widgets/embed-amd.js"]


def test_static_face_wins_over_widget_view():
    from myst_nb.core.render import get_mime_priority

    config = yaml.safe_load((BOOK / "_config.yml").read_text(encoding="utf-8"))
    overrides = [tuple(o) for o in config["sphinx"]["config"]["nb_mime_priority_overrides"]]
    order = get_mime_priority("html", overrides)

    def shown(*mimes):
        return next(m for m in order if m in mimes)

    assert shown(WIDGET_VIEW, "image/png", "text/plain") == "image/png"
    assert shown(WIDGET_VIEW, "image/svg+xml", "text/plain") == "image/svg+xml"
    assert shown(WIDGET_VIEW, "text/html", "text/plain") == "text/html"
    # A widget with no static face still shows as a widget, not as its repr.
    assert shown(WIDGET_VIEW, "text/plain") == WIDGET_VIEW


def test_chinese_search_uses_jieba():
    from sphinx.search import zh

    assert zh.JIEBA, "jieba is not importable: Sphinx would index Chinese character by character"


# -- the real book's HTML --------------------------------------------------

def test_book_builds_with_every_page(book_html):
    names = {p.relative_to(book_html).as_posix() for p in pages(book_html)}
    assert {"intro.html", "from_book_to_real_ros.html", "part1_basics/index.html",
            "part2_facer/index.html", "part3_tools/index.html", "search.html"} <= names
    intro = (book_html / "intro.html").read_text(encoding="utf-8")
    assert '<html lang="zh-CN"' in intro
    text = html_lib.unescape(re.sub(r"<[^>]+>", "", intro))
    assert "%load_ext labkit" in text and "make lab" in text
    # Wrapped Chinese source lines join without a space (tools/book_sphinx.py).
    assert "环境变量……本书把这道门槛" in text


def test_no_page_fetches_from_the_network(book_html, widget_book_html):
    checked = 0
    for html in (book_html, widget_book_html):
        for page in pages(html):
            found = parse(page)
            remote = [u for u in found.urls if is_remote(u)]
            assert not remote, f"{page.name} fetches {remote}"
            for kind, body in found.inline_scripts:
                if "json" in kind:  # widget state and views are data, not code
                    continue
                assert not re.search(r"https?://", body), f"{page.name}: {body[:200]}"
            checked += 1
    assert checked >= 7


def test_style_sheets_import_nothing_remote(book_html):
    for css in (book_html / "_static").rglob("*.css"):
        text = re.sub(r"/\*.*?\*/", "", css.read_text(encoding="utf-8", errors="replace"),
                      flags=re.S)
        assert not re.search(r"(url\(\s*['\"]?|@import\s+['\"])(https?:)?//", text), css


def test_vendored_files_are_served(book_html):
    vendor = book_html / "_static" / "vendor"
    for name in ("require.js", "labkit_widgets.js", "jupyter-widgets/embed-amd.js",
                 "mathjax/tex-svg-full.js", "widgets/ipycanvas/index.js",
                 "widgets/ipyevents/index.js"):
        assert (vendor / name).is_file(), name
    assert list((vendor / "jupyter-widgets").glob("*.woff2")), "widget icon fonts"


def test_widget_scripts_only_on_widget_pages(book_html):
    intro = parse(book_html / "intro.html")
    # Sphinx puts MathJax on a page whose toctree holds a page with math (the root
    # holds them all), so only the widget manager's scripts must stay off it.
    assert not [u for u in intro.urls if "vendor/" in u and "vendor/mathjax/" not in u]


def test_chinese_words_in_search_index(book_html):
    text = (book_html / "searchindex.js").read_text(encoding="utf-8")
    index = json.loads(text[text.index("(") + 1:text.rindex(")")])
    terms = index["terms"]
    # jieba cuts sentences into words: whole words are index terms, and the
    # ROS vocabulary (tools/book_search_words.txt) stays whole.
    for word in ("话题", "节点", "时间", "工作空间", "海龟仿真器", "功能包"):
        assert word in terms, word
    assert any(CJK.search(t) for t in index["titles"])


# -- the scratch book with saved widget state --------------------------------

def test_widget_page_loads_manager_in_order(widget_book_html):
    found = parse(widget_book_html / "part1_basics" / "widget_page.html")
    scripts = [u.split("?")[0] for u in found.urls if "vendor/" in u]
    assert scripts.index("../_static/vendor/require.js") \
        < scripts.index("../_static/vendor/labkit_widgets.js") \
        < scripts.index("../_static/vendor/jupyter-widgets/embed-amd.js")
    assert "../_static/vendor/mathjax/tex-svg-full.js" in scripts
    kinds = [k for k, _ in found.inline_scripts]
    assert "application/vnd.jupyter.widget-state+json" in kinds


def test_two_faced_output_renders_its_picture(widget_book_html):
    found = parse(widget_book_html / "part1_basics" / "widget_page.html")
    views = [json.loads(body) for kind, body in found.inline_scripts if kind == WIDGET_VIEW]
    assert len(views) == 2  # the slider and the canvas box; not the two-faced one
    assert [u for u in found.urls if u.startswith("../_images/") and u.endswith(".png")]


# -- a missing browser or npm ---------------------------------------------------

def test_missing_tool_fails_in_ci_and_skips_elsewhere(monkeypatch):
    from book_support import missing

    monkeypatch.setenv("CI", "true")
    with pytest.raises(pytest.fail.Exception, match="chromium"):
        missing("chromium is not installed")
    monkeypatch.delenv("CI")
    with pytest.raises(pytest.skip.Exception, match="chromium"):
        missing("chromium is not installed")
