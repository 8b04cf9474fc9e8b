"""The 3D viewer (what RViz shows in the URDF chapter), drawn with meshcat's
three.js viewer: a URDF robot (boxes, cylinders, spheres, DAE/STL/OBJ meshes,
material colours) and TF frames as named axis triads, following /tf live.

Two faces:
- static: `RobotView.iframe()` / `_repr_html_()` is a self-contained
  `<iframe srcdoc=...>` (meshcat's viewer script and the scene, gzip-compressed
  and base64-inlined, unpacked by the browser): no server, works in the HTML
  book. `animate()` adds a meshcat animation (e.g. the driving facer,
  labkit.robots.facer.drive_view()).
- live: `RobotView.follow()` starts a hidden process whose node subscribes
  /tf and /tf_static (and /robot_description) and moves the scene. In JupyterLab
  `show()` displays a widget (labkit/viz/meshcat_widget.py) that gets the scene
  through the kernel's own comm, so it works wherever JupyterLab's server runs;
  the static face goes in the same output. Outside Jupyter, `serve()` starts a
  tiny page server on 127.0.0.1 only (meshcat's own listens on every interface):
  it answers only its own Host and Origin, and its page stops polling when the
  server is gone.

The scene is kept as meshcat commands (msgpack), exactly what meshcat's own
server would replay to a browser.
"""
import base64
import functools
import gzip
import html as _html
import os
import re
import struct
import threading
import weakref

import numpy as np

ROOT = "/meshcat"
ROBOT = ROOT + "/robot"
FRAMES = ROOT + "/frames"


# ---------------------------------------------------------------- assets
@functools.lru_cache(maxsize=1)
def _viewer_js_gz():
    import importlib.util       # find meshcat without importing it (its __init__ pulls zmq)
    package = importlib.util.find_spec("meshcat").submodule_search_locations[0]
    path = os.path.join(package, "viewer", "dist", "main.min.js")
    with open(path, "rb") as handle:
        return base64.b64encode(gzip.compress(handle.read(), 9, mtime=0)).decode("ascii")


def _command_blob(command):
    """One meshcat command as the viewer reads it: a length prefix and its msgpack."""
    import umsgpack
    blob = umsgpack.packb(command, force_float_precision="single")
    return struct.pack("<I", len(blob)) + blob


def commands_blob(commands):
    return b"".join(_command_blob(command) for command in commands)


def _pack(commands):
    return base64.b64encode(gzip.compress(commands_blob(commands), 9, mtime=0)).decode("ascii")


