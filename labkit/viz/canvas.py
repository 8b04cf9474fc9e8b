"""The turtlesim window, in two faces: a live canvas widget and a static PNG.

    from labkit.viz.canvas import TurtleCanvas
    c = TurtleCanvas.attach()     # the turtlesim running in this kernel
    c                             # live widget in JupyterLab + PNG for the book
    c.snapshot()                  # PNG bytes of the current state (500x500)
    c.replay(seconds=5)           # animated picture of the last 5 s

The live widget is an ipycanvas MultiCanvas with three layers: the background
colour, the pen trails (drawn incrementally from the simulator's pen log), and
the turtles. A daemon thread redraws at most `fps` times a second and only
after the simulator reported a change, so an idle canvas costs nothing.

Each canvas sends its drawing through a command channel of its own (an ipycanvas
canvas manager), one message per frame. ipycanvas's default is one manager for
the whole kernel, whose "current canvas" is shared state: with several canvases
drawing from their own threads (a long session: every `TurtleCanvas.attach()`
follows the newest turtlesim), a command set from one thread while another
thread's frame was being sent went missing, together with the "switch to this
canvas" before it, so the new canvas's first frame was drawn onto another canvas
and the new one stayed white; and in the browser one failed command stops that
manager's queue for every canvas that shares it. One manager per canvas keeps
every canvas's commands, and any failure, to itself.
"""
import io
import threading
import time
import weakref

import numpy as np
from PIL import Image

from labkit.sims.turtlesim import physics, sprites

SIZE = physics.WINDOW_SIZE
_following = weakref.WeakSet()          # canvases whose thread follows a simulation


# ------------------------------------------------------------------ static rendering
def compose(background, turtles, pixels):
    """One frame as a PIL RGB image: background, pen layer, then the turtles.

    `turtles` holds (name, x_px, y_px, orient, sprite) as TurtleWorld.snapshot() gives them.
    """
    image = Image.new("RGB", (SIZE, SIZE), tuple(background))
    pen = Image.frombuffer("RGBA", (SIZE, SIZE), np.ascontiguousarray(pixels), "raw", "RGBA", 0, 1)
    image.paste(pen, (0, 0), pen)       # alpha is 0 or 255: the pen layer is copied where drawn
    for _, x, y, orient, look in turtles:
        turned = sprites.rotated(look, int(round(np.degrees(orient))) % 360)
        w, h = turned.size
        image.paste(turned, (int(round(x - w / 2)), int(round(y - h / 2))), turned)
    return image


def render(world):
    """The current state of a TurtleWorld as a PIL RGB image (500x500)."""
    with world.lock:
        background, turtles, _ = world.snapshot()
        pixels = world.path.pixels.copy()
    return compose(background, turtles, pixels)


class PNG(bytes):
    """PNG file bytes that a notebook displays as the picture."""

    def _repr_png_(self):
        return bytes(self)

    def __repr__(self):
        return f"<PNG image, {len(self)} bytes>"


def png_bytes(image):
    buf = io.BytesIO()
    image.save(buf, format="PNG")
    return PNG(buf.getvalue())


def _find_world(source=None):
    """A TurtleWorld from a TurtleSim node, a world, or the newest running turtlesim."""
    if source is None:
        from labkit.sims.turtlesim import node
        sims = node.running()
        if not sims:
            raise RuntimeError("turtlesim is not running (start it with "
                               "`ros2 run turtlesim turtlesim_node`)")
        source = sims[-1]
    return source if isinstance(source, physics.TurtleWorld) else source.world


