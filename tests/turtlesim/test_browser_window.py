"""`labkit ros2 run turtlesim turtlesim_node` in a terminal opens a window like the real
node's: a live page on 127.0.0.1. Driven here in real headless Chromium while a second
terminal publishes cmd_vel over DDS (loopback), as connect_real_ros teaches."""
import os
import random
import re
import signal
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book"))
from book_cdp import Browser, find_chromium  # noqa: E402

from labkit.viz import window  # noqa: E402

# the bounding box and count of pixels that are not the background (69, 86, 255)
DRAWN = """(() => {
  const c = document.getElementById('frame');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let n = 0, x0 = 1e9, y0 = 1e9, x1 = -1, y1 = -1;
  for (let i = 0; i < d.length; i += 4) {
    if (Math.abs(d[i] - 69) + Math.abs(d[i+1] - 86) + Math.abs(d[i+2] - 255) > 30) {
      const p = i / 4, x = p % c.width, y = (p - x) / c.width;
      n++; x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
    }
  }
  return [n, x0, y0, x1, y1, c.width];
})()"""


def _labkit(*args, env):
    return subprocess.Popen([sys.executable, "-m", "labkit", *args], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            encoding="utf-8")


def _stop(proc):
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    return proc.stdout.read() if proc.stdout else ""


@pytest.mark.skipif(find_chromium() is None, reason="no chromium (CI installs Debian's)")
@pytest.mark.skipif(sys.platform != "linux", reason="SIGINT to a child is POSIX")
def test_turtle_moves_in_the_browser_window(tmp_path):
    env = dict(os.environ, LABKIT_TIME="live", CI="1", LABKIT_DDS="on",
               ROS_DOMAIN_ID=str(random.Random(os.getpid()).randrange(150, 230)))
    env.pop("LABKIT_NO_WINDOW", None)
    sim = _labkit("ros2", "run", "turtlesim", "turtlesim_node", env=env)
    pub = browser = None
    try:
        lines = []
        deadline = time.monotonic() + 60
        url = None
        while url is None:
            line = sim.stdout.readline()
            assert line and time.monotonic() < deadline, "".join(lines)
            lines.append(line)
            found = re.search(r"\[turtlesim\]: no window \(CI\); the live picture is served "
                              r"at (http://127\.0\.0\.1:\d+/)$", line.rstrip())
            url = found and found.group(1)
        browser = Browser(find_chromium(), tmp_path / "chromium")
        page = browser.page()
        page.call("Page.enable")
        page.call("Runtime.enable")
        page.call("Page.navigate", url=url)
        page.wait_for("window.labkitFrames && window.labkitFrames() > 0")
        assert page.evaluate("document.title") == "TurtleSim"
        n0, *box0, width = page.evaluate(DRAWN)
        assert width == 500 and 200 < n0 < 3000          # one turtle, no trail yet
        pub = _labkit("ros2", "topic", "pub", "-r", "10", "/turtle1/cmd_vel",
                      "geometry_msgs/msg/Twist", "{linear: {x: 2.0}, angular: {z: 1.0}}", env=env)
        # the page follows: the turtle leaves the centre and its white trail grows
        deadline = time.monotonic() + 60
        while True:
            n, *box, _ = page.evaluate(DRAWN)
            if n > n0 + 400 and box != box0:
                break
            assert time.monotonic() < deadline, (n0, box0, n, box)
            time.sleep(0.5)
        frames = page.evaluate("window.labkitFrames()")
        assert frames >= 3
        _stop(pub)
        pub = None
        _stop(sim)
        # the node stopped: the window says so, and nothing listens any more
        page.wait_for("document.title === 'TurtleSim (stopped)'", timeout=20)
        with pytest.raises(OSError):
            urllib.request.urlopen(url + "state.json", timeout=3)
    finally:
        if browser is not None:
            browser.close()
        if pub is not None:
            _stop(pub)
        _stop(sim)


class _Log(list):
    def __call__(self, text):
        self.append(text)


def _fake_render():
    from PIL import Image
    return Image.new("RGB", (4, 4), (69, 86, 255))


def test_no_window_outside_a_terminal_or_in_virtual_time(monkeypatch):
    log = _Log()
    monkeypatch.setattr(window, "ENABLED", False)
    assert window.open_window("TurtleSim", _fake_render, lambda: 0, log) is None
    monkeypatch.setattr(window, "ENABLED", True)
    from labkit.graph import world
    monkeypatch.setattr(world, "mode", lambda: "virtual")
    assert window.open_window("TurtleSim", _fake_render, lambda: 0, log) is None
    assert log == []


def test_headless_one_line_and_no_browser(monkeypatch):
    from labkit.graph import world
    monkeypatch.setattr(window, "ENABLED", True)
    monkeypatch.setattr(world, "mode", lambda: "live")
    opened = []
    monkeypatch.setattr(window.webbrowser, "open", lambda *a, **k: opened.append(a) or True)
    monkeypatch.setenv("LABKIT_NO_WINDOW", "1")
    log = _Log()
    assert window.open_window("TurtleSim", _fake_render, lambda: 0, log) is None
    assert log == ["no window (LABKIT_NO_WINDOW=1)"]
    monkeypatch.delenv("LABKIT_NO_WINDOW")
    monkeypatch.delenv("CI", raising=False)
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    monkeypatch.setattr(window.sys, "platform", "linux")
    log = _Log()
    w = window.open_window("TurtleSim", _fake_render, lambda: 0, log)
    try:
        assert log == [f"no window (no display); the live picture is served at {w.url}"]
        assert w.url.startswith("http://127.0.0.1:") and opened == []
        with urllib.request.urlopen(w.url + "frame.png", timeout=5) as reply:
            assert reply.read()[:8] == b"\x89PNG\r\n\x1a\n"
    finally:
        w.close()
    monkeypatch.setenv("DISPLAY", ":0")
    log = _Log()
    w = window.open_window("TurtleSim", _fake_render, lambda: 0, log)
    try:
        assert log == [] and opened == [(w.url,)]
    finally:
        w.close()
    assert window._open == []


def test_gazebo_2d_world_window_follows_the_robot(monkeypatch):
    """The 2D world of the Gazebo chapter, started from a terminal, gets the same window:
    its picture changes when the robot moves."""
    from labkit.graph import world
    from labkit.sims.world2d import gz_cli
    from labkit.sims.world2d import world as world2d
    from labkit.sims.world2d.sim import Simulation
    monkeypatch.setattr(window, "ENABLED", True)
    monkeypatch.setattr(world, "mode", lambda: "live")
    monkeypatch.setenv("CI", "1")
    monkeypatch.delenv("LABKIT_NO_WINDOW", raising=False)
    sim = Simulation(world2d.load(), running=False)
    printed = []
    monkeypatch.setattr("builtins.print", lambda *a, **k: printed.append(" ".join(map(str, a))))
    w = gz_cli._terminal_window(sim)
    monkeypatch.undo()
    try:
        assert printed == [f"[Msg] no window (CI); the live picture is served at {w.url}"]
        with urllib.request.urlopen(w.url + "frame.png", timeout=5) as reply:
            before = reply.read()
        v0 = w.version()
        vehicle = sim.vehicles[0]
        vehicle.x += 1.0
        assert w.version() == v0 + 1 and w.version() == v0 + 1
        with urllib.request.urlopen(w.url + "frame.png", timeout=5) as reply:
            assert reply.read() != before
    finally:
        w.close()
        sim.close()