# The page unpacks the viewer and the scene with the browser's DecompressionStream.
_PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>MeshCat</title>
<style>body{{margin:0}}#meshcat-pane{{width:100vw;height:100vh;overflow:hidden}}</style>
</head><body><div id="meshcat-pane"></div>
<script>
(async function () {{
  async function unzip(b64) {{
    var bytes = Uint8Array.from(atob(b64), function (c) {{ return c.charCodeAt(0); }});
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  }}
  (0, eval)(new TextDecoder().decode(await unzip("{js}")));
  var viewer = new MeshCat.Viewer(document.getElementById("meshcat-pane"));
  window.viewer = viewer;
  var cmds = await unzip("{scene}"), view = new DataView(cmds.buffer), i = 0;
  while (i < cmds.length) {{
    var n = view.getUint32(i, true);
    viewer.handle_command_bytearray(cmds.subarray(i + 4, i + 4 + n));
    i += 4 + n;
  }}
  {live}
}})();
</script></body></html>
"""


# ---------------------------------------------------------------- geometry
def _uuid(counter=[0]):
    # deterministic ids, so a notebook's stored snapshot is the same every run
    counter[0] += 1
    return f"labkit-{counter[0]:08d}"


def _material(rgba, kind="MeshPhongMaterial", **extra):
    r, g, b, a = rgba
    color = (int(r * 255) << 16) + (int(g * 255) << 8) + int(b * 255)
    data = {"uuid": _uuid(), "type": kind, "color": color, "reflectivity": 0.5,
            "side": 2, "transparent": a < 1.0, "opacity": float(a)}
    data.update(extra)
    return data


def _object(geometry, material, matrix=None, kind="Mesh", extra_geometries=(),
            extra_materials=(), extra_textures=()):
    matrix = np.eye(4) if matrix is None else matrix
    return {
        "metadata": {"version": 4.5, "type": "Object"},
        "geometries": [geometry, *extra_geometries],
        "materials": [material, *extra_materials],
        "textures": list(extra_textures),
        "images": [],
        "object": {"uuid": _uuid(), "type": kind, "geometry": geometry["uuid"],
                   "material": material["uuid"],
                   "matrix": [float(v) for v in matrix.T.flatten()]},
    }


def _geometry(shape, base_dir=None):
    """(three.js geometry dict, extra 4x4 to apply) for a urdf_parser_py geometry."""
    from urdf_parser_py import urdf as u
    if isinstance(shape, u.Box):
        x, y, z = shape.size
        return {"uuid": _uuid(), "type": "BoxGeometry", "width": x, "height": y,
                "depth": z}, np.eye(4)
    if isinstance(shape, u.Cylinder):
        # three.js cylinders run along Y, URDF's along Z
        turn = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], float)
        return {"uuid": _uuid(), "type": "CylinderGeometry", "radiusTop": shape.radius,
                "radiusBottom": shape.radius, "height": shape.length,
                "radialSegments": 32}, turn
    if isinstance(shape, u.Sphere):
        return {"uuid": _uuid(), "type": "SphereGeometry", "radius": shape.radius,
                "widthSegments": 24, "heightSegments": 16}, np.eye(4)
    if isinstance(shape, u.Mesh):
        return _mesh(shape, base_dir)
    return None, None


_DAE_IMAGES = re.compile(r"<library_images>.*?</library_images>", re.S)


def _mesh(shape, base_dir):
    from labkit.robots import packages
    path = packages.resolve_uri(shape.filename, base_dir)
    fmt = os.path.splitext(path)[1].lower().lstrip(".")
    scale = np.diag(list(shape.scale or (1.0, 1.0, 1.0)) + [1.0])
    try:
        if fmt == "stl":
            import umsgpack
            with open(path, "rb") as handle:
                data = umsgpack.Ext(0x12, handle.read())     # meshcat's uint8 array ext
        elif fmt in ("dae", "obj"):
            with open(path, encoding="utf-8", errors="replace") as handle:
                data = handle.read()
            if fmt == "dae":
                # The static page cannot fetch the texture files a DAE names (they
                # would be 404s on the book's pages): drop them, keep the colours.
                data = _DAE_IMAGES.sub("", data)
        else:
            return None, None
    except OSError:
        return None, None
    return {"uuid": _uuid(), "type": "_meshfile_geometry", "format": fmt,
            "data": data}, scale


def _triad(scale):
    import umsgpack
    points = np.array([[0, 0, 0], [scale, 0, 0], [0, 0, 0], [0, scale, 0],
                       [0, 0, 0], [0, 0, scale]], np.float32)
    colors = np.array([[1, 0, 0], [1, 0, 0], [0, 1, 0], [0, 1, 0],
                       [0, 0, 1], [0, 0, 1]], np.float32)
    ext = 0x17                                                   # float32 array
    geometry = {"uuid": _uuid(), "type": "BufferGeometry", "data": {"attributes": {
        "position": {"itemSize": 3, "type": "Float32Array", "normalized": False,
                     "array": umsgpack.Ext(ext, points.tobytes())},
        "color": {"itemSize": 3, "type": "Float32Array", "normalized": False,
                  "array": umsgpack.Ext(ext, colors.tobytes())}}}}
    material = {"uuid": _uuid(), "type": "LineBasicMaterial", "vertexColors": True,
                "linewidth": 2}
    return _object(geometry, material, kind="LineSegments")


_LABEL_CANVAS, _LABEL_FONT = 256, 48      # meshcat's _text texture: 256 px square, 48 px font


def _label(text, size):
    """The frame's name on a sprite `size` metres square (always faces the camera), like
    RViz's TF names. Ids come from the name: the same scene gives the same page."""
    texture = {"uuid": f"labkit-name-{text}-texture", "type": "_text", "text": text,
               "font_size": _LABEL_FONT, "font_face": "sans-serif"}
    material = {"uuid": f"labkit-name-{text}-material", "type": "SpriteMaterial",
                "map": texture["uuid"], "transparent": True, "depthTest": False}
    m = np.diag([size, size, size, 1.0])
    return {"metadata": {"version": 4.5, "type": "Object"}, "geometries": [],
            "materials": [material], "textures": [texture], "images": [],
            "object": {"uuid": f"labkit-name-{text}", "type": "Sprite",
                       "material": material["uuid"],
                       "matrix": [float(v) for v in m.T.flatten()]}}


def _corners(shape, geometry):
    """The 8 corners of a visual's box in the geometry's own frame (before `extra`), or None."""
    kind = geometry.get("type")
    if kind == "BoxGeometry":
        half = np.array([geometry["width"], geometry["height"], geometry["depth"]]) / 2
    elif kind == "CylinderGeometry":
        r = geometry["radiusTop"]
        half = np.array([r, geometry["height"] / 2, r])
    elif kind == "SphereGeometry":
        half = np.full(3, geometry["radius"])
    elif kind == "_meshfile_geometry":
        points = _mesh_points(geometry["format"], geometry["data"])
        if points is None or not len(points):
            return None
        lo, hi = points.min(0), points.max(0)
        return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                         for z in (lo[2], hi[2])])
    else:
        return None
    return np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * half


