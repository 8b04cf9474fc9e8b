"""The turtlesim canvas's draw pipeline over a long live session with several canvases.

The browser side of ipycanvas keeps, per canvas manager, one "current canvas" and
one queue of commands. A model of it here replays every message the kernel sends
and checks what a browser would draw: every canvas gets its own full frame
(background, trails, turtles), no command lands on another canvas, and no
command arrives without a canvas to draw on. (ch22 in JupyterLab: a new canvas
stayed white because its first frame went to another canvas through the shared
manager.)
"""
import collections
import threading
import time

import pytest

import labkit


class BrowserModel:
    """What ipycanvas's JavaScript does with the manager messages (no pixels)."""

    def __init__(self):
        from ipycanvas.canvas import _CMD_LIST
        self.names = _CMD_LIST
        self.current = {}                               # manager -> canvas model id
        self.drawn = collections.defaultdict(list)      # canvas model id -> commands
        self.switched = collections.defaultdict(set)    # manager -> canvas ids
        self.errors = []
        self.lock = threading.Lock()

    def receive(self, manager, command, buffers):
        commands = command if command and isinstance(command[0], list) else [command]
        with self.lock:
            wanted = sum(c[2] for c in commands if len(c) > 2)
            if wanted != len(buffers):
                self.errors.append(f"{wanted} buffers announced, {len(buffers)} sent")
            for c in commands:
                name = self.names[c[0]]
                if name == "switchCanvas":
                    target = c[1][0].replace("IPY_MODEL_", "")
                    self.current[id(manager)] = target
                    self.switched[id(manager)].add(target)
                elif id(manager) not in self.current:
                    self.errors.append(f"{name} with no canvas to draw on")
                else:
                    self.drawn[self.current[id(manager)]].append(name)


@pytest.fixture
def browser(monkeypatch):
    from ipycanvas.canvas import _CanvasManager
    model = BrowserModel()
    original = _CanvasManager._send_custom

    def send(self, command, buffers=[]):
        model.receive(self, command, list(buffers))
        return original(self, command, buffers)
    monkeypatch.setattr(_CanvasManager, "_send_custom", send)
    return model


def test_many_canvases_each_get_their_own_frames(live_time, browser, until):
    from labkit.viz.canvas import TurtleCanvas
    canvases = []

    def open_canvas(sim=None):
        c = TurtleCanvas.attach(sim)
        c.widget
        c.start()
        canvases.append(c)
        return c

    for round_ in range(3):         # three turtlesims, as a chapter runs them one by one
        labkit.ros2("run turtlesim turtlesim_node")
        from labkit.sims.turtlesim import node
        assert until(lambda: node.running())
        labkit.ros2('topic pub --rate 30 /turtle1/cmd_vel geometry_msgs/msg/Twist '
                    '"{linear: {x: 2.0}, angular: {z: 1.8}}"')
        open_canvas()
        # new canvases open while the others draw, from other threads too (turtlesim
        # opens its window from its own process thread)
        openers = [threading.Thread(target=open_canvas, args=(node.running()[-1],))
                   for _ in range(2)]
        for t in openers:
            t.start()
        open_canvas()
        for t in openers:
            t.join()
        time.sleep(0.6)
        labkit.reset()

    try:
        assert not browser.errors, browser.errors[:3]
        owner = {}
        for c in canvases:
            for layer in c._layers:
                owner[layer.model_id] = c
        for switched in browser.switched.values():
            assert len({id(owner[m]) for m in switched}) == 1, \
                "one manager drew on several turtle canvases"
        for c in canvases:
            background, trails, turtles = (browser.drawn[layer.model_id] for layer in c._layers)
            assert "fillRect" in background and "putImageData" in trails \
                and "drawImage" in turtles, "a canvas never got its first full frame"
            assert c.frames_drawn >= 1 and c.messages_sent >= 1
    finally:
        for c in canvases:
            c.close()


def test_a_failed_frame_still_leaves_its_commands_whole(live_time, browser, monkeypatch):
    """An error half-way through a frame must not leave the canvas's channel holding
    commands (ipycanvas's own hold_canvas() does, for every canvas of the kernel)."""
    from labkit.viz import canvas as canvas_module
    labkit.ros2("run turtlesim turtlesim_node")
    c = canvas_module.TurtleCanvas.attach()
    c.widget
    monkeypatch.setattr(canvas_module.TurtleCanvas, "_sprite_image",
                        lambda self, look: (_ for _ in ()).throw(RuntimeError("boom")))
    with pytest.raises(RuntimeError):
        c._draw(full=True)
    assert c._manager._commands_cache == []
    assert not browser.errors
    c.close()


def test_reset_leaves_no_canvas_following(live_time, browser):
    from labkit.viz.canvas import TurtleCanvas
    labkit.ros2("run turtlesim turtlesim_node")
    canvases = [TurtleCanvas.attach() for _ in range(3)]
    for c in canvases:
        c.start()
    threads = [c._thread for c in canvases]
    labkit.reset()
    assert all(not t.is_alive() for t in threads)
    labkit.ros2("run turtlesim turtlesim_node")      # a new turtlesim: a new canvas works
    fresh = TurtleCanvas.attach()
    fresh.start()
    assert fresh.frames_drawn == 1 and fresh._thread.is_alive()
    assert "putImageData" in browser.drawn[fresh._layers[1].model_id]
    fresh.close()
