"""The meshcat widget's script in headless Chromium with meshcat's REAL viewer bundle and a
stand-in for the widget model: the bundle loads (even where an AMD `define` exists), the
scene the kernel sends is drawn (a WebGL canvas, every command handled), no error."""
import functools
import http.server
import os
import sys
import threading

import pytest

from labkit.viz import meshcat_view

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "book"))

URDF = """<?xml version="1.0"?>
<robot name="probe">
  <material name="blue"><color rgba="0 0 0.8 1"/></material>
  <link name="base_link">
    <visual><geometry><cylinder length="0.6" radius="0.2"/></geometry>
      <material name="blue"/></visual>
  </link>
  <link name="head"><visual><geometry><sphere radius="0.2"/></geometry></visual></link>
  <link name="box"><visual><geometry><box size="0.1 0.2 0.3"/></geometry></visual></link>
  <joint name="neck" type="continuous">
    <parent link="base_link"/><child link="head"/><origin xyz="0 0 0.3"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="to_box" type="fixed">
    <parent link="head"/><child link="box"/><origin xyz="0.2 0 0"/>
  </joint>
</robot>
"""

HARNESS = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><link rel="icon" href="data:,"></head><body>
<div id="out"></div>
<script>
  window.define = function () {};          // an AMD loader on the page (JupyterLab may have one)
  window.define.amd = true;
  window.__played = 0;
  window.__failed = [];
  Object.defineProperty(window, "MeshCat", {configurable: true,
    get() { return this.__meshcat; },
    set(m) {
      const play = m.Viewer.prototype.handle_command_bytearray;
      m.Viewer.prototype.handle_command_bytearray = function (bytes) {
        try { play.call(this, bytes); window.__played += 1; }
        catch (e) { window.__failed.push(String(e)); }
      };
      this.__meshcat = m;
    }});
</script>
<script type="module">
  import widget from "./widget.mjs";
  const viewer_js = await (await fetch("viewer.b64")).text();
  const scene = new Uint8Array(await (await fetch("scene.bin")).arrayBuffer());
  const handlers = {};
  window.__sent = [];
  const model = {
    get: (k) => ({viewer_js: viewer_js, height: 300})[k],
    on: (ev, fn) => { handlers[ev] = fn; },
    off: (ev) => { delete handlers[ev]; },
    send: (m) => {
      window.__sent.push(m);
      if (m.type === "ready") {
        handlers["msg:custom"]({type: "commands"}, [new DataView(scene.buffer)]);
      }
    },
  };
  await widget.render({model: model, el: document.getElementById("out")});
  window.__done = true;
</script>
</body></html>
"""


@pytest.fixture
def served(tmp_path):
    from labkit.viz import meshcat_widget
    esm = meshcat_widget.MeshcatWidget._esm
    (tmp_path / "widget.mjs").write_text(esm.read_text() if hasattr(esm, "read_text")
                                         else str(esm))
    (tmp_path / "viewer.b64").write_text(meshcat_view._viewer_js_gz())
    view = meshcat_view.RobotView(URDF)
    commands = view.commands()
    (tmp_path / "scene.bin").write_bytes(meshcat_view.commands_blob(commands))
    (tmp_path / "index.html").write_text(HARNESS)

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

        def end_headers(self):
            self.send_header("Cache-Control", "no-store")
            super().end_headers()
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(Quiet, directory=str(tmp_path)))
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}/index.html", len(commands)
    server.shutdown()
    server.server_close()
    thread.join()


def test_real_viewer_bundle_draws_the_scene_the_kernel_sends(served, tmp_path):
    from book_cdp import Browser, find_chromium
    binary = find_chromium()
    if binary is None:
        pytest.skip("chromium is not installed")
    url, count = served
    profile = tmp_path / "profile"
    profile.mkdir()
    browser = Browser(binary, profile)
    try:
        page = browser.page()
        try:
            page.open(url)
            page.wait_for("window.__done === true")
            assert page.evaluate("window.__sent.map(m => m.type).join()") == "ready"
            assert page.evaluate("window.__failed") == []
            assert page.evaluate("window.__played") == count
            assert page.evaluate("document.querySelectorAll('#out canvas').length") >= 1
            assert page.evaluate("document.getElementById('out').style.height") == "300px"
            assert page.errors() == []
        finally:
            page.close()
    finally:
        browser.close()
