"""The 3D viewer's live parts (issues 11 §4 and 13): in JupyterLab a widget that gets the
scene through the kernel's comm (no side port); the page server for browsers outside
Jupyter answers only its own Host/Origin, refuses bad requests with a bare 400 and
nothing printed, and `labkit.reset()` closes it (port and thread)."""
import http.client
import os
import shutil
import struct
import subprocess
import threading

import pytest
import umsgpack

import labkit
from labkit import plugins, robots
from labkit.viz import meshcat_view

plugins.register_all()          # the robots room's bundled packages (urdf_tutorial)

SHARE = robots.share_directory("facer_description")
URDF = os.path.join(SHARE, "urdf", "01-one-shape.urdf")


@pytest.fixture(autouse=True)
def _clean():
    labkit.reset()
    yield
    labkit.reset()


def _get(port, path, headers=None):
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=5)
    try:
        conn.request("GET", path, headers=headers or {})
        reply = conn.getresponse()
        return reply.status, dict(reply.getheaders()), reply.read()
    finally:
        conn.close()


def _listening(port):
    if shutil.which("ss") is None:
        pytest.skip("ss is not installed: the socket table cannot be read")
    table = subprocess.run(["ss", "-Hltn"], capture_output=True, text=True).stdout
    return any(line.split()[3].endswith(f":{port}") for line in table.splitlines())


def _decode(blob):
    out, i = [], 0
    while i < len(blob):
        (n,) = struct.unpack_from("<I", blob, i)
        out.append(umsgpack.unpackb(blob[i + 4:i + 4 + n]))
        i += 4 + n
    return out


def test_page_server_checks_host_and_origin_and_sends_no_cors(capfd):
    view = meshcat_view.RobotView(URDF)
    port = int(view.serve().rsplit(":", 1)[1])
    status, headers, body = _get(port, "/updates?since=0")
    assert status == 200 and int(headers["X-Seq"]) >= 0
    assert "Access-Control-Allow-Origin" not in headers
    assert _get(port, "/", {"Host": f"localhost:{port}"})[0] == 200
    assert b"MeshCat.Viewer" in _get(port, "/")[2]
    # another name for this address (DNS rebinding), another page's fetch: refused
    assert _get(port, "/updates?since=0", {"Host": f"attacker.example:{port}"})[0] == 403
    assert _get(port, "/updates?since=0", {"Origin": "http://attacker.example"})[0] == 403
    assert _get(port, "/", {"Origin": "null"})[0] == 403
    assert _get(port, "/updates?since=0", {"Origin": f"http://127.0.0.1:{port}"})[0] == 200
    # bad requests: a bare 400 / 404, and nothing in the notebook
    for bad in ("/updates?since=abc", "/updates?since=-1", "/updates?since=1&since=2"):
        status, _, body = _get(port, bad)
        assert (status, body) == (400, b"Bad Request\n")
    assert _get(port, "/nothing")[0] == 404
    out, err = capfd.readouterr()
    assert out == "" and err == ""


def test_served_page_polls_its_own_server_and_gives_up_politely():
    view = meshcat_view.RobotView(URDF)
    view.serve()
    page = view.html(live=True)
    assert 'fetch("updates?since=" + seq)' in page       # same origin: no CORS needed
    assert "failures >= 4" in page                       # stops when the server is gone
    assert "updates?since" not in view.html()             # the stored snapshot never polls


def test_labkit_reset_closes_the_page_server():
    view = meshcat_view.RobotView(URDF)
    port = int(view.serve().rsplit(":", 1)[1])
    assert _listening(port)
    labkit.reset()
    assert not _listening(port)
    assert not [t for t in threading.enumerate() if t.name == "labkit-meshcat-server"]


def test_live_view_is_a_widget_fed_through_the_comm(monkeypatch):
    from labkit.viz import display as display_module
    from labkit.viz.meshcat_widget import MeshcatWidget
    shown = []
    monkeypatch.setattr(display_module, "display", lambda data, raw: shown.append(data))
    view = meshcat_view.RobotView(URDF)
    view.show(live=True)
    (bundle,) = shown
    widget = view.widget()
    assert isinstance(widget, MeshcatWidget)
    assert bundle["application/vnd.jupyter.widget-view+json"]["model_id"] == widget.model_id
    assert bundle["text/html"].startswith("<iframe srcdoc=")     # the static face, same output
    assert not [t for t in threading.enumerate() if t.name == "labkit-meshcat-server"]
    sent = []
    monkeypatch.setattr(widget, "send", lambda content, buffers=None: sent.append(
        (content, buffers)))
    # a page draws the widget: it asks, and gets the whole scene
    widget._on_front_end_message(widget, {"type": "ready"}, [])
    (content, (blob,)), = sent
    assert content == {"type": "commands"}
    paths = [c["path"] for c in _decode(blob)]
    assert "/meshcat/robot/base_link/visual_0" in paths
    # scene changes reach it as they happen
    sent.clear()
    import numpy as np
    view.set_frame_poses({"base_link": np.eye(4)})
    assert [c["type"] for c in _decode(sent[0][1][0])] == ["set_transform"] * 2
    # after labkit.reset() it follows nothing, and a redrawn page still gets the last scene
    labkit.reset()
    sent.clear()
    view.set_frame_poses({"base_link": np.eye(4)})
    assert sent == []
    widget._on_front_end_message(widget, {"type": "ready"}, [])
    assert "/meshcat/robot/base_link/visual_0" in [c["path"] for c in _decode(sent[0][1][0])]


