"""Animated replays of turtlesim, so the static book shows motion.

The simulator keeps the last 30 s of visible states (one entry per simulated
step that changed something, stamped with ROS time) and pen keyframes;
`replay()` samples that history at a fixed frame rate and encodes an animated
GIF or WebP with Pillow. In virtual time the history is per simulated frame,
so the same notebook gives the same animation.
"""
import base64
import bisect
import io
from collections import deque

from PIL import Image

from labkit.sims.turtlesim import physics
from labkit.viz.canvas import compose

_MIME = {"gif": "image/gif", "webp": "image/webp"}


class Replay:
    """Encoded animation; displays as an <img> (and image/gif where that is the format)."""

    def __init__(self, data, format, frames, seconds):
        self.data = data
        self.format = format
        self.frames = frames
        self.seconds = seconds

    @property
    def mimetype(self):
        return _MIME[self.format]

    def html(self):
        b64 = base64.b64encode(self.data).decode("ascii")
        return '<img src="data:%s;base64,%s" alt="turtlesim replay" width="%d"/>' % (
            self.mimetype, b64, physics.WINDOW_SIZE)

    def _repr_mimebundle_(self, include=None, exclude=None):
        bundle = {"text/plain": "<turtlesim replay: %d frames, %.1f s, %d bytes %s>"
                  % (self.frames, self.seconds, len(self.data), self.format.upper()),
                  "text/html": self.html()}
        if self.format == "gif":
            bundle["image/gif"] = base64.b64encode(self.data).decode("ascii")
        return bundle

    def save(self, path):
        with open(path, "wb") as f:
            f.write(self.data)


def sample_frames(world, seconds=5.0, fps=15):
    """PIL images of the last `seconds` of `world`, `fps` per second (at least one)."""
    with world.lock:
        history = list(world.history)
        if not history:
            return [compose(*_current(world))]
        end = max(world.now_ns, history[-1][0])
        start = end - int(seconds * 1e9)
        step = int(1e9 / fps)
        times = [h[0] for h in history]
        picks = []
        t = start
        while t <= end:
            i = bisect.bisect_right(times, t) - 1
            picks.append(max(i, 0))
            t += step
        frames = []
        pen = _PenCursor(world, history[picks[0]][1])
        for i in picks:
            _, seq, background, turtles = history[i]
            frames.append(compose(background, turtles, pen.advance(seq)))
    return frames


def _current(world):
    background, turtles, _ = world.snapshot()
    return background, turtles, world.path.pixels.copy()


class _PenCursor:
    """Rebuilds the pen layer forward in time from a keyframe, one logged operation at a time."""

    def __init__(self, world, seq):
        self.world = world
        self.path = physics.PathImage.__new__(physics.PathImage)
        self.path.ops = deque(maxlen=1)
        base_seq, base_pixels = None, None
        for _, k_seq, k_pixels in reversed(world.keyframes):
            if k_seq <= seq:
                base_seq, base_pixels = k_seq, k_pixels
                break
        if base_seq is None:            # older than anything kept: start from the oldest keyframe
            _, base_seq, base_pixels = world.keyframes[0]
        self.path.pixels = base_pixels.copy()
        self.path.seq = base_seq
        self.seq = base_seq

    def advance(self, seq):
        if seq > self.seq:
            for s, op in self.world.path.ops:
                if self.seq < s <= seq:
                    physics.apply_op(self.path, op)
            self.seq = seq
        return self.path.pixels


def encode(frames, fps=15, format="gif", scale=1.0):
    """Encode PIL frames as an animated GIF or WebP (bytes), looping forever."""
    if scale != 1.0:
        size = (max(1, int(frames[0].width * scale)), max(1, int(frames[0].height * scale)))
        frames = [f.resize(size, Image.BILINEAR) for f in frames]
    duration = int(round(1000 / fps))
    buf = io.BytesIO()
    if format == "gif":
        # one shared palette keeps the file small and the colours steady between frames
        palette = frames[-1].quantize(colors=64, method=Image.Quantize.MEDIANCUT)
        paletted = [f.quantize(palette=palette, dither=Image.Dither.NONE) for f in frames]
        paletted[0].save(buf, format="GIF", save_all=True, append_images=paletted[1:],
                         duration=duration, loop=0, optimize=False, disposal=1)
    elif format == "webp":
        frames[0].save(buf, format="WEBP", save_all=True, append_images=frames[1:],
                       duration=duration, loop=0, quality=70, method=4)
    else:
        raise ValueError("format must be 'gif' or 'webp'")
    return buf.getvalue()


def replay(world, seconds=5.0, fps=15, format="gif", scale=1.0):
    """A Replay of the last `seconds` of a TurtleWorld."""
    frames = sample_frames(world, seconds, fps)
    return Replay(encode(frames, fps, format, scale), format, len(frames), seconds)
