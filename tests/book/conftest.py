"""Fixtures for the book checks: one offline build of the real book and one
of a scratch book holding a widget notebook, made once per test session,
served on 127.0.0.1 and opened in headless Chromium."""

from __future__ import annotations

import concurrent.futures
import functools
import http.server
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from book_support import BOOK, FIXTURES, ROOT, missing

sys.path.insert(0, str(ROOT / "tools"))
import book_build  # noqa: E402


def _scratch_book(base: Path) -> Path:
    """A scratch book with the real _config.yml and one executed notebook
    with saved widget state (ipywidgets, ipycanvas, ipyevents), a two-faced
    output and math."""
    book = base / "book"
    book.mkdir()
    shutil.copy(BOOK / "_config.yml", book)
    shutil.copytree(BOOK / "_static", book / "_static",
                    ignore=shutil.ignore_patterns("vendor"))
    # _config.yml loads our Sphinx extension from ../tools.
    (base / "tools").symlink_to(ROOT / "tools")
    # In a chapter folder, like the chapters: asset paths must work from there.
    (book / "part1_basics").mkdir()
    shutil.copy(FIXTURES / "widget_page.ipynb.json", book / "part1_basics" / "widget_page.ipynb")
    (book / "_toc.yml").write_text("format: jb-book\nroot: part1_basics/widget_page\n",
                                   encoding="utf-8")
    return book


@pytest.fixture(scope="session")
def _builds(tmp_path_factory) -> dict[str, Path]:
    """Both builds, side by side (each is its own jupyter-book process).
    Private output folders: other people may build book/_build meanwhile."""
    try:
        book_build.ensure_node_modules()  # once, before the parallel builds
    except SystemExit as exc:  # no npm to fetch the browser files
        missing(str(exc))
    scratch_base = tmp_path_factory.mktemp("widget_book")
    jobs = {"book": (BOOK, tmp_path_factory.mktemp("book")),
            "widgets": (_scratch_book(scratch_base), scratch_base / "out")}
    with concurrent.futures.ThreadPoolExecutor(len(jobs)) as pool:
        # jupyter-book runs without any network where the machine allows it.
        futures = {name: pool.submit(book_build.build, book, out, without_network=True)
                   for name, (book, out) in jobs.items()}
        try:
            return {name: f.result() for name, f in futures.items()}
        except subprocess.CalledProcessError as exc:
            pytest.fail(f"book build failed: {exc}", pytrace=False)


@pytest.fixture(scope="session")
def book_html(_builds) -> Path:
    """The real book, built offline."""
    return _builds["book"]


@pytest.fixture(scope="session")
def widget_book_html(_builds) -> Path:
    """The scratch book holding the widget notebook, built offline."""
    return _builds["widgets"]


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):  # keep pytest's output clean
        pass


@pytest.fixture(scope="session")
def served(book_html, widget_book_html, tmp_path_factory):
    """Both builds on one local server: returns a url(name, path) function."""
    site = tmp_path_factory.mktemp("site")
    for name, html in {"book": book_html, "widgets": widget_book_html}.items():
        (site / name).symlink_to(html, target_is_directory=True)
    handler = functools.partial(_QuietHandler, directory=str(site))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    port = server.server_address[1]
    yield lambda name, path="": f"http://127.0.0.1:{port}/{name}/{path}"
    server.shutdown()
    server.server_close()
    thread.join()


@pytest.fixture(scope="session")
def browser(tmp_path_factory):
    from book_cdp import Browser, find_chromium

    binary = find_chromium()
    if binary is None:
        missing("chromium is not installed (Debian: apt-get install chromium "
                "fonts-noto-cjk; .ci/run does this in CI)")
    profile = tmp_path_factory.mktemp("chromium") / "profile"
    profile.mkdir()
    chrome = Browser(binary, profile)
    yield chrome
    chrome.close()


@pytest.fixture(scope="session")
def page(browser):
    p = browser.page()
    yield p
    p.close()