# ------------------------------------------------------------------------ the canvas
class TurtleCanvas:
    """A view of one turtlesim. Display it for the live widget (plus a PNG)."""

    def __init__(self, sim=None, fps=30):
        self.world = _find_world(sim)
        self._node = sim if sim is not None and hasattr(sim, "world") else None
        self._newest = sim is None      # attached to "the running turtlesim": follow restarts
        self.fps = fps
        self.frames_drawn = 0           # live frames sent to the browser
        self._widget = None
        self._layers = None
        self._images = {}               # sprite index -> ipywidgets.Image
        self._wake = threading.Event()
        self._stop = threading.Event()
        self._thread = None
        self._drawn = None              # (background, turtles, pen seq) last sent
        self._manager = None            # this canvas's own ipycanvas command channel
        self._draw_lock = threading.Lock()
        self.messages_sent = 0          # frames flushed to the browser

    @classmethod
    def attach(cls, sim=None, fps=30):
        """A canvas on the newest turtlesim running in this kernel (or on `sim`)."""
        return cls(sim, fps=fps)

    @classmethod
    def remote(cls, fps=30):
        """A canvas on the turtlesim of another process (after labkit.connect()): its
        turtles follow their /<name>/pose topics (labkit.viz.remote_turtles)."""
        from labkit.viz.remote_turtles import RemoteTurtles
        canvas = cls(RemoteTurtles().world, fps=fps)
        return canvas

    # -- static faces -----------------------------------------------------------------
    def image(self):
        """The current picture as a PIL image."""
        self._follow_restart()
        return render(self.world)

    def snapshot(self):
        """The current picture as PNG bytes (500x500, like the real window); shows as an image."""
        return png_bytes(self.image())

    def replay(self, seconds=5.0, fps=15, format="gif", scale=1.0):
        """An animated picture (GIF or WebP) of the last `seconds` of simulation."""
        from labkit.viz.replay import replay
        self._follow_restart()
        return replay(self.world, seconds=seconds, fps=fps, format=format, scale=scale)

    def _follow_restart(self):
        """If attached to 'the running turtlesim' and a newer one started, switch to it."""
        if not self._newest:
            return False
        from labkit.sims.turtlesim import node
        sims = node.running()
        if not sims or sims[-1].world is self.world:
            return False
        old, self.world = self.world, sims[-1].world
        if self._widget is not None:
            if self._wake.set in old.listeners:
                old.listeners.remove(self._wake.set)
            self.world.listeners.append(self._wake.set)
            self._drawn = None          # next frame redraws everything
            self._wake.set()
        return True

    def _repr_png_(self):
        return bytes(self.snapshot())

    def _ipython_display_(self):
        from labkit.viz.display import register_window, show
        widget = self.widget
        self.start()
        register_window(self)           # turtlesim's window: shown again if its cell re-runs
        show(widget, png=self.snapshot(), text="<turtlesim canvas>")
        # a page reloaded meanwhile has empty canvas models (ipycanvas keeps no pixels):
        # every showing gets a whole frame, not only what changed since the last one
        with self._draw_lock:
            self._drawn = None
        self._wake.set()

    # -- live face ----------------------------------------------------------------------
    @property
    def widget(self):
        if self._widget is None:
            self._build()
        return self._widget

    def _build(self):
        from ipycanvas import MultiCanvas
        from ipycanvas.canvas import _CanvasManager
        # a command channel of its own that holds every command until the frame is
        # complete (see the module's docstring)
        self._manager = _CanvasManager()
        self._manager._caching = True
        self._widget = MultiCanvas(3, width=SIZE, height=SIZE)
        self._layers = [self._widget[i] for i in range(3)]
        for layer in self._layers:
            layer._canvas_manager = self._manager
        with self._draw_lock:
            self._layers[1].line_cap = "square"      # Qt's default pen cap
        self._draw(full=True)
        self.world.listeners.append(self._wake.set)

    def start(self):
        """Start following the simulation (idempotent)."""
        if self._thread is not None and self._thread.is_alive():
            return
        self.widget
        self._stop.clear()
        # a plain thread: it only reads the world, so it never takes part in virtual time.
        # turtlesim_node shows its window from its own process thread; labkit.process would
        # then adopt this thread into that process and into virtual time, where its plain
        # Event waits hold the baton forever. A viewer belongs to neither.
        from labkit.viz.display import viewer_thread
        self._thread = viewer_thread(self._follow, "turtle-canvas")
        _following.add(self)

    def stop(self):
        """Stop following (the widget keeps its last picture)."""
        self._stop.set()
        self._wake.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        self._thread = None
        if self._wake.set in self.world.listeners:
            self.world.listeners.remove(self._wake.set)

    def close(self):
        self.stop()
        if self._widget is not None:
            self._widget.close()
            self._manager.close()

    def _follow(self):
        period = 1.0 / self.fps
        while not self._stop.is_set():
            if not self._wake.wait(timeout=1.0):
                # idle: nothing changed; but turtlesim may have restarted or ended
                if not self._follow_restart() and self._source_ended():
                    break
                continue
            self._wake.clear()
            if self._stop.is_set():
                break
            started = time.monotonic()
            try:
                self._draw()
            except Exception:           # a closed widget or dead kernel ends the thread
                break
            rest = period - (time.monotonic() - started)
            if rest > 0:
                self._stop.wait(rest)   # at most `fps` frames a second

    def _source_ended(self):
        """A canvas on one given turtlesim node stops following when that node is gone."""
        if self._node is None:
            return False
        from labkit.sims.turtlesim import node
        return self._node not in node.running()

    def _sprite_image(self, look):
        img = self._images.get(look)
        if img is None:
            from ipywidgets import Image as ImageWidget
            img = self._images[look] = ImageWidget(value=sprites.sprite_png(look), format="png")
        return img

    def _draw(self, full=False):
        """Send what changed since the last frame to the browser (one message)."""
        with self._draw_lock:
            try:
                self._draw_frame(full)
            finally:
                # whatever was queued goes out whole, even after an error half-way
                if self._manager._commands_cache:
                    self.messages_sent += 1
                self._manager.flush()

    def _draw_frame(self, full):
        background_layer, trails, turtle_layer = self._layers
        with self.world.lock:
            background, turtles, seq = self.world.snapshot()
            last = self._drawn
            ops = None if (full or last is None) else self.world.ops_since(last[2])
            pixels = self.world.path.pixels.copy() if ops is None else None
        if last is not None and (background, turtles, seq) == last and not full:
            return
        if full or last is None or last[0] != background:
            background_layer.fill_style = "rgb(%d, %d, %d)" % background
            background_layer.fill_rect(0, 0, SIZE, SIZE)
        if ops is None:
            trails.clear()
            trails.put_image_data(pixels, 0, 0)
        elif ops:
            _stroke_ops(trails, ops)
        if full or last is None or last[1] != turtles:
            turtle_layer.clear()
            for _, x, y, orient, look in turtles:
                turtle_layer.save()
                turtle_layer.translate(x, y)
                turtle_layer.rotate(-orient)     # canvas angles turn clockwise (y down)
                turtle_layer.draw_image(self._sprite_image(look), -sprites.SIZE / 2,
                                        -sprites.SIZE / 2)
                turtle_layer.restore()
        self._drawn = (background, turtles, seq)
        self.frames_drawn += 1


def stop_all():
    """labkit.reset(): no canvas goes on following (each keeps its last picture;
    displaying it again starts it again)."""
    for canvas in list(_following):
        canvas.stop()
    _following.clear()


def _install_reset_hook():
    from labkit import process
    if stop_all not in process.reset_hooks:
        process.reset_hooks.append(stop_all)


_install_reset_hook()


def _stroke_ops(layer, ops):
    """Draw logged pen operations; runs of same-width lines go out as one batched command."""
    segments, colors, width = [], [], None

    def flush():
        if segments:
            layer.line_width = width
            layer.stroke_styled_line_segments(np.array(segments, dtype=np.float64),
                                              np.array(colors, dtype=np.uint8))
            segments.clear()
            colors.clear()

    for op in ops:
        if op[0] == "clear":
            flush()
            layer.clear()
            continue
        _, x0, y0, x1, y1, rgb, w = op
        if w != width:
            flush()
            width = w
        segments.append(((x0, y0), (x1, y1)))
        colors.append(rgb)
    flush()
