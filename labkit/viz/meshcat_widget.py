"""The live face of the 3D viewer in JupyterLab: a widget (anywidget) that runs meshcat's
viewer in the notebook page and gets the scene through the kernel's own comm.

No side port: it works when JupyterLab's server is on another machine, and nothing
polls, so a kernel that is gone leaves the last picture in place and no errors behind.
The static face (`RobotView.iframe()`) is displayed with it in the same output, for
the HTML book and for a notebook reopened without its kernel.
"""
import pathlib

import anywidget
import traitlets

from labkit.viz.meshcat_view import _viewer_js_gz, commands_blob


class MeshcatWidget(anywidget.AnyWidget):
    """A live meshcat view of one RobotView (see labkit/viz/meshcat_view.py)."""

    _esm = pathlib.Path(__file__).with_name("meshcat_widget.js")
    viewer_js = traitlets.Unicode("").tag(sync=True)     # meshcat's viewer, gzip+base64
    height = traitlets.Int(420).tag(sync=True)

    def __init__(self, view, **kwargs):
        super().__init__(viewer_js=_viewer_js_gz(), height=view.height, **kwargs)
        self._view = view
        self._last = None                 # the scene when it stopped following the view
        self.on_msg(self._on_front_end_message)

    def _on_front_end_message(self, _widget, content, _buffers):
        # a view was (re)drawn in a page: give it the whole current scene
        if isinstance(content, dict) and content.get("type") == "ready":
            self.push(self._view.commands() if self._view is not None else self._last)

    def push(self, commands):
        """Send scene changes to every page showing this widget."""
        if commands:
            self.send({"type": "commands"}, buffers=[commands_blob(commands)])

    def detach(self):
        """Stop following the view (labkit.reset()); a page keeps showing the last scene."""
        if self._view is not None:
            self._last = self._view.commands()
            self._view = None
