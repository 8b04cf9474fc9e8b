"""A turtlesim canvas shown again draws a whole frame again.

In live JupyterLab, reloading the page (or reopening the notebook) while the
kernel runs gives the browser new, empty canvas models: ipycanvas keeps no
pixels. When the learner then re-runs `%ros2 run turtlesim turtlesim_node`, the
running job shows its canvas again; it must not stay white (no background, no
trails) until the turtle moves, and then show only what changed since.
"""
import collections

import pytest

import labkit


@pytest.fixture
def sent(monkeypatch):
    """The drawing commands each canvas model got from the kernel, by model id."""
    from ipycanvas.canvas import _CMD_LIST, _CanvasManager
    drawn = collections.defaultdict(list)
    current = {}
    original = _CanvasManager._send_custom

    def send(self, command, buffers=[]):
        commands = command if command and isinstance(command[0], list) else [command]
        for c in commands:
            name = _CMD_LIST[c[0]]
            if name == "switchCanvas":
                current[id(self)] = c[1][0].replace("IPY_MODEL_", "")
            elif id(self) in current:
                drawn[current[id(self)]].append(name)
        return original(self, command, buffers)
    monkeypatch.setattr(_CanvasManager, "_send_custom", send)
    return drawn


def test_a_canvas_shown_again_gets_a_whole_frame(live_time, sent, until):
    from labkit.viz.canvas import TurtleCanvas
    labkit.ros2("run turtlesim turtlesim_node")
    canvas = TurtleCanvas.attach()
    try:
        canvas._ipython_display_()
        background, trails, turtles = (layer.model_id for layer in canvas._layers)
        assert until(lambda: "fillRect" in sent[background] and "drawImage" in sent[turtles])
        # the page is reloaded: the browser's canvas models start empty
        sent.clear()
        frames = canvas.frames_drawn
        canvas._ipython_display_()          # the cell that started turtlesim runs again
        assert until(lambda: canvas.frames_drawn > frames)
        assert "fillRect" in sent[background], "the background was not drawn again"
        assert "putImageData" in sent[trails], "the pen trails were not drawn again"
        assert "drawImage" in sent[turtles], "the turtle was not drawn again"
    finally:
        canvas.close()
