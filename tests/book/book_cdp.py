"""A small Chrome DevTools Protocol client for the browser check.

Starts headless Chromium with its debugging port on 127.0.0.1 and drives one
page over a WebSocket (websocket-client). Records what a page did while it
loaded: requests, console errors, exceptions.
"""

from __future__ import annotations

import base64
import json
import shutil
import subprocess
import time
import urllib.request
from pathlib import Path

import websocket

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
    "--window-size=1280,900", "--hide-scrollbars", "--lang=zh-CN",
]


class CDPError(RuntimeError):
    pass


def find_chromium() -> str | None:
    for name in CHROMIUM_NAMES:
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """A headless Chromium process; `page()` connects to its first tab."""

    def __init__(self, binary: str, user_data_dir: Path):
        self.user_data_dir = Path(user_data_dir)
        self.log = open(self.user_data_dir.parent / "chromium.log", "wb")
        self.proc = subprocess.Popen(
            [binary, *CHROMIUM_FLAGS, f"--user-data-dir={self.user_data_dir}", "about:blank"],
            stdout=self.log, stderr=subprocess.STDOUT)
        self.port = self._wait_port()

    def _wait_port(self, timeout: float = 60.0) -> int:
        # Chromium writes the port it picked into DevToolsActivePort.
        active = self.user_data_dir / "DevToolsActivePort"
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise CDPError(f"chromium exited with code {self.proc.returncode}")
            if active.is_file():
                lines = active.read_text().split()
                if lines:
                    return int(lines[0])
            time.sleep(0.05)
        raise CDPError("chromium did not open its debugging port")

    def page(self) -> "Page":
        with urllib.request.urlopen(f"http://127.0.0.1:{self.port}/json/list") as reply:
            targets = json.load(reply)
        pages = [t for t in targets if t.get("type") == "page"]
        if not pages:
            raise CDPError("chromium has no page target")
        return Page(pages[0]["webSocketDebuggerUrl"])

    def close(self) -> None:
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self.log.close()


class Page:
    def __init__(self, ws_url: str):
        # Chromium refuses WebSocket clients that send an Origin it does not know.
        self.ws = websocket.create_connection(ws_url, timeout=60, suppress_origin=True)
        self.next_id = 0
        self.events: list[dict] = []
        for domain in ("Page", "Runtime", "Network", "Log"):
            self.call(f"{domain}.enable")

    # -- protocol -------------------------------------------------------
    def _receive(self, timeout: float) -> dict | None:
        self.ws.settimeout(timeout)
        try:
            msg = json.loads(self.ws.recv())
        except websocket.WebSocketTimeoutException:
            return None
        if "method" in msg:
            self.events.append(msg)
        return msg

    def call(self, method: str, timeout: float = 60.0, **params) -> dict:
        self.next_id += 1
        mid = self.next_id
        self.ws.send(json.dumps({"id": mid, "method": method, "params": params}))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            msg = self._receive(max(0.01, deadline - time.monotonic()))
            if msg is not None and msg.get("id") == mid:
                if "error" in msg:
                    raise CDPError(f"{method}: {msg['error']}")
                return msg.get("result", {})
        raise CDPError(f"{method}: no reply in {timeout} s")

    def evaluate(self, expression: str):
        result = self.call("Runtime.evaluate", expression=expression,
                           returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise CDPError(f"evaluate failed: {result['exceptionDetails']}")
        return result["result"].get("value")

    def wait_for(self, expression: str, timeout: float = 30.0):
        """Poll a JavaScript expression until it is truthy; return its value."""
        deadline = time.monotonic() + timeout
        value = None
        while time.monotonic() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            self._receive(0.1)
        raise CDPError(f"timed out waiting for {expression!r} (last value {value!r})")

    # -- pages ----------------------------------------------------------
    def open(self, url: str, timeout: float = 60.0) -> None:
        """Navigate, wait for the load event, then for the network to go quiet."""
        self.events.clear()
        self.call("Page.navigate", url=url)
        deadline = time.monotonic() + timeout
        while not any(e["method"] == "Page.loadEventFired" for e in self.events):
            if time.monotonic() > deadline:
                raise CDPError(f"{url} did not finish loading")
            self._receive(0.2)
        self.settle(deadline=deadline)

    def settle(self, quiet: float = 0.5, deadline: float | None = None) -> None:
        deadline = deadline or time.monotonic() + 30.0
        last_activity = time.monotonic()
        while time.monotonic() < deadline:
            msg = self._receive(0.1)
            if msg is not None and "method" in msg:
                last_activity = time.monotonic()
            if not self.pending_requests() and time.monotonic() - last_activity >= quiet:
                return

    def pending_requests(self) -> set[str]:
        started, done = set(), set()
        for e in self.events:
            if e["method"] == "Network.requestWillBeSent":
                started.add(e["params"]["requestId"])
            elif e["method"] in ("Network.loadingFinished", "Network.loadingFailed"):
                done.add(e["params"]["requestId"])
        return started - done

    # -- what happened --------------------------------------------------
    def requested_urls(self) -> list[str]:
        return [e["params"]["request"]["url"] for e in self.events
                if e["method"] == "Network.requestWillBeSent"]

    def errors(self) -> list[str]:
        found = []
        for e in self.events:
            p = e["params"]
            if e["method"] == "Runtime.consoleAPICalled" and p["type"] in ("error", "assert"):
                found.append("console: " + " ".join(
                    str(a.get("value", a.get("description", ""))) for a in p["args"]))
            elif e["method"] == "Runtime.exceptionThrown":
                d = p["exceptionDetails"]
                found.append("exception: " + d.get("exception", {}).get(
                    "description", d.get("text", "")))
            elif e["method"] == "Log.entryAdded" and p["entry"]["level"] == "error":
                found.append(f"log: {p['entry']['text']} ({p['entry'].get('url', '')})")
            elif e["method"] == "Network.loadingFailed" and not p.get("canceled"):
                found.append(f"network: {p.get('errorText')} ({p['requestId']})")
        return found

    def screenshot(self, path: Path, width: int = 1280, max_height: int = 6000) -> None:
        """A full-page screenshot: grow the viewport to the page's height
        first (capturing beyond the viewport catches the theme mid-relayout)."""
        metrics = self.call("Page.getLayoutMetrics")
        size = metrics.get("cssContentSize") or metrics["contentSize"]
        height = int(min(max(size["height"], 600), max_height))
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height,
                  deviceScaleFactor=1, mobile=False)
        try:
            # Let the layout and the theme's transitions finish.
            self.evaluate("new Promise(r => requestAnimationFrame(() => setTimeout(r, 400)))")
            shot = self.call("Page.captureScreenshot", format="png")
        finally:
            self.call("Emulation.clearDeviceMetricsOverride")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(base64.b64decode(shot["data"]))

    def close(self) -> None:
        self.ws.close()