_FLOATS = re.compile(r"<float_array[^>]*>([^<]*)<")
_OBJ_VERTEX = re.compile(r"^v\s+(\S+)\s+(\S+)\s+(\S+)", re.M)


def _mesh_points(fmt, data):
    """Vertices of a mesh file (binary STL, COLLADA position arrays, OBJ), for its extent."""
    try:
        if fmt == "stl":
            raw = bytes(data.data)
            count = struct.unpack_from("<I", raw, 80)[0]
            records = np.frombuffer(raw[84:84 + 50 * count], dtype=np.dtype(
                [("v", "<f4", (12,)), ("a", "<u2")]))
            return records["v"][:, 3:].reshape(-1, 3).astype(float)
        if fmt == "dae":
            arrays = [np.array(a.split(), float) for a in _FLOATS.findall(data)]
            arrays = [a.reshape(-1, 3) for a in arrays if len(a) and len(a) % 3 == 0]
            return np.vstack(arrays[:1]) if arrays else None     # the first: positions
        if fmt == "obj":
            return np.array(_OBJ_VERTEX.findall(data), float)
    except (ValueError, struct.error):
        return None
    return None


# ---------------------------------------------------------------- the camera
FOV_DEG = 75.0             # meshcat's camera (vertical field of view)
VIEW_PX = (688, 420)       # the view the camera is framed for: the book's column, 420 px high
FILL = 0.72                # the model's box takes up to this share of the view's half-sizes
ELEVATION_DEG = 32.0       # seen from above, at RViz's kind of angle
AZIMUTH_DEG = -50.0        # from the front right, as the chapter's static pictures
LABEL_PX = 14.0            # a frame name's font size on screen


