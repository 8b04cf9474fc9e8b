"""`make lab` / `labkit lab`: the book in JupyterLab, live, on a working copy.

    labkit lab [--root lab] [jupyterlab options...]
    python -m labkit.tools.lab [--root lab] [jupyterlab options...]

In a checkout of the book the working copy is `lab/` beside `book/`; where labkit was
installed with pip alone (`pip install "labkit[lab]"`, no book beside it) JupyterLab
opens the current folder (or --root) as it is. Run as root (Docker, WSL, cloud VMs)
it passes JupyterLab's --allow-root itself. JupyterLab starts with the settings in
lab_settings/overrides.json: no "get notified about official Jupyter news?" popup, no
update check (nothing reaches the network); and with lab_custom/custom.css, which
scales an SVG picture wider than its cell down to the cell (JupyterLab draws SVG
outputs as images at their own size).

JupyterLab saves (and autosaves) the notebooks it has open. So that a learner's
checkout stays clean, the book's files are copied once into a working folder
(`lab/`, ignored by git) and JupyterLab opens that: run, change, break and save
freely there; delete a file (or the whole folder) to get the book's version back
on the next `make lab`. Files already in the working copy are never overwritten.

Saving also drops the live widget views from outputs: their models live in the
kernel, so after a reload they would only read "Error displaying widget: model
not found"; the static face stored beside them (the PNG of a canvas, the picture
of a keypad, a job's command line) is what a reopened notebook shows.
"""
import os
import pathlib
import shutil
import signal
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
BOOK = ROOT / "book"
SKIP = {"_build", "_work", ".ipynb_checkpoints", "__pycache__"}
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
SETTINGS = pathlib.Path(__file__).resolve().parent / "lab_settings"
CUSTOM_CSS = pathlib.Path(__file__).resolve().parent / "lab_custom" / "custom.css"
CSS_BEGIN, CSS_END = "/* labkit lab: begin */", "/* labkit lab: end */"


def working_copy(book=BOOK, target=ROOT / "lab"):
    """Copy the book's files that the working copy does not have yet; returns the
    list of files copied."""
    copied = []
    for src in sorted(book.rglob("*")):
        rel = src.relative_to(book)
        if any(part in SKIP for part in rel.parts) or not src.is_file():
            continue
        dst = target / rel
        if dst.exists():
            continue
        dst.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dst)
        copied.append(rel)
    return copied


def strip_live_views(model, **kwargs):
    """jupyter_server pre-save hook: no widget view is saved where the output has
    another face to show."""
    if model.get("type") != "notebook":
        return
    for cell in model["content"].get("cells", []):
        for out in cell.get("outputs", []) or []:
            data = out.get("data")
            if data and WIDGET_VIEW in data and len(data) > 1:
                del data[WIDGET_VIEW]


def is_root():
    return hasattr(os, "geteuid") and os.geteuid() == 0


def command(root, extra=()):
    extra = list(extra)
    if is_root() and "--allow-root" not in extra:
        extra.append("--allow-root")     # JupyterLab refuses root without it
    return [sys.executable, "-m", "jupyterlab", "--ip=127.0.0.1",
            f"--notebook-dir={root}",
            "--ContentsManager.pre_save_hook=labkit.tools.lab.strip_live_views",
            f"--LabApp.app_settings_dir={SETTINGS}",
            "--LabApp.custom_css=True",       # the page loads <config dir>/custom/custom.css
            *extra]


def install_custom_css(config_dir=None):
    """Put labkit's rules into JupyterLab's custom.css (<Jupyter config dir>/custom/),
    which the page loads when started with --LabApp.custom_css=True, as `labkit lab`
    starts it; jupyter_server reads custom.css from the config dir only. The rules sit
    between two marker comments: whatever else the file holds is kept, and running
    again replaces only labkit's block. Returns the file's path."""
    if config_dir is None:
        from jupyter_core.paths import jupyter_config_dir
        config_dir = jupyter_config_dir()
    path = pathlib.Path(config_dir) / "custom" / "custom.css"
    path.parent.mkdir(parents=True, exist_ok=True)
    ours = f"{CSS_BEGIN}\n{CUSTOM_CSS.read_text(encoding='utf-8').strip()}\n{CSS_END}\n"
    text = path.read_text(encoding="utf-8") if path.exists() else ""
    if CSS_BEGIN in text and CSS_END in text:
        head, rest = text.split(CSS_BEGIN, 1)
        text = head + ours + rest.split(CSS_END, 1)[1].lstrip("\n")
    else:
        text = text + ("\n" if text and not text.endswith("\n") else "") + ours
    path.write_text(text, encoding="utf-8")
    return path


def run(cmd, env=None):
    """Run JupyterLab as a child and wait for it (os.execv does not exist as such on
    Windows). Ctrl+C reaches the child through the terminal as it would reach
    `jupyter lab`; SIGTERM/SIGHUP sent to us are passed on; the child's exit code is
    ours."""
    child = subprocess.Popen(cmd, env=env)
    forwarded = []

    def forward(signum, frame):
        forwarded.append(signum)
        if child.poll() is None:
            child.send_signal(signum)

    old = {}
    for name in ("SIGTERM", "SIGHUP"):
        sig = getattr(signal, name, None)
        if sig is not None:
            try:
                old[sig] = signal.signal(sig, forward)
            except ValueError:       # not the main thread
                pass
    try:
        while True:
            try:
                return child.wait()
            except KeyboardInterrupt:
                # the terminal sent Ctrl+C to the child too; JupyterLab asks or stops
                continue
    finally:
        for sig, handler in old.items():
            signal.signal(sig, handler)


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    book = BOOK if (BOOK / "_toc.yml").is_file() else None
    root = ROOT / "lab" if book else pathlib.Path.cwd()
    if argv[:1] == ["--root"]:
        root = pathlib.Path(argv[1]).resolve()
        argv = argv[2:]
    if book is not None:
        copied = working_copy(book, root)
        if copied:
            print(f"labkit: {len(copied)} files of the book copied to {root.name}/ "
                  "(your working copy; the book itself stays as shipped)")
    env = dict(os.environ, LABKIT_TIME="live")
    install_custom_css()
    return run(command(root, argv), env=env)


if __name__ == "__main__":
    sys.exit(main())
