"""Build the HTML book offline: ``make book`` runs this.

1. ``npm ci`` when node_modules is missing or older than package-lock.json
   (the only step that uses the network: the npm registry, once);
2. copy the browser files into book/_static/vendor (tools/book_assets.py);
3. ``jupyter-book build`` from the outputs stored in the notebooks.

Run: ``python tools/book_build.py [--book book] [--path-output DIR]``.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import book_assets  # noqa: E402  (sibling script)
import make  # noqa: E402  (sibling script: npm ci, shared with the test set-up)

ROOT = book_assets.ROOT


def ensure_node_modules(root: Path = ROOT) -> None:
    if not make.ensure_node_modules(root):
        raise SystemExit("book_build: node_modules is missing and `npm` is not installed "
                         "(install Node.js, then run `npm ci` in the repository root)")


def no_network_prefix() -> list[str]:
    """`unshare` arguments that run a command with no network at all, when
    this machine allows it (root, or user namespaces); else nothing."""
    unshare = shutil.which("unshare")
    for args in (["-n"], ["-r", "-n"]):
        if unshare and subprocess.run([unshare, *args, "true"],
                                      capture_output=True).returncode == 0:
            return [unshare, *args]
    return []


def build(book: Path, path_output: Path | None = None, *, without_network=False) -> Path:
    """Build the HTML; return the folder holding index.html.

    ``without_network=True`` runs jupyter-book where it cannot reach any
    network (if the machine allows it), proving the build needs none.
    """
    ensure_node_modules()
    book_assets.vendor(book)
    prefix = no_network_prefix() if without_network else []
    cmd = [*prefix, sys.executable, "-c", "from jupyter_book.cli.main import main; main()",
           "build", str(book)]
    if path_output is not None:
        cmd += ["--path-output", str(path_output)]
    subprocess.run(cmd, check=True)
    return (path_output or book) / "_build" / "html"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--book", type=Path, default=ROOT / "book")
    parser.add_argument("--path-output", type=Path, default=None,
                        help="build into DIR/_build/html instead of book/_build/html")
    args = parser.parse_args(argv)
    build(args.book, args.path_output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
