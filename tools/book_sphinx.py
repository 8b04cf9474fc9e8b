"""Sphinx extension for the labkit book (loaded through book/_config.yml).

jupyter-book v1 adds every ``*.js`` and ``*.css`` under ``book/_static`` to
every page. The files that ``tools/book_assets.py`` copies into
``_static/vendor`` must not be: MathJax is loaded by Sphinx only on pages
with math, and the widget scripts by myst-nb only on pages that hold saved
widget state (in the order RequireJS needs). This removes them again.

It also gives Sphinx's Chinese search indexer our ROS vocabulary, and drops
the line breaks of wrapped Chinese source text, which browsers would show as
spaces between two Chinese characters.
"""

from __future__ import annotations

import re
from pathlib import Path

from docutils import nodes

VENDOR_PREFIX = "vendor/"
# ROS words jieba should keep whole when it indexes the pages for search
# ("工作空间", not "工作" + "空间"), so that a reader's query finds them.
SEARCH_WORDS = Path(__file__).resolve().parent / "book_search_words.txt"


def _filename(entry) -> str:
    # html_js_files / html_css_files hold names or (name, attributes) pairs.
    return entry[0] if isinstance(entry, (tuple, list)) else entry


def drop_vendor_files(app, config) -> None:
    for key in ("html_js_files", "html_css_files"):
        files = getattr(config, key, None) or []
        kept = [f for f in files if not str(_filename(f)).startswith(VENDOR_PREFIX)]
        # jupyter-book may list _static twice (ours and its own): keep one each.
        unique = []
        for f in kept:
            if f not in unique:
                unique.append(f)
        setattr(config, key, unique)


def add_search_words(app, config) -> None:
    # Sphinx's Chinese indexer loads a jieba user dictionary from this option;
    # set it here because the path must be absolute.
    options = dict(config.html_search_options or {})
    options.setdefault("dict", str(SEARCH_WORDS))
    config.html_search_options = options


# Wide (CJK) characters, full-width punctuation, and the dashes, ellipsis and
# quotes Chinese text uses.
_WIDE = "\u2e80-\u9fff\uf900-\ufaff\u3000-\u303f\uff00-\uffef\u2014\u2026\u201c\u201d\u2018\u2019"
_WIDE_CHAR = re.compile(f"[{_WIDE}]")
_CJK_BREAK = re.compile(f"(?<=[{_WIDE}])[ \\t]*\\n[ \\t]*(?=[{_WIDE}])")
# Text inside these is shown as written.
_VERBATIM = (nodes.literal_block, nodes.literal, nodes.raw, nodes.math,
             nodes.math_block, nodes.comment)


def join_cjk_lines(app, doctree) -> None:
    """Remove a soft line break between two Chinese characters (Markdown
    source wrapped at 80 columns), as CSS Text 3 asks and browsers don't.

    MyST gives each soft break its own Text node ("\\n") between the text
    nodes of the two lines, so look at the neighbours too.
    """
    for element in list(doctree.findall(nodes.TextElement)):
        if isinstance(element, _VERBATIM):
            continue
        children = element.children
        for i, child in enumerate(children):
            if not isinstance(child, nodes.Text) or "\n" not in child:
                continue
            text = str(child)
            if not text.strip():  # a soft break on its own
                before = _edge(children[i - 1], -1) if i > 0 else ""
                after = _edge(children[i + 1], 0) if i + 1 < len(children) else ""
                joined = "" if _WIDE_CHAR.match(before) and _WIDE_CHAR.match(after) else text
            else:
                joined = _CJK_BREAK.sub("", text)
            if joined != text:
                children[i] = nodes.Text(joined)
                children[i].parent = element


def _edge(node, index: int) -> str:
    """First (index 0) or last (index -1) character of a plain Text node."""
    if isinstance(node, nodes.Text) and str(node):
        return str(node)[index]
    return ""


def setup(app):
    app.connect("doctree-read", join_cjk_lines)
    app.connect("config-inited", add_search_words)
    app.connect("config-inited", drop_vendor_files, priority=100)
    # jupyter-book always passes `comments_config` (for sphinx_comments, which
    # the book does not load: comments need third-party servers). Knowing the
    # name keeps the build free of an "unknown config value" warning.
    if "comments_config" not in app.config:
        app.add_config_value("comments_config", {}, "html")
    return {"parallel_read_safe": True, "parallel_write_safe": True}
