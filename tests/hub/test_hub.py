"""The book on a real JupyterHub (loopback only): three learners log in through the
hub's REST API, start their servers (local processes), and run ch03 at the same time
through the Jupyter server API (a kernel and its websocket, as JupyterLab does). Each
learner's exercises report what that learner did; nothing of one learner (files, the
ROS graph, jobs, the ROS domain) reaches another; the idle culler stops an idle server.
"""
import asyncio
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import uuid
from pathlib import Path

import pytest

from tests.hub._learners import REPO, load, solved, write

CHP = REPO / "node_modules" / ".bin" / "configurable-http-proxy"
pytestmark = [
    pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the hub test runs on Linux"),
    pytest.mark.skipif(shutil.which("node") is None or not CHP.exists(),
                       reason="configurable-http-proxy missing: run `npm ci` (package.json)"),
]
PASSWORDS = {"alice": "a-pw-1", "bob": "b-pw-2", "carol": "c-pw-3"}


def _port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Hub:
    def __init__(self, tmp_path, idle_timeout=15):
        self.dir = tmp_path
        self.port = _port()
        self.base = f"http://127.0.0.1:{self.port}"
        self.hub_port = _port()
        env = dict(os.environ, HUBTEST_DIR=str(tmp_path), HUBTEST_PORT=str(self.port),
                   HUBTEST_HUB_PORT=str(self.hub_port), HUBTEST_PROXY_API_PORT=str(_port()),
                   HUBTEST_CHP=str(CHP), HUBTEST_PASSWORDS=json.dumps(PASSWORDS),
                   PYTHONPATH=str(REPO), HUBTEST_IDLE_TIMEOUT=str(idle_timeout))
        env.pop("LABKIT_EXERCISE_LOG", None)
        self.log = open(tmp_path / "hub.log", "w", encoding="utf-8")
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "jupyterhub", "-f", str(Path(__file__).with_name("hub_config.py"))],
            cwd=tmp_path, env=env, stdout=self.log, stderr=subprocess.STDOUT,
            start_new_session=True)

    def request(self, method, path, token=None, body=None, timeout=30):
        import urllib.error
        import urllib.request
        req = urllib.request.Request(self.base + path, method=method,
                                     data=None if body is None else json.dumps(body).encode())
        if token:
            req.add_header("Authorization", f"token {token}")
        try:
            with urllib.request.urlopen(req, timeout=timeout) as resp:
                text = resp.read().decode("utf-8")
                return resp.status, (json.loads(text) if text.strip() else None)
        except urllib.error.HTTPError as e:
            return e.code, None

    def wait_up(self, timeout=60):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            assert self.proc.poll() is None, self.logtext()
            try:
                if self.request("GET", "/hub/api/")[0] == 200:
                    return
            except OSError:
                pass
            time.sleep(0.3)
        pytest.fail("hub did not start\n" + self.logtext())

    def logtext(self):
        self.log.flush()
        return (self.dir / "hub.log").read_text(encoding="utf-8")[-4000:]

    def stop(self):
        """SIGTERM to the hub: it stops the learners' servers, its services and the proxy
        itself; whatever of this hub is still running after that is ended here."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(60)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()
        self.log.close()
        import psutil
        api = f"127.0.0.1:{self.hub_port}/"
        left = []
        for p in psutil.process_iter(["environ"]):
            env = p.info["environ"] or {}
            if env.get("HUBTEST_DIR") == str(self.dir) or api in env.get("JUPYTERHUB_API_URL", ""):
                left.append(p)
        for p in left:
            try:
                p.terminate()
            except psutil.Error:
                pass
        psutil.wait_procs(left, timeout=10)


def _message(session, code):
    msg_id = uuid.uuid4().hex
    return msg_id, {
        "header": {"msg_id": msg_id, "msg_type": "execute_request", "session": session,
                   "username": "", "version": "5.3", "date": ""},
        "parent_header": {}, "metadata": {}, "channel": "shell", "buffers": [],
        "content": {"code": code, "silent": False, "store_history": True,
                    "user_expressions": {}, "allow_stdin": False, "stop_on_error": False}}


class Kernel:
    """A notebook's kernel driven over its websocket, as JupyterLab does."""

    def __init__(self, hub, user, token, path):
        self.hub, self.user, self.token, self.path = hub, user, token, path

    async def start(self):
        from tornado.httpclient import AsyncHTTPClient, HTTPRequest
        from tornado.websocket import websocket_connect
        client = AsyncHTTPClient()
        resp = await client.fetch(HTTPRequest(
            f"{self.hub.base}/user/{self.user}/api/sessions", method="POST",
            headers={"Authorization": f"token {self.token}"}, request_timeout=120,
            body=json.dumps({"path": self.path, "type": "notebook", "name": "",
                             "kernel": {"name": "python3"}})))
        self.kernel_id = json.loads(resp.body)["kernel"]["id"]
        self.session = uuid.uuid4().hex
        ws = f"ws://127.0.0.1:{self.hub.port}/user/{self.user}/api/kernels/" \
             f"{self.kernel_id}/channels?session_id={self.session}"
        self.ws = await websocket_connect(HTTPRequest(
            ws, headers={"Authorization": f"token {self.token}"}, request_timeout=60))

    async def run(self, code, timeout=120):
        """The cell's text output (streams, results, errors) once the kernel is idle."""
        msg_id, msg = _message(self.session, code)
        await self.ws.write_message(json.dumps(msg))
        out, idle, replied = [], False, False
        end = time.monotonic() + timeout
        while not (idle and replied):
            raw = await asyncio.wait_for(self.ws.read_message(), max(0.1, end - time.monotonic()))
            assert raw is not None, "kernel websocket closed"
            m = _decode(raw)
            if m.get("parent_header", {}).get("msg_id") != msg_id:
                continue
            kind, content = m["msg_type"], m["content"]
            if kind == "stream":
                out.append(content["text"])
            elif kind in ("execute_result", "display_data"):
                out.append(content["data"].get("text/plain", "") + "\n")
            elif kind == "error":
                out.append(f"{content['ename']}: {content['evalue']}\n")
            elif kind == "status" and content["execution_state"] == "idle":
                idle = True
            elif kind == "execute_reply":
                replied = True
        return "".join(out)


