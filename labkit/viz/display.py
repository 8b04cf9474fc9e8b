"""One display call for the two faces of every picture.

`show(widget, static)` emits a single output whose MIME bundle holds both the
widget view (JupyterLab renders it live) and a static picture (the HTML book
and GitHub render that; the book's config ranks the static types first).
"""
import base64

from IPython.display import display


def _b64(data):
    return base64.b64encode(data).decode("ascii") if isinstance(data, bytes) else data


def bundle(widget=None, png=None, svg=None, html=None, jpeg=None, text="<labkit picture>"):
    data = {"text/plain": text}
    if png is not None:
        data["image/png"] = _b64(png)
    if jpeg is not None:           # photos (camera frames): a fraction of a PNG's size
        data["image/jpeg"] = _b64(jpeg)
    if svg is not None:
        data["image/svg+xml"] = svg
    if html is not None:
        data["text/html"] = html
    if widget is not None and getattr(widget, "model_id", None):
        data["application/vnd.jupyter.widget-view+json"] = {
            "version_major": 2, "version_minor": 0, "model_id": widget.model_id}
    return data


def show(widget=None, *, png=None, svg=None, html=None, jpeg=None, text="<labkit picture>"):
    """Display a widget together with its static picture in one output."""
    display(bundle(widget, png=png, svg=svg, html=html, jpeg=jpeg, text=text), raw=True)


def live_kernel():
    """True in live time inside a Jupyter kernel: where live views (widgets that follow
    the graph) belong. Virtual time (nbval, book-exec) stores plain, repeatable output."""
    from labkit.graph import world
    if world.mode() != "live":
        return False
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and getattr(shell, "kernel", None) is not None


def register_window(view):
    """A view opened by a program (turtlesim's canvas, a key pad) belongs to its process:
    when the cell that started the program runs again, the view is shown again."""
    from labkit import process
    proc = process.current()
    if proc is not process.MAIN and view not in proc.windows:
        proc.windows.append(view)


def viewer_thread(target, name):
    """Start a daemon thread for a viewer: it takes no part in virtual time and belongs
    to no labkit process (stopping the program it shows does not join it)."""
    import threading

    from labkit import process
    thread = threading.Thread(target=target, name=name, daemon=True)
    thread._labkit_world = True
    thread._labkit_process = process.MAIN
    thread.start()
    return thread
