"""A simulator's window in a terminal: a live page served on 127.0.0.1, opened in the
default browser.

    labkit ros2 run turtlesim turtlesim_node     # a window shows the turtles, live

Real turtlesim opens a Qt window; a terminal here has no GUI toolkit to rely on, but
every machine has a browser. `BrowserWindow(title, render)` serves one page on
127.0.0.1 (an ephemeral port) that shows the picture `render()` returns (a PIL image),
refreshed while it changes -- turtles, pen trails, background colour -- and opens it
with `webbrowser`. `close()` (the node stops) shuts the server down; the page then
says so and stops asking.

Only for programs started from a terminal (`labkit ros2 run`, `labkit exec`, in live
time): a notebook already has the canvas widget, and virtual time (tests, CI, book
builds) shows nothing. Where no window can be opened -- no display (Linux without
DISPLAY/WAYLAND_DISPLAY), CI, or LABKIT_NO_WINDOW=1 -- no browser is started and the
node logs one line (with the page's address, except under LABKIT_NO_WINDOW=1, which
serves nothing).
"""
import io
import json
import os
import sys
import threading


def __getattr__(name):
    # webbrowser is imported when a window opens (a terminal starts ~6 ms sooner)
    if name == "webbrowser":
        import webbrowser
        return webbrowser
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


ENABLED = False          # set by the `labkit` terminal command (labkit/cli/main.py)
_open = []               # windows open in this process

PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>{title}</title>
<style>
 body {{ margin: 0; background: #2b2b2b; color: #ddd; font: 14px sans-serif; }}
 #bar {{ padding: 4px 8px; background: #3c3f41; }}
 #frame {{ display: block; }}
</style></head>
<body><div id="bar">{title}</div><canvas id="frame" width="1" height="1"></canvas>
<script>
const view = document.getElementById('frame'), bar = document.getElementById('bar');
let seen = -1, frames = 0;
window.labkitFrames = () => frames;
function load(n) {{         // the next picture, drawn once complete (never half a frame)
  return new Promise((ok, fail) => {{
    const next = new Image();
    next.onload = () => {{
      view.width = next.naturalWidth; view.height = next.naturalHeight;
      view.getContext('2d').drawImage(next, 0, 0); frames += 1; ok();
    }};
    next.onerror = fail;
    next.src = 'frame.png?n=' + n;
  }});
}}
async function poll() {{
  try {{
    const r = await fetch('state.json', {{cache: 'no-store'}});
    const s = await r.json();
    if (s.closed) throw new Error('closed');
    if (s.version !== seen) {{ seen = s.version; await load(seen); }}
    setTimeout(poll, {period});
  }} catch (e) {{
    bar.textContent = '{title} \u2014 stopped';
    document.title = '{title} (stopped)';
  }}
}}
poll();
</script></body></html>
"""


def headless_reason():
    """Why no window can be opened here, or '' when one can."""
    if os.environ.get("LABKIT_NO_WINDOW", "") not in ("", "0"):
        return "LABKIT_NO_WINDOW=1"
    if os.environ.get("CI", "") not in ("", "0", "false"):
        return "CI"
    if sys.platform.startswith("linux") and not (os.environ.get("DISPLAY") or
                                                 os.environ.get("WAYLAND_DISPLAY")):
        return "no display"
    return ""


class BrowserWindow:
    """A live picture on 127.0.0.1. `render()` returns a PIL image; `state()` returns any
    value that changes when the picture does (a new frame is sent only then)."""

    def __init__(self, title, render, state, fps=20):
        self.title, self._render, self._state, self.fps = title, render, state, fps
        self._lock = threading.Lock()
        self._version, self._last = 0, object()
        self._closed = False
        window = self
        import http.server              # only when a window opens (a terminal's start-up)

        class Handler(http.server.BaseHTTPRequestHandler):
            def log_message(self, *args):      # the terminal belongs to the node
                pass

            def do_GET(self):
                path = self.path.split("?", 1)[0]
                if path == "/":
                    body = PAGE.format(title=window.title,
                                       period=int(1000 / window.fps)).encode("utf-8")
                    self._send(body, "text/html; charset=utf-8")
                elif path == "/state.json":
                    self._send(json.dumps({"version": window.version(),
                                           "closed": window._closed}).encode("utf-8"),
                               "application/json")
                elif path == "/frame.png":
                    self._send(window.png(), "image/png")
                else:
                    self.send_error(404)

            def _send(self, body, kind):
                self.send_response(200)
                self.send_header("Content-Type", kind)
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Cache-Control", "no-store")
                self.end_headers()
                self.wfile.write(body)

        self._server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self._server.daemon_threads = True
        self.url = f"http://127.0.0.1:{self._server.server_address[1]}/"
        self._thread = threading.Thread(target=self._server.serve_forever,
                                        name="labkit-window", daemon=True)
        self._thread.start()
        _open.append(self)

    def version(self):
        """Counts the picture's changes (read by the page to fetch only new frames)."""
        with self._lock:
            now = self._state()
            if now != self._last:
                self._last = now
                self._version += 1
            return self._version

    def png(self):
        buffer = io.BytesIO()
        self._render().save(buffer, format="PNG")
        return buffer.getvalue()

    def open_browser(self):
        try:
            import webbrowser
            return webbrowser.open(self.url, new=1)
        except Exception:       # no browser registered: the address was logged
            return False

    def close(self):
        if self._closed:
            return
        self._closed = True
        self._server.shutdown()
        self._server.server_close()
        self._thread.join(timeout=2.0)
        if self in _open:
            _open.remove(self)


def open_window(title, render, state, log):
    """The window of a simulator node started from a terminal, or None. `log(text)`
    prints the node's one line where no window can be opened."""
    if not ENABLED:
        return None
    from labkit.graph import world
    if world.mode() != "live":
        return None
    why = headless_reason()
    if why == "LABKIT_NO_WINDOW=1":
        log(f"no window ({why})")
        return None
    window = BrowserWindow(title, render, state)
    if why:
        log(f"no window ({why}); the live picture is served at {window.url}")
    elif not window.open_browser():
        log(f"no browser could be started; the live picture is served at {window.url}")
    return window


def close_all():
    for window in list(_open):
        window.close()
