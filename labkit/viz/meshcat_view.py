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


def _label(text, size):
    """The frame's name on a sprite (always faces the camera), like RViz's TF names."""
    texture = {"uuid": _uuid(), "type": "_text", "text": text, "font_size": 48,
               "font_face": "sans-serif"}
    material = {"uuid": _uuid(), "type": "SpriteMaterial", "map": texture["uuid"],
                "transparent": True, "depthTest": False}
    m = np.diag([size, size, size, 1.0])
    m[2, 3] = size * 0.15
    return {"metadata": {"version": 4.5, "type": "Object"}, "geometries": [],
            "materials": [material], "textures": [texture], "images": [],
            "object": {"uuid": _uuid(), "type": "Sprite", "material": material["uuid"],
                       "matrix": [float(v) for v in m.T.flatten()]}}


# ---------------------------------------------------------------- the view
class RobotView:
    """A URDF robot and its TF frames in meshcat.

    `model`: a RobotModel, URDF text, or a .urdf/.xacro path (None: frames only).
    """

    def __init__(self, model=None, *, frames=True, frame_scale=0.15, height=420,
                 fixed_frame=None):
        self.height = height
        self.reach = None         # metres the camera must take in (None: the robot's size)
        self.show_frames = frames
        self.frame_scale = frame_scale
        self.fixed_frame = fixed_frame
        self._objects = {}        # path -> set_object command
        self._transforms = {}     # path -> 4x4
        self._animation = None
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
                    self._objects[path] = self._set_object(path, _object(geometry,
                                                                         _material(rgba), m))
            if self.show_frames:
                for link_name in model.links:
                    self._add_frame(link_name)
        self.set_joint_positions({})

    def _add_frame(self, name):
        path = f"{FRAMES}/{name}"
        if path + "/triad" in self._objects:
            return
        self._objects[path + "/triad"] = self._set_object(path + "/triad",
                                                          _triad(self.frame_scale))
        if not getattr(self, "_no_labels", False):
            self._objects[path + "/label"] = self._set_object(
                path + "/label", _label(name, self.frame_scale * 2.0))

    def hide_labels(self):
        """Frames keep their axes but lose their names (RViz's TF "Show Names" off):
        a small robot's names pile up on each other. Returns the view."""
        with self._lock:
            self._no_labels = True
            gone = [p for p in self._objects if p.startswith(FRAMES) and p.endswith("/label")]
            for p in gone:
                del self._objects[p]
        self._push([{"type": "delete", "path": p} for p in gone])
        return self

    @staticmethod
    def _set_object(path, obj):
        return {"type": "set_object", "path": path, "object": obj}

    def set_frame_poses(self, poses):
        """{frame: 4x4 in the fixed frame}: move links and triads."""
        with self._lock:
            for name, matrix in poses.items():
                if self.model is not None and name in self.model.links:
                    self._transforms[f"{ROBOT}/{name}"] = matrix
                if self.show_frames:
                    self._add_frame(name)
                    self._transforms[f"{FRAMES}/{name}"] = matrix
        self._push([self._set_transform(p, m) for p, m in self._current(poses)])

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
        tracks = {}
        for k, poses in enumerate(frames):
            for path, m in self._current(poses):
                from labkit.robots.urdf import quaternion_from_matrix
                q = quaternion_from_matrix(m[:3, :3])
                entry = tracks.setdefault(path, ([], []))
                entry[0].append({"time": k, "value": [float(v) for v in m[:3, 3]]})
                entry[1].append({"time": k, "value": list(q)})
        self._animation = {"type": "set_animation", "path": "",
                           "options": {"play": True, "repetitions": repetitions},
                           "animations": [{"path": path, "clip": {
                               "fps": fps, "name": "default", "tracks": [
                                   {"name": ".position", "type": "vector3", "keys": pos},
                                   {"name": ".quaternion", "type": "quaternion", "keys": rot}]}}
                               for path, (pos, rot) in tracks.items()]}
        if frames:
            self.set_frame_poses(frames[0])

    # -- what a page replays ---------------------------------------------------------
    def commands(self):
        """Every meshcat command that draws the current scene (lowered dicts)."""
        with self._lock:
            out = [self._camera()] + list(self._objects.values())
            out += [self._set_transform(p, m) for p, m in self._transforms.items()]
            if self._animation is not None:
                out.append(self._animation)
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

    def _camera(self):
        """Put meshcat's camera at a distance that fits the robot (meshcat's is Y-up)."""
        reach = self.reach or 1.0
        if self.model is not None and not self.reach:
            poses = self.model.link_poses({})
            reach = max([float(np.linalg.norm(m[:3, 3])) for m in poses.values()] + [0.4])
        d = 2.2 * reach + 0.5
        return {"type": "set_property", "path": "/Cameras/default/rotated/<object>",
                "property": "position", "value": [d, 0.6 * d, d * 0.8]}


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
