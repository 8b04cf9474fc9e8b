"""Paths and helpers shared by the book checks (a plain module: test files
must not import conftest, whose name other test folders share)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BOOK = ROOT / "book"
FIXTURES = Path(__file__).resolve().parent / "fixtures"
SCREENSHOTS = BOOK / "_build" / "screenshots"


def in_ci() -> bool:
    return os.environ.get("CI", "").lower() in ("1", "true", "yes")


def missing(reason: str):
    """A missing system tool fails the check in CI and skips it elsewhere."""
    if in_ci():
        pytest.fail(reason, pytrace=False)
    pytest.skip(reason)


def pages(html: Path) -> list[Path]:
    """The HTML pages of a build (not the files under _static and friends)."""
    skip = ("_static", "_sources", "_images")
    return sorted(p for p in html.rglob("*.html") if p.relative_to(html).parts[0] not in skip)
