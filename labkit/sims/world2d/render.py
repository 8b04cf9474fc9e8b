"""Top-down pictures of the 2D world: obstacles, vehicles, scan rays and hits.

`draw(world, poses_and_ranges)` gives a Pillow image; `picture()` a PNG of the
running simulation, `replay()` an animated GIF of its recent scans.
"""
import io
import math

import numpy as np

BACKGROUND = (204, 204, 204)      # the ground plane's 0.8 grey
GRID = (185, 185, 185)
RAY = (255, 170, 0)
HIT = (220, 0, 0)


class _View:
    def __init__(self, world, pixels):
        self.w, self.h = float(world.ground[0]), float(world.ground[1])
        self.scale = pixels / max(self.w, self.h)
        self.size = (int(round(self.w * self.scale)), int(round(self.h * self.scale)))

    def px(self, x, y):
        """World metres (x right, y up) -> image pixels (y down)."""
        return ((x + self.w / 2) * self.scale, (self.h / 2 - y) * self.scale)


def draw(world, vehicles, pixels=480, rays=True):
    """vehicles: [(VehicleConfig, pose, ranges or None[, pose of the scan])]. A PIL image."""
    from PIL import Image, ImageDraw
    view = _View(world, pixels)
    image = Image.new("RGB", view.size, BACKGROUND)
    pen = ImageDraw.Draw(image)
    for metre in range(-int(view.w // 2), int(view.w // 2) + 1):
        pen.line([view.px(metre, -view.h / 2), view.px(metre, view.h / 2)], fill=GRID)
    for metre in range(-int(view.h // 2), int(view.h // 2) + 1):
        pen.line([view.px(-view.w / 2, metre), view.px(view.w / 2, metre)], fill=GRID)
    for ob in world.obstacles:
        color = tuple(ob.color)
        if ob.type == "cylinder":
            (x0, y0), (x1, y1) = view.px(ob.x - ob.radius, ob.y + ob.radius), \
                view.px(ob.x + ob.radius, ob.y - ob.radius)
            pen.ellipse([x0, y0, x1, y1], fill=color, outline=(60, 60, 60))
        else:
            pen.polygon([view.px(*c) for c in ob.corners()], fill=color, outline=(60, 60, 60))
    for config, pose, ranges, *scan_pose in vehicles:
        if rays and ranges is not None:
            _draw_scan(pen, view, config, scan_pose[0] if scan_pose else pose, ranges)
        _draw_vehicle(pen, view, config, pose)
    return image


def _frame(pose):
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    return lambda px_, py_: (x + c * px_ - s * py_, y + s * px_ + c * py_)


def _draw_scan(pen, view, config, pose, ranges):
    lidar = config.lidar
    origin = _frame(pose)(*lidar.offset)
    ranges = np.asarray(ranges, dtype=float)
    angles = pose[2] + lidar.angles()[: len(ranges)]
    finite = np.isfinite(ranges)
    reach = np.where(finite, ranges, lidar.range_max)
    step = max(1, len(ranges) // 90)         # draw every n-th ray: a fan, not a blot
    o = view.px(*origin)
    for i in range(0, len(ranges), step):
        end = (origin[0] + reach[i] * math.cos(angles[i]),
               origin[1] + reach[i] * math.sin(angles[i]))
        pen.line([o, view.px(*end)], fill=RAY)
    hx = origin[0] + ranges[finite] * np.cos(angles[finite])
    hy = origin[1] + ranges[finite] * np.sin(angles[finite])
    for px_, py_ in zip(hx, hy):
        u, v = view.px(px_, py_)
        pen.ellipse([u - 1.5, v - 1.5, u + 1.5, v + 1.5], fill=HIT)


def _draw_vehicle(pen, view, config, pose):
    world = _frame(pose)
    (lx, ly), (ox, oy) = config.chassis_size, config.chassis_offset
    body = [world(ox + a * lx / 2, oy + b * ly / 2) for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    pen.polygon([view.px(*p) for p in body], fill=tuple(config.color), outline=(0, 0, 160))
    nose = [world(ox + lx / 2, 0.0), world(ox + lx / 2 - 0.5, 0.3), world(ox + lx / 2 - 0.5, -0.3)]
    pen.polygon([view.px(*p) for p in nose], fill=(0, 0, 160))


def _sim(sim):
    if sim is None:
        from .sim import current
        sim = current()
    return sim


def image(sim=None, pixels=480, rays=True):
    """A PIL image of a Simulation now."""
    sim = _sim(sim)
    return draw(sim.world, [(v.config, v.pose, v.ranges, v.scan_pose or v.pose)
                            for v in sim.vehicles], pixels, rays)


def png_bytes(sim=None, pixels=480, rays=True):
    buffer = io.BytesIO()
    image(sim, pixels, rays).save(buffer, format="PNG", optimize=True)
    return buffer.getvalue()


def picture(sim=None, pixels=480, rays=True, path=None):
    """An IPython PNG of the world now (also saved to `path` if given). In live
    JupyterLab it is the live view (`LiveView`): it follows the robot while it drives."""
    if path is None and _live_kernel():
        return LiveView(sim, pixels=pixels, rays=rays)
    data = png_bytes(sim, pixels, rays)
    if path:
        with open(path, "wb") as handle:
            handle.write(data)
    from IPython.display import Image
    return Image(data=data, format="png")


def _live_kernel():
    from labkit.viz.display import live_kernel
    return live_kernel()


class LiveView:
    """The world from above, live: an image widget redrawn (at most `fps` times a
    second, only when something moved) while the simulation runs; its static face is
    the PNG of the moment it was shown. Like the turtlesim window, it costs nothing
    while the robot stands still."""

    def __init__(self, sim=None, pixels=480, rays=True, fps=8):
        import threading
        self.sim = _sim(sim)
        self.pixels, self.rays, self.fps = pixels, rays, fps
        self.frames_drawn = 0
        self._widget = None
        self._stop = threading.Event()
        self._thread = None
        self._drawn = None

    def _state(self):
        return (self.sim.time_ns if not self.sim.paused else None,
                tuple(tuple(v.pose) for v in self.sim.vehicles))

    def snapshot(self):
        return png_bytes(self.sim, self.pixels, self.rays)

    @property
    def widget(self):
        if self._widget is None:
            import ipywidgets as widgets
            self._widget = widgets.Image(value=self.snapshot(), format="png")
            self._drawn = self._state()
            self.frames_drawn = 1
        return self._widget

    def start(self):
        if self._thread is not None and self._thread.is_alive():
            return
        self.widget
        self._stop.clear()
        from labkit.viz.display import viewer_thread
        self._thread = viewer_thread(self._follow, "world2d-view")

    def stop(self):
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        self._thread = None

    def _follow(self):
        from .sim import running
        while not self._stop.wait(1.0 / self.fps):
            if self.sim not in running():
                break                           # the world was stopped: keep the last picture
            state = self._state()
            if state[1] == self._drawn[1]:
                continue                        # nothing moved
            try:
                self._widget.value = self.snapshot()
            except Exception:                   # a closed widget or a gone kernel
                break
            self._drawn = state
            self.frames_drawn += 1

    def _repr_png_(self):
        return self.snapshot()

    def _ipython_display_(self):
        from labkit.viz.display import show
        widget = self.widget
        self.start()
        show(widget, png=self.snapshot(), text="<world2d view>")


def gif_bytes(sim=None, pixels=320, seconds=10.0, fps=10):
    """Animated GIF of the last `seconds` of recorded scans."""
    sim = _sim(sim)
    history = list(sim.history)
    if not history:
        frames = [image(sim, pixels)]
    else:
        t_end = history[-1][0]
        history = [h for h in history if h[0] >= t_end - seconds]
        frames = [draw(sim.world, [(v.config, pose, ranges) for v, (pose, ranges)
                                   in zip(sim.vehicles, states)], pixels)
                  for _, states in history]
    frames = [f.convert("P", palette=1, colors=64) for f in frames]   # ADAPTIVE palette
    buffer = io.BytesIO()
    frames[0].save(buffer, format="GIF", save_all=True, append_images=frames[1:],
                   duration=int(1000 / fps), loop=0, optimize=True)
    return buffer.getvalue()


def replay(sim=None, pixels=320, seconds=10.0, fps=10, path=None):
    data = gif_bytes(sim, pixels, seconds, fps)
    if path:
        with open(path, "wb") as handle:
            handle.write(data)
    from IPython.display import Image
    return Image(data=data, format="gif")


def laser_scan_image(msg, pixels=360, reach=None):
    """A sensor_msgs/LaserScan drawn in its own frame, from above, as RViz's LaserScan
    display shows it with the fixed frame set to the scan's frame_id (x up the page)."""
    from PIL import Image, ImageDraw
    ranges = np.asarray(msg.ranges, dtype=float)
    angles = msg.angle_min + msg.angle_increment * np.arange(len(ranges))
    ok = np.isfinite(ranges) & (ranges >= msg.range_min) & (ranges <= msg.range_max)
    reach = float(reach or msg.range_max or 10.0)
    scale = pixels / (2.0 * reach)
    image = Image.new("RGB", (pixels, pixels), (48, 48, 48))     # RViz's dark background
    pen = ImageDraw.Draw(image)
    centre = pixels / 2.0

    def px(x, y):              # x forward = up, y left = left
        return (centre - y * scale, centre - x * scale)
    for metre in range(-int(reach), int(reach) + 1):
        pen.line([px(metre, -reach), px(metre, reach)], fill=(90, 90, 90))
        pen.line([px(-reach, metre), px(reach, metre)], fill=(90, 90, 90))
    pen.line([px(0, 0), px(1, 0)], fill=(255, 0, 0), width=2)         # the frame's x axis
    pen.line([px(0, 0), px(0, 1)], fill=(0, 255, 0), width=2)         # and y axis
    for x, y in zip(ranges[ok] * np.cos(angles[ok]), ranges[ok] * np.sin(angles[ok])):
        u, v = px(x, y)
        pen.rectangle([u - 1, v - 1, u + 1, v + 1], fill=(255, 255, 255))
    pen.text((6, 6), f"Fixed Frame: {msg.header.frame_id}", fill=(220, 220, 220))
    return image


def laser_scan_picture(msg, pixels=360, reach=None, path=None):
    """IPython PNG of laser_scan_image (also saved to `path` if given)."""
    buffer = io.BytesIO()
    laser_scan_image(msg, pixels, reach).save(buffer, format="PNG", optimize=True)
    if path:
        with open(path, "wb") as handle:
            handle.write(buffer.getvalue())
    from IPython.display import Image
    return Image(data=buffer.getvalue(), format="png")