def test_widget_script_is_a_module_that_never_polls():
    from labkit.viz import meshcat_widget
    script = meshcat_widget.MeshcatWidget._esm
    text = script.read_text() if hasattr(script, "read_text") else str(script)
    assert "export default" in text and "fetch(" not in text and "setTimeout" not in text
    node = shutil.which("node")
    if node is not None:          # a syntax error would only show in the browser
        done = subprocess.run([node, "--input-type=module", "--check"], input=text,
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr


def test_labkit_reset_leaves_no_thread_and_rclpy_shutdown_after_it_is_fine():
    before = set(threading.enumerate())
    labkit.ros2('run turtlesim turtlesim_node')
    labkit.ros2('topic echo /turtle1/pose')
    labkit.ros2('run rviz2 rviz2')
    view = meshcat_view.RobotView(URDF)
    view.follow()
    view.serve()
    view.widget()
    import labkit.rclpy as rclpy
    rclpy.init(args=[])
    rclpy.create_node('notebook_node')
    labkit.sleep(0.5)
    assert len(set(threading.enumerate()) - before) >= 5
    labkit.reset()
    assert [t.name for t in set(threading.enumerate()) - before] == []
    rclpy.shutdown()               # the notebook's last cell after a reset: no error


NODE_HARNESS = r'''
import widget from "WIDGET";
globalThis.window = globalThis;
const handlers = {}, sent = [];
const model = {
  get: (k) => ({viewer_js: process.env.VIEWER_JS, height: 300})[k],
  on: (ev, fn) => { handlers[ev] = fn; },
  off: (ev) => { delete handlers[ev]; },
  send: (m) => sent.push(m),
};
const el = {style: {}};
const cleanup = await widget.render({model, el});
const bytes = Buffer.from(process.env.BLOB, "base64");
handlers["msg:custom"]({type: "commands"},
                       [new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength)]);
cleanup();
console.log(JSON.stringify({sent, height: el.style.height, played: window.PLAYED,
                            handlers: Object.keys(handlers)}));
'''

FAKE_VIEWER = '''
(function (root) {
  if (typeof define === "function" && define.amd) { define([], function () {}); return; }
  root.PLAYED = [];
  root.MeshCat = {Viewer: function (el) {
    this.handle_command_bytearray = function (b) { root.PLAYED.push(b.length); };
  }};
})(this);
'''


def test_widget_script_plays_what_the_kernel_sends(tmp_path):
    """The widget's JS in node, with a stand-in for meshcat's viewer bundle: it loads the
    UMD bundle even where an AMD `define` exists, asks for the scene, plays every
    length-prefixed command of a buffer, and lets go of the comm when the view goes."""
    import base64
    import gzip
    import json
    node = shutil.which("node")
    if node is None:
        pytest.skip("node is not installed")
    from labkit.viz import meshcat_widget
    script = tmp_path / "widget.mjs"
    script.write_text(meshcat_widget.MeshcatWidget._esm.read_text()
                      if hasattr(meshcat_widget.MeshcatWidget._esm, "read_text")
                      else str(meshcat_widget.MeshcatWidget._esm))
    harness = tmp_path / "harness.mjs"
    harness.write_text("globalThis.define = function () {}; globalThis.define.amd = true;\n"
                       + NODE_HARNESS.replace("WIDGET", script.as_uri()))
    commands = [{"type": "set_transform", "path": "/a", "matrix": [1.0] * 16},
                {"type": "delete", "path": "/b"}]
    blob = meshcat_view.commands_blob(commands)
    viewer = base64.b64encode(gzip.compress(FAKE_VIEWER.encode())).decode()
    env = dict(os.environ, VIEWER_JS=viewer, BLOB=base64.b64encode(blob).decode())
    done = subprocess.run([node, str(harness)], capture_output=True, text=True, env=env,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["sent"] == [{"type": "ready"}]
    assert result["height"] == "300px"
    sizes = [len(meshcat_view._command_blob(c)) - 4 for c in commands]
    assert result["played"] == sizes
    assert result["handlers"] == []
