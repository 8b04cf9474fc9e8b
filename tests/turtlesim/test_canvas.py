"""The canvas faces: PNG snapshot, animated replay, and the live widget's drawing logic."""
import io

import numpy as np
from PIL import Image

from labkit.sims.turtlesim import physics as P
from labkit.viz.canvas import TurtleCanvas
from labkit.viz.replay import replay

TICK = 16_000_000


def driven_world(seconds=3.0):
    w = P.TurtleWorld()
    w.spawn("", P.CENTER, P.CENTER, 0.0)
    w.step(0)
    t = 0
    for k in range(int(seconds / 0.016)):
        t += TICK
        if k % 25 == 0:
            w.turtles["turtle1"].command_velocity(2.0, 0.0, 1.0, t)
        w.step(t)
    return w


def test_snapshot_is_a_500x500_png_showing_background_trail_and_turtle():
    w = driven_world()
    png = TurtleCanvas(w).snapshot()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert png._repr_png_() == bytes(png)           # shows as a picture in a notebook
    img = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))
    assert img.shape == (500, 500, 3)
    assert tuple(img[2, 2]) == P.DEFAULT_BACKGROUND
    trail = (img == P.DEFAULT_PEN).all(axis=2)
    assert trail.sum() > 300                      # a 3 px wide trail of a few metres
    # the start of the trail is where turtle1 started, the centre of the window
    assert trail[247:253, 247:253].any()
    # the turtle sprite (green) sits at the turtle's position
    x, y, _ = w.turtles["turtle1"].pose()
    col, row = int(x * P.METER), int((P.HEIGHT_IN_METERS - y) * P.METER)
    patch = img[row - 8:row + 8, col - 8:col + 8].astype(int)
    assert ((patch[..., 1] > patch[..., 2] + 30)).sum() > 20


def test_snapshot_follows_background_and_clear():
    w = driven_world(1.0)
    w.set_background((255, 0, 0))
    w.clear()
    img = np.asarray(Image.open(io.BytesIO(TurtleCanvas(w).snapshot())).convert("RGB"))
    assert tuple(img[2, 2]) == (255, 0, 0)
    assert not (img == P.DEFAULT_PEN).all(axis=2).any()


def test_replay_is_small_animated_and_deterministic():
    w = driven_world(6.0)
    first = replay(w, seconds=5, fps=15, format="gif")
    assert replay(w, seconds=1, fps=5).data == replay(w, seconds=1, fps=5).data
    assert len(first.data) < 300_000
    img = Image.open(io.BytesIO(first.data))
    assert img.format == "GIF" and img.n_frames == first.frames == 76
    img.seek(0)
    start = np.asarray(img.convert("RGB"))
    img.seek(img.n_frames - 1)
    end = np.asarray(img.convert("RGB"))
    assert (start != end).any()                   # something moved
    webp = replay(w, seconds=1, fps=5, format="webp")
    assert Image.open(io.BytesIO(webp.data)).format == "WEBP" and len(webp.data) < 300_000
    bundle = first._repr_mimebundle_()
    assert bundle["text/html"].startswith('<img src="data:image/gif;base64,')


def test_replay_rebuilds_the_pen_layer_of_the_past():
    w = driven_world(4.0)
    frames = replay(w, seconds=3, fps=5).frames
    img = Image.open(io.BytesIO(replay(w, seconds=3, fps=5).data))
    counts = []
    for i in range(frames):
        img.seek(i)
        counts.append(int((np.asarray(img.convert("RGB")) == P.DEFAULT_PEN).all(axis=2).sum()))
    assert counts == sorted(counts) and counts[0] < counts[-1]   # the trail grows


def test_live_widget_draws_only_changes():
    w = driven_world(0.5)
    canvas = TurtleCanvas(w)
    canvas.widget                                  # builds and draws the first frame
    assert canvas.frames_drawn == 1
    canvas._draw()
    assert canvas.frames_drawn == 1                # nothing changed: nothing sent
    t = w.now_ns
    w.turtles["turtle1"].command_velocity(1.0, 0.0, 0.0, t)
    for _ in range(3):
        t += TICK
        w.step(t)
    canvas._draw()
    assert canvas.frames_drawn == 2
    w.set_background((0, 0, 0))
    canvas._draw()
    assert canvas.frames_drawn == 3
    canvas.close()
    assert canvas._wake.set not in w.listeners


def test_live_widget_follows_in_a_thread_and_stops():
    w = driven_world(0.2)
    canvas = TurtleCanvas(w)
    canvas.start()
    assert canvas._thread.is_alive()
    canvas.stop()
    assert canvas._thread is None


def test_canvas_thread_ends_with_its_turtlesim():
    import threading
    from labkit import process
    from labkit.sims.turtlesim import node
    proc = process.start(["turtlesim", "turtlesim_node"], echo=False)
    canvas = TurtleCanvas(node.running()[-1])
    canvas.start()
    thread = canvas._thread
    proc.stop()
    thread.join(timeout=5.0)          # the follower notices within a second
    assert not thread.is_alive()
    assert threading.active_count() < 50