def _decode(raw):
    """A websocket frame: JSON text, or (a message with binary buffers, e.g. a widget's)
    the server's binary framing: buffer count, offsets, the JSON message first."""
    if isinstance(raw, str):
        return json.loads(raw)
    count = int.from_bytes(raw[:4], "big")
    offsets = [int.from_bytes(raw[4 + 4 * i:8 + 4 * i], "big") for i in range(count)]
    end = offsets[1] if count > 1 else len(raw)
    return json.loads(raw[offsets[0]:end].decode("utf-8"))


def _code_cells(nb):
    for cell in nb["cells"]:
        if cell["cell_type"] == "code" and "solution" not in cell["metadata"].get("tags", []):
            yield "".join(cell["source"])


async def _learner(hub, user, token, nb):
    kernel = Kernel(hub, user, token, "ch03_topics.ipynb")
    await kernel.start()
    outputs = [await kernel.run(code) for code in _code_cells(nb)]
    probe = await kernel.run(
        "import os, labkit, rclpy\n"
        "if not rclpy.ok():\n    rclpy.init()\n"
        f"open('mine_{user}.txt', 'w', encoding='utf-8').write('{user}')\n"
        f"_probe = rclpy.create_node('only_{user}')\n"
        "_jobs = %ros2 topic pub --rate 1 /chatter_" + user + " std_msgs/msg/String \"{data: hi}\"\n"
        "labkit.sleep(1.0)\n"
        "print('DOMAIN', os.environ['ROS_DOMAIN_ID'])\n"
        "print('NODES', *sorted(labkit.ros2('node list').stdout.split()))\n"
        "print('JOBS', labkit.ros2('jobs').stdout.replace(chr(10), ' | '))\n"
        "print('FILES', *sorted(n for n in os.listdir('.') if n.startswith('mine_')))\n"
        "print(next(l for l in labkit.ros2('doctor --report').stdout.splitlines() if 'domain id' in l))\n")
    kernel.ws.close()
    return outputs, probe


def _reports(outputs):
    """{练习 3.x: whole report text} of the last report of each exercise."""
    found = {}
    for text in outputs:
        if "【练习" in text:
            title = text[text.index("【") + 1:text.index("】")]
            found[title] = text[text.index("【"):]
    return found