class Camera:
    """Where the view looks from: framed from the scene's bounding box (`lo`, `hi`, metres,
    Z up), looking at its centre from above, as near as keeps the box's corners (or the
    scene's own `points`, when given: a round path does not reach its box's corners)
    within FILL of the view. `project()` gives view pixels (x right,
    y down) and depth; `unproject()` is its inverse at a depth."""

    def __init__(self, lo, hi, width=VIEW_PX[0], height=VIEW_PX[1], points=None):
        self.width, self.height = width, height
        self.centre = (np.asarray(lo, float) + np.asarray(hi, float)) / 2
        el, az = np.radians(ELEVATION_DEG), np.radians(AZIMUTH_DEG)
        self.back = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
        self.forward = -self.back
        self.right = np.cross(self.forward, [0.0, 0.0, 1.0])
        self.right /= np.linalg.norm(self.right)
        self.up = np.cross(self.right, self.forward)
        self.tan_v = np.tan(np.radians(FOV_DEG) / 2)
        self.tan_h = self.tan_v * width / height
        if points is None:
            points = [[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                      for z in (lo[2], hi[2])]
        q = np.asarray(points, float).reshape(-1, 3) - self.centre
        # the nearest distance at which every point is inside FILL of the view
        shift = q @ self.forward
        need = np.concatenate([np.abs(q @ self.right) / (FILL * self.tan_h) - shift,
                               np.abs(q @ self.up) / (FILL * self.tan_v) - shift, [0.3]])
        self.distance = float(need.max())
        self.position = self.centre + self.distance * self.back

    def project(self, point):
        q = np.asarray(point, float) - self.position
        depth = q @ self.forward
        x = (q @ self.right) / (depth * self.tan_h)
        y = (q @ self.up) / (depth * self.tan_v)
        return (x + 1) / 2 * self.width, (1 - y) / 2 * self.height, depth

    def unproject(self, px, py, depth):
        x, y = 2 * px / self.width - 1, 1 - 2 * py / self.height
        return self.position + depth * (self.forward + x * self.tan_h * self.right
                                        + y * self.tan_v * self.up)

    def metres_per_px(self, depth):
        return 2 * depth * self.tan_v / self.height

    def commands(self):
        """The scene moved so that its centre is meshcat's orbit target (the origin), the
        floor grid with it, and meshcat's camera (Y up under the scene's turn) set back."""
        shift = np.eye(4)
        shift[:3, 3] = -self.centre
        back = self.distance * self.back
        return [RobotView._set_transform(ROOT, shift),
                RobotView._set_transform("/Grid", shift),
                # meshcat's own 0.5 m axes at the origin: RViz has none (the frames have theirs)
                {"type": "set_property", "path": "/Axes", "property": "visible", "value": False},
                {"type": "set_property", "path": "/Cameras/default/rotated/<object>",
                 "property": "position",
                 "value": [float(back[0]), float(back[2]), float(-back[1])]}]


def _text_box(text, font_px):
    """(width, height) in px of a name drawn at `font_px` (sans-serif, as meshcat's _text)."""
    wide = sum(1.0 if ord(ch) > 0x2E80 else (0.62 if ch.isupper() or ch in "mwMW_" else 0.56)
               for ch in text)
    return max(wide * font_px, font_px), 1.25 * font_px


def place_labels(anchors, camera, fonts=None):
    """{name: (x, y, w, h)} screen boxes (px, top-left) for frame names at their anchors
    ({name: (px, py)}), beside the anchor and never on top of each other (nor off the view
    where there is room): tried right-above, left-above, right-below, left-below, then
    further up and down."""
    placed = {}
    gap = 4.0
    for name in sorted(anchors, key=lambda n: (anchors[n][1], anchors[n][0], n)):
        ax, ay = anchors[name]
        w, h = _text_box(name, (fonts or {}).get(name, LABEL_PX))
        tries = []
        for step in range(0, 12):
            for dy in (-(h + gap) - step * (h + 1), gap + step * (h + 1)):
                for x in (ax + gap, ax - gap - w):
                    tries.append((x, ay + dy))
        best = None
        for x, y in tries:
            box = (x, y, w, h)
            inside = 0 <= x and x + w <= camera.width and 0 <= y and y + h <= camera.height
            free = all(not _overlap(box, other) for other in placed.values())
            if free and inside:
                best = box
                break
            if free and best is None:
                best = box
        placed[name] = best
    return placed


def _overlap(a, b, margin=1.0):
    return (a[0] < b[0] + b[2] + margin and b[0] < a[0] + a[2] + margin
            and a[1] < b[1] + b[3] + margin and b[1] < a[1] + a[3] + margin)


# ---------------------------------------------------------------- the view
class RobotView:
    """A URDF robot and its TF frames in meshcat.

    `model`: a RobotModel, URDF text, or a .urdf/.xacro path (None: frames only).
    """

    def __init__(self, model=None, *, frames=True, frame_scale=0.15, height=420,
                 fixed_frame=None):
        self.height = height
        self.reach = None         # metres around the scene's centre the camera must take in (None: its box)
        self.show_frames = frames
        self.frame_scale = frame_scale
        self.fixed_frame = fixed_frame
        self._objects = {}        # path -> set_object command
        self._transforms = {}     # path -> 4x4
        self._animation = None    # (key frames, fps, repetitions)
        self._extents = {}        # link -> corners of its visuals in the link's frame
        self._view_camera = None  # the camera of the scene a page got last (names follow it)
        self._view_empty = False  # that scene had nothing in it (the first frames re-frame it)
        self._label_sent = {}     # frame -> where its name was sent (frame coordinates)
        self._lock = threading.Lock()
        self._listeners = []      # live pages (server queues)
        self.model = None
        self._tf = {}             # child -> (parent, 4x4) from /tf and /tf_static
        self._process = None
        self._server = None
        self._widget = None
        if model is not None:
            self.set_model(model)

    # -- content ---------------------------------------------------------------
    def set_model(self, model):
        """Draw a robot; its links sit where forward kinematics puts them (all joints 0)."""
        from labkit import robots
        if not hasattr(model, "links"):
            model = robots.load(model)
        with self._lock:
            self._objects = {p: o for p, o in self._objects.items() if not p.startswith(ROBOT)}
            self._extents = {}
            self.model = model
            base_dir = os.path.dirname(model.filename) if model.filename else None
            for link_name, link in model.links.items():
                for i, visual in enumerate(link.visuals):
                    geometry, extra = _geometry(visual.geometry, base_dir)
                    if geometry is None:
                        continue
                    origin = visual.origin
                    from labkit.robots.urdf import pose_matrix
                    m = pose_matrix(origin.xyz if origin and origin.xyz else (0, 0, 0),
                                    origin.rpy if origin and origin.rpy else (0, 0, 0)) @ extra
                    rgba = model.material_rgba(visual)
                    if rgba is None:        # RViz draws a link without material white/grey
                        rgba = (0.8, 0.8, 0.8, 1.0)
                    path = f"{ROBOT}/{link_name}/visual_{i}"
                    corners = _corners(visual.geometry, geometry)
                    if corners is not None:
                        self._extents.setdefault(link_name, []).append(
                            (m @ np.c_[corners, np.ones(len(corners))].T).T[:, :3])
                    self._objects[path] = self._set_object(path, _object(geometry,
                                                                         _material(rgba), m))
            if self.show_frames:
                for link_name in model.links:
                    self._add_frame(link_name)
            shown = self._view_camera is not None
        self.set_joint_positions({})
        if shown:        # a live page showed the scene before this model came: redraw it
            self._push([{"type": "delete", "path": ROBOT}] + self.commands())

    def _add_frame(self, name):
        path = f"{FRAMES}/{name}"
        if path + "/triad" in self._objects:
            return
        self._objects[path + "/triad"] = self._set_object(path + "/triad",
                                                          _triad(self.frame_scale))

    def hide_labels(self):
        """Frames keep their axes but lose their names (RViz's TF "Show Names" off):
        a small robot's names pile up on each other. Returns the view."""
        with self._lock:
            self._no_labels = True
            gone = [f"{FRAMES}/{name}/label" for name in self._label_sent]
            self._label_sent = {}
        self._push([{"type": "delete", "path": p} for p in gone])
        return self

    # -- framing and names ---------------------------------------------------------
    def _frame_names(self):
        return [p[len(FRAMES) + 1:-len("/triad")] for p in self._objects
                if p.startswith(FRAMES + "/") and p.endswith("/triad")]

    def _poses_now(self):
        """{frame or link: 4x4} as the scene shows them now."""
        poses = {}
        for path, m in self._transforms.items():
            for prefix in (ROBOT + "/", FRAMES + "/"):
                if path.startswith(prefix):
                    poses[path[len(prefix):]] = m
        return poses

    def bounds(self):
        """(lo, hi): the box (metres, fixed frame) around everything the scene shows, over
        its current poses and every key frame of its animation."""
        return self._extent()[:2]

    def _extent(self):
        """(lo, hi, points): the box and the points it holds (None: the box only)."""
        sets = [self._poses_now()] + list(self._animation[0] if self._animation else [])
        points = []
        frames = set(self._frame_names()) if self.show_frames else set()
        for poses in sets:
            for name, m in poses.items():
                m = np.asarray(m, float)
                for corners in self._extents.get(name, ()):
                    points.append((m[:3, :3] @ corners.T).T + m[:3, 3])
                if name in frames:
                    points.append(m[:3, 3] + np.vstack([np.zeros(3), self.frame_scale
                                                        * m[:3, :3].T]))
        if not points:
            return np.array([-1.0, -1.0, 0.0]), np.array([1.0, 1.0, 0.5]), None
        allp = np.vstack(points)
        lo, hi = allp.min(0), allp.max(0)
        if self.reach:
            centre = (lo + hi) / 2
            lo, hi = np.minimum(lo, centre - self.reach), np.maximum(hi, centre + self.reach)
            return lo, hi, None
        return lo, hi, allp

    def camera(self):
        """The camera a page of this scene starts with (framed from `bounds()`)."""
        lo, hi, points = self._extent()
        return Camera(lo, hi, points=points)

    def _label_size(self, camera):
        return _LABEL_CANVAS / _LABEL_FONT * LABEL_PX * camera.metres_per_px(camera.distance)

    def label_boxes(self, poses=None, camera=None):
        """{frame: (x, y, w, h)} where each frame's name lands in the view (px)."""
        camera = camera or self._view_camera or self.camera()
        poses = self._poses_now() if poses is None else poses
        names = [n for n in self._frame_names() if n in poses]
        anchors, fonts = {}, {}
        for name in names:
            x, y, depth = camera.project(np.asarray(poses[name])[:3, 3])
            if depth <= 0:
                continue
            anchors[name] = (x, y)
            fonts[name] = LABEL_PX * camera.distance / depth
        return place_labels(anchors, camera, fonts)

    def _label_commands(self, poses, camera, create):
        """set_object (when `create`) and set_transform of every name that moved."""
        if not self.show_frames or getattr(self, "_no_labels", False):
            return []
        out = []
        size = self._label_size(camera)
        for name, (x, y, w, h) in self.label_boxes(poses, camera).items():
            pose = np.asarray(poses[name], float)
            _, _, depth = camera.project(pose[:3, 3])
            font = LABEL_PX * camera.distance / depth
            # the text's box sits above the sprite's centre (it is drawn on a baseline there)
            world = camera.unproject(x + w / 2, y + h / 2 + 0.27 * font, depth)
            local = np.linalg.solve(pose, np.append(world, 1.0))[:3]
            path = f"{FRAMES}/{name}/label"
            key = tuple(np.round(local, 5))
            if create or name not in self._label_sent:
                out.append(self._set_object(path, _label(name, size)))
            elif self._label_sent[name] == key:
                continue
            self._label_sent[name] = key
            shift = np.eye(4)
            shift[:3, 3] = local
            out.append(self._set_transform(path, shift))
        return out

    @staticmethod
    def _set_object(path, obj):
        return {"type": "set_object", "path": path, "object": obj}

    def set_frame_poses(self, poses):
        """{frame: 4x4 in the fixed frame}: move links and triads."""
        with self._lock:
            before = set(self._objects)
            for name, matrix in poses.items():
                if self.model is not None and name in self.model.links:
                    self._transforms[f"{ROBOT}/{name}"] = matrix
                if self.show_frames:
                    self._add_frame(name)
                    self._transforms[f"{FRAMES}/{name}"] = matrix
            # a frame first seen after a page got the scene: its axes go to the page too
            commands = [o for p, o in self._objects.items() if p not in before]
            if self._view_camera is None:
                commands = []                      # no page yet: it gets everything at once
            elif self._view_empty and self._transforms:
                # the page was framed on an empty scene: frame it on what came
                self._view_camera, self._view_empty = self.camera(), False
                commands = self._view_camera.commands() + commands
        commands += [self._set_transform(p, m) for p, m in self._current(poses)]
        with self._lock:
            if self._view_camera is not None:
                commands += self._label_commands(self._poses_now(), self._view_camera, False)
        self._push(commands)

    def _current(self, poses):
        for name, matrix in poses.items():
            if self.model is not None and name in self.model.links:
                yield f"{ROBOT}/{name}", matrix
            if self.show_frames:
                yield f"{FRAMES}/{name}", matrix

    def set_joint_positions(self, positions, base=None):
        """Pose the robot by forward kinematics ({joint: position}); `base` places the root."""
        poses = self.model.link_poses(positions)
        if base is not None:
            poses = {k: base @ v for k, v in poses.items()}
        self.set_frame_poses(poses)

    @staticmethod
    def _set_transform(path, matrix):
        return {"type": "set_transform", "path": path,
                "matrix": [float(v) for v in np.asarray(matrix).T.flatten()]}

    def animate(self, frames, fps=10, repetitions=1000):
        """A meshcat animation from a list of {frame: 4x4} (one per key frame)."""
        self._animation = (list(frames), fps, repetitions)
        if frames:
            self.set_frame_poses(frames[0])

    def _animation_command(self, camera):
        from labkit.robots.urdf import quaternion_from_matrix
        frames, fps, repetitions = self._animation
        tracks = {}
        saved = dict(self._label_sent)
        for k, poses in enumerate(frames):
            moves = [(p, m) for p, m in self._current(poses)]
            for command in self._label_commands(poses, camera, True):
                if command["type"] == "set_transform":
                    moves.append((command["path"], np.array(command["matrix"]).reshape(4, 4).T))
            for path, m in moves:
                q = quaternion_from_matrix(m[:3, :3])
                entry = tracks.setdefault(path, ([], []))
                entry[0].append({"time": k, "value": [float(v) for v in m[:3, 3]]})
                entry[1].append({"time": k, "value": list(q)})
        self._label_sent = saved
        return {"type": "set_animation", "path": "",
                "options": {"play": True, "repetitions": repetitions},
                "animations": [{"path": path, "clip": {
                    "fps": fps, "name": "default", "tracks": [
                        {"name": ".position", "type": "vector3", "keys": pos},
                        {"name": ".quaternion", "type": "quaternion", "keys": rot}]}}
                    for path, (pos, rot) in tracks.items()]}

    # -- what a page replays ---------------------------------------------------------
    def commands(self):
        """Every meshcat command that draws the current scene (lowered dicts)."""
        with self._lock:
            camera = self.camera()
            self._view_camera = camera
            self._view_empty = not self._transforms
            self._label_sent = {}
            out = camera.commands() + list(self._objects.values())
            out += [self._set_transform(p, m) for p, m in self._transforms.items()]
            out += self._label_commands(self._poses_now(), camera, True)
            if self._animation is not None:
                out.append(self._animation_command(camera))
        return out

    def html(self, live=False):
        """A self-contained meshcat page of the scene (`live`: it polls the page server
        that served it, see `serve()`)."""
        return _PAGE.format(js=_viewer_js_gz(), scene=_pack(self.commands()),
                            live=_LIVE_JS if live else "")

    def iframe(self, height=None):
        """`<iframe srcdoc=...>`: the static snapshot the notebook stores."""
        height = height or self.height
        return ('<iframe srcdoc="{}" style="width:100%;height:{}px;border:none" '
                'title="meshcat"></iframe>').format(_html.escape(self.html(), quote=True),
                                                    height)

    def _repr_html_(self):
        return self.iframe()

    def widget(self):
        """The live widget of this view (made once); scene changes reach it as they happen."""
        if self._widget is None:
            from labkit.viz.meshcat_widget import MeshcatWidget
            self._widget = MeshcatWidget(self)
            _live.add(self)
        return self._widget

    def show(self, live=None):
        """Display the view. live=None: the live widget (the static snapshot in the same
        output) when labkit runs in live time inside a kernel, else the static snapshot
        alone (what the book stores)."""
        from IPython.display import display
        if live is None:
            import labkit
            from IPython import get_ipython
            shell = get_ipython()
            live = (labkit.time_mode() == "live" and shell is not None
                    and getattr(shell, "kernel", None) is not None)
        if live:
            from labkit.viz import display as _display
            _display.show(self.widget(), html=self.iframe(), text="<meshcat view>")
            return
        # raw HTML: IPython's HTML() warns about every "<iframe" ("Consider using IFrame")
        display({"text/html": self._repr_html_()}, raw=True)

    # -- live: follow /tf ----------------------------------------------------------
    def follow(self, fixed_frame=None):
        """Start a hidden node that follows /tf, /tf_static and /robot_description."""
        from labkit import process
        if fixed_frame:
            self.fixed_frame = fixed_frame
        if self._process is not None:
            return self._process
        view = self

        def main(args=None):
            _follow_main(view, args)
        self._process = process.start(main=main, name="labkit_meshcat_view", echo=False)
        _live.add(self)
        return self._process

    def stop(self):
        """Stop following /tf, close the page server; a live widget keeps its last scene."""
        if self._process is not None:
            self._process.stop()
            self._process = None
        if self._server is not None:
            self._server.close()
            self._server = None
        if self._widget is not None:
            self._widget.detach()
            self._widget = None
        _live.discard(self)

    def on_tf(self, transforms):
        """Take a list of TransformStamped, recompute every frame's pose in the fixed frame."""
        for t in transforms:
            tr, q = t.transform.translation, t.transform.rotation
            from scipy.spatial.transform import Rotation
            m = np.eye(4)
            m[:3, :3] = Rotation.from_quat([q.x, q.y, q.z, q.w]).as_matrix()
            m[:3, 3] = (tr.x, tr.y, tr.z)
            self._tf[t.child_frame_id] = (t.header.frame_id, m)
        self.set_frame_poses(self.tf_poses())

    def tf_poses(self):
        """{frame: 4x4} of every known frame in the fixed frame (default: the tree's root)."""
        poses = {}

        def pose(frame, depth=0):
            if frame in poses:
                return poses[frame]
            entry = self._tf.get(frame)
            if entry is None or depth > 64:
                poses[frame] = np.eye(4)
            else:
                poses[frame] = pose(entry[0], depth + 1) @ entry[1]
            return poses[frame]
        for child in list(self._tf):
            pose(child)
        if self.fixed_frame and self.fixed_frame in poses:
            inv = np.linalg.inv(poses[self.fixed_frame])
            poses = {k: inv @ v for k, v in poses.items()}
        return poses

    # -- live page server --------------------------------------------------------------
    def serve(self, port=0):
        """Serve a live page at http://127.0.0.1:<port>/ (127.0.0.1 only) for a browser
        outside Jupyter; returns the URL. `stop()` or `labkit.reset()` closes it."""
        if self._server is None:
            self._server = _LiveServer(self, port)
            _live.add(self)
        return self._server.url

    def _push(self, commands):
        if not commands:
            return
        if self._server is not None:
            self._server.push(commands)
        if self._widget is not None:
            self._widget.push(commands)


# The served page polls its own server for new commands (no websocket needed). When the
# server is gone (labkit.reset(), the kernel ended) it retries a few times, more and more
# slowly, then stops for good: no console full of refused connections.
_LIVE_JS = """
  var seq = 0, failures = 0;
  async function poll() {
    try {
      var r = await fetch("updates?since=" + seq);
      if (!r.ok) throw new Error(r.status);
      seq = parseInt(r.headers.get("X-Seq") || seq);
      var cmds = new Uint8Array(await r.arrayBuffer()), dv = new DataView(cmds.buffer), j = 0;
      while (j < cmds.length) {
        var m = dv.getUint32(j, true);
        viewer.handle_command_bytearray(cmds.subarray(j + 4, j + 4 + m));
        j += 4 + m;
      }
      failures = 0;
    } catch (e) {
      failures += 1;
      if (failures >= 4) {
        document.title = "MeshCat (stopped)";
        return;
      }
    }
    setTimeout(poll, failures ? 500 * Math.pow(2, failures) : 50);
  }
  poll();
"""


def robot_view(source, positions=None, **kwargs):
    """One call for the book: a RobotView of a model posed at `positions`."""
    view = RobotView(source, **kwargs)
    if positions:
        view.set_joint_positions(positions)
    return view


# ---------------------------------------------------------------- live parts
_views = []
_live = weakref.WeakSet()         # views with live parts (a follower process, a live widget)


def stop_all():
    """labkit.reset(): every view stops following and tells its live pages to stop."""
    for view in list(_live):
        view.stop()
    _views.clear()


def current():
    """The view of the most recent `ros2 run rviz2 rviz2` (None if none ran)."""
    return _views[-1] if _views else None


def rviz_main(args=None):
    """`rviz2` stand-in: a node named rviz2 that keeps a RobotView of /robot_description
    and /tf; `labkit.viz.meshcat_view.current()` returns it for display."""
    view = RobotView()
    _views.append(view)
    _follow_main(view, args, node_name="rviz2")


def _follow_main(view, args=None, node_name="labkit_meshcat_view"):
    """The hidden viewer node: /tf, /tf_static and /robot_description move the scene."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import module
    from labkit.rclpy.executors import ExternalShutdownException
    from labkit.rclpy.qos import DurabilityPolicy, QoSProfile
    rclpy.init(args=args)
    node = rclpy.create_node(node_name)
    TFMessage = module("tf2_msgs.msg").TFMessage
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)

    def on_description(msg):
        try:
            view.set_model(msg.data)
        except ValueError as exc:
            node.get_logger().warn(str(exc))
    node.create_subscription(TFMessage, "/tf", lambda m: view.on_tf(m.transforms),
                             QoSProfile(depth=100))
    node.create_subscription(TFMessage, "/tf_static", lambda m: view.on_tf(m.transforms),
                             QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    node.create_subscription(module("std_msgs.msg").String, "/robot_description",
                             on_description, latched)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


class _LiveServer:
    """A tiny HTTP server on 127.0.0.1 (never another interface): `/` is the page,
    `/updates?since=N` the commands that changed since sequence N.

    Loopback is not enough (any web page the browser shows may send requests to it, and
    a DNS-rebinding name may point at it): it answers only requests whose Host is its own
    address and whose Origin, if any, is its own page; it sends no CORS header, so no
    other page may read its answers. Bad requests get a bare status, and nothing is
    printed into the notebook."""

    def __init__(self, view, port=0):
        import http.server
        self.view = view
        self._seq = 0
        self._latest = {}                 # path -> (seq, packed command)
        self._cond = threading.Condition()
        server = self

        class Handler(http.server.BaseHTTPRequestHandler):
            def log_message(self, *args):     # keep the notebook quiet
                pass

            def do_GET(self):
                status, headers, body = server.answer(self.path, self.headers)
                self.send_response(status)
                for key, value in headers:
                    self.send_header(key, value)
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Cache-Control", "no-store")
                self.end_headers()
                self.wfile.write(body)

        class Server(http.server.ThreadingHTTPServer):
            daemon_threads = True

            def handle_error(self, request, client_address):
                pass                          # a broken connection is not the reader's news

        self.httpd = Server(("127.0.0.1", port), Handler)
        self.port = self.httpd.server_address[1]
        self.url = f"http://127.0.0.1:{self.port}"
        self._thread = threading.Thread(target=self.httpd.serve_forever,
                                        name="labkit-meshcat-server", daemon=True)
        self._thread.start()

    def _allowed(self, headers):
        hosts = {f"127.0.0.1:{self.port}", f"localhost:{self.port}"}
        if headers.get("Host") not in hosts:
            return False
        origin = headers.get("Origin")
        return origin is None or origin in {f"http://{h}" for h in hosts}

    def answer(self, path, headers):
        """(status, headers, body) for a GET of `path`."""
        import urllib.parse
        text = [("Content-Type", "text/plain; charset=utf-8")]
        if not self._allowed(headers):
            return 403, text, b"Forbidden\n"
        url = urllib.parse.urlparse(path)
        if url.path == "/updates":
            since = urllib.parse.parse_qs(url.query).get("since", ["0"])
            if len(since) != 1 or not since[0].isdigit():
                return 400, text, b"Bad Request\n"
            seq, body = self.updates(int(since[0]))
            return 200, [("Content-Type", "application/octet-stream"),
                         ("X-Seq", str(seq))], body
        if url.path in ("/", "/index.html"):
            return 200, [("Content-Type", "text/html; charset=utf-8")], \
                self.view.html(live=True).encode("utf-8")
        return 404, text, b"Not Found\n"

    def push(self, commands):
        with self._cond:
            for command in commands:
                self._seq += 1
                self._latest[command["path"]] = (self._seq, _command_blob(command))

    def updates(self, since):
        with self._cond:
            parts = [blob for seq, blob in sorted(self._latest.values()) if seq > since]
            return self._seq, b"".join(parts)

    def close(self):
        self.httpd.shutdown()
        self.httpd.server_close()
        self._thread.join(timeout=2.0)
