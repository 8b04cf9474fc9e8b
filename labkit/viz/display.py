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