def test_three_learners_on_a_hub(tmp_path):
    homes = tmp_path / "home"
    notebooks = {"alice": load(), "bob": solved(load()), "carol": solved(load())}
    for user, nb in notebooks.items():
        write(nb, homes / user / "ch03_topics.ipynb")
    hub = Hub(tmp_path)
    try:
        hub.wait_up()
        # log in through the REST API: a learner's password gives that learner's token only
        assert hub.request("POST", "/hub/api/users/alice/tokens",
                           body={"auth": {"username": "alice", "password": "wrong"}})[0] == 403
        assert hub.request("POST", "/hub/api/users/bob/tokens",
                           body={"auth": {"username": "alice", "password": "a-pw-1"}})[0] == 403
        tokens = {}
        for user, pw in PASSWORDS.items():
            status, body = hub.request("POST", f"/hub/api/users/{user}/tokens",
                                       body={"auth": {"username": user, "password": pw}})
            assert status == 201, (status, hub.logtext())
            tokens[user] = body["token"]
        for user in PASSWORDS:
            assert hub.request("POST", f"/hub/api/users/{user}/server", tokens[user])[0] in (201, 202)
        end = time.monotonic() + 150
        while time.monotonic() < end:     # each server answers through the proxy
            if all(hub.request("GET", f"/user/{u}/api/status", tokens[u])[0] == 200
                   for u in PASSWORDS):
                break
            time.sleep(0.5)
        else:
            pytest.fail("servers not ready\n" + hub.logtext())

        async def everyone():
            return await asyncio.gather(*(_learner(hub, u, tokens[u], notebooks[u])
                                          for u in PASSWORDS))
        results = dict(zip(PASSWORDS, asyncio.run(everyone())))

        # exercises: as shipped, all three fail; solved, all three pass
        for user, (outputs, _) in results.items():
            reports = _reports(outputs)
            assert sorted(reports) == ["练习 3.1", "练习 3.2", "练习 3.3"], outputs
            for title, text in reports.items():
                assert text.rstrip().endswith("全部正确！") == (user != "alice"), (user, text)
            assert "[错] /turtle1/cmd_vel 应该有 2 个发布者" in reports["练习 3.1"] or user != "alice"
            log = [json.loads(line) for line in
                   (homes / user / ".labkit_exercises.jsonl").read_text(encoding="utf-8").splitlines()]
            assert {r["exercise"]: r["passed"] for r in log} == \
                {t: user != "alice" for t in ("练习 3.1", "练习 3.2", "练习 3.3")}

        # nothing of one learner reaches another
        domains = set()
        for user, (_, probe) in results.items():
            lines = dict(line.split(" ", 1) for line in probe.splitlines() if " " in line)
            assert "DOMAIN" in lines, probe
            domain = lines["DOMAIN"]
            assert 1 <= int(domain) <= 101
            domains.add(domain)
            assert f"domain id               : {domain}" in probe or \
                any(ln.strip().startswith("domain id") and ln.rstrip().endswith(domain)
                    for ln in probe.splitlines()), probe
            nodes = lines["NODES"].split()
            assert f"/only_{user}" in nodes
            assert not any(f"/only_{o}" in nodes for o in PASSWORDS if o != user), nodes
            assert f"/chatter_{user}" in lines["JOBS"]
            assert not any(f"/chatter_{o}" in lines["JOBS"] for o in PASSWORDS if o != user)
            assert lines["FILES"].split() == [f"mine_{user}.txt"]
            assert sorted(p.name for p in (homes / user).glob("mine_*")) == [f"mine_{user}.txt"]
        assert len(domains) == 3
        # one learner's token opens no other learner's server or files
        status, _ = hub.request("GET", "/user/bob/api/contents", tokens["alice"])
        assert status == 403
        status, listing = hub.request("GET", "/user/bob/api/contents", tokens["bob"])
        assert status == 200 and "mine_alice.txt" not in {c["name"] for c in listing["content"]}

        # stop two; the idle culler stops the third once it has been idle 15 s
        for user in ("alice", "bob"):
            assert hub.request("DELETE", f"/hub/api/users/{user}/server", tokens[user])[0] in (202, 204)
        end = time.monotonic() + 90
        while time.monotonic() < end:
            servers = hub.request("GET", "/hub/api/users/carol", tokens["carol"])[1]["servers"]
            if not servers:
                break
            time.sleep(1)
        else:
            pytest.fail("the idle culler did not stop carol's server\n" + hub.logtext())
        log = (hub.dir / "hub.log").read_text(encoding="utf-8")
        assert "DELETE /hub/api/users/carol/server (idle-culler@127.0.0.1)" in log
        assert "/users/alice/server (idle-culler" not in log   # stopped by its learner
        assert all(not hub.request("GET", f"/hub/api/users/{u}", tokens[u])[1]["servers"]
                   for u in PASSWORDS)
    finally:
        hub.stop()
