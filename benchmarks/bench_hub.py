"""What one learner costs on a JupyterHub, and how many fit a 2-core / 24 GB server.

    python benchmarks/bench_hub.py [--learners 1,3,6] [--out FILE.json]

Starts the hub of tests/hub (127.0.0.1, configurable-http-proxy, local spawner) with
learners in LIVE time (as on a real hub), then measures through the hub, as a browser:
  1. one learner (memory as PSS: shared libraries split among the processes using them):
     the single-user server's memory idle; its kernel running ch03 and then
     ch14 (the Part 2 node tasks, in a copy of the chapter's folder): wall time, CPU
     seconds (server + kernel), peak memory; CPU while idle afterwards (simulators left
     running, as a learner leaves them);
  2. N learners at once running ch03 live, while a probe kernel times a small cell
     (`labkit.ros2('node list')`) every 0.5 s: median and 95th percentile cell latency.
Prints a table and the capacity estimate (memory: 80 % of 24 GB; CPU: 2 cores).
"""
import argparse
import asyncio
import json
import os
import shutil
import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path

import psutil

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
os.environ["HUBTEST_TIME"] = "live"

from tests.hub._learners import load, write          # noqa: E402
from tests.hub import test_hub as th                   # noqa: E402

CH14 = REPO / "book" / "part2_facer" / "ch14_node_tasks.ipynb"


def _procs(user):
    """The learner's single-user server and its kernels."""
    out = []
    for p in psutil.process_iter(["cmdline", "environ"]):
        try:
            env = p.info["environ"] or {}
            if env.get("JUPYTERHUB_USER") == user:
                out.append(p)
        except (psutil.Error, TypeError):
            pass
    return out


class Meter(threading.Thread):
    """Samples memory (PSS, sum) and CPU seconds of a learner's processes every 0.25 s."""

    def __init__(self, user):
        super().__init__(daemon=True)
        self.user, self.peak, self.stop_flag = user, 0, False
        self.cpu0 = self.cpu_now()

    def cpu_now(self):
        total = 0.0
        for p in _procs(self.user):
            try:
                t = p.cpu_times()
                total += t.user + t.system + t.children_user + t.children_system
            except psutil.Error:
                pass
        return total

    def rss_now(self):
        total = 0
        for p in _procs(self.user):
            try:           # PSS: shared libraries counted once across the class
                total += p.memory_full_info().pss
            except (psutil.Error, AttributeError):
                try:
                    total += p.memory_info().rss
                except psutil.Error:
                    pass
        return total

    def run(self):
        while not self.stop_flag:
            self.peak = max(self.peak, self.rss_now())
            time.sleep(0.25)

    def stop(self):
        self.stop_flag = True
        self.join()
        return self.cpu_now() - self.cpu0


def _cells(nb):
    return list(th._code_cells(nb))


async def _run_notebook(hub, user, token, path, nb):
    k = th.Kernel(hub, user, token, path)
    await k.start()
    t0 = time.monotonic()
    for code in _cells(nb):
        await k.run(code, timeout=300)
    wall = time.monotonic() - t0
    k.ws.close()
    return k, wall


def _start(hub, users, passwords):
    tokens = {}
    for u in users:
        status, body = hub.request("POST", f"/hub/api/users/{u}/tokens",
                                   body={"auth": {"username": u, "password": passwords[u]}})
        assert status == 201, status
        tokens[u] = body["token"]
        hub.request("POST", f"/hub/api/users/{u}/server", tokens[u])
    end = time.monotonic() + 300
    while time.monotonic() < end:
        if all(hub.request("GET", f"/user/{u}/api/status", tokens[u])[0] == 200 for u in users):
            return tokens
        time.sleep(0.5)
    raise RuntimeError("servers did not start:\n" + hub.logtext())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--learners", default="1,3,6")
    ap.add_argument("--out")
    args = ap.parse_args()
    counts = [int(n) for n in args.learners.split(",")]
    users = [f"l{i:02d}" for i in range(max(counts) + 1)]      # + the probe learner
    passwords = {u: f"pw-{u}" for u in users}
    tmp = Path(tempfile.mkdtemp(prefix="bench_hub_"))
    th.PASSWORDS.clear()
    th.PASSWORDS.update(passwords)
    for u in users:
        write(load(), tmp / "home" / u / "ch03_topics.ipynb")
    shutil.copytree(REPO / "book" / "part2_facer", tmp / "home" / users[0] / "part2_facer",
                    ignore=shutil.ignore_patterns("_build", "_work", ".ipynb_checkpoints"))
    hub = th.Hub(tmp, idle_timeout=3600)
    fig = {"cpus": psutil.cpu_count(), "ram_gb": round(psutil.virtual_memory().total / 2**30, 1)}
    try:
        hub.wait_up()
        one = users[0]
        tokens = _start(hub, [one], passwords)
        time.sleep(5)
        m = Meter(one)
        fig["server_idle_mb"] = round(m.rss_now() / 2**20)
        idle_cpu0 = m.cpu_now()
        time.sleep(10)
        fig["server_idle_cpu_pct"] = round((m.cpu_now() - idle_cpu0) / 10 * 100, 1)

        for name, path, nb in (("ch03", "ch03_topics.ipynb", load()),
                               ("ch14", "part2_facer/ch14_node_tasks.ipynb", load(CH14))):
            m = Meter(one)
            m.start()
            kernel, wall = asyncio.run(_run_notebook(hub, one, tokens[one], path, nb))
            cpu = m.stop()
            fig[f"{name}_wall_s"] = round(wall, 1)
            fig[f"{name}_cpu_s"] = round(cpu, 1)
            fig[f"{name}_peak_mb"] = round(m.peak / 2**20)
            c0 = m.cpu_now()
            time.sleep(10)
            fig[f"{name}_after_idle_cpu_pct"] = round((m.cpu_now() - c0) / 10 * 100, 1)
            fig[f"{name}_after_mb"] = round(m.rss_now() / 2**20)
        hub.request("DELETE", f"/hub/api/users/{one}/server", tokens[one])
        time.sleep(3)

        fig["latency"] = {}
        probe = users[-1]
        ptok = _start(hub, [probe], passwords)
        for n in counts:
            group = users[:n]
            toks = _start(hub, group, passwords)

            async def round_():
                pk = th.Kernel(hub, probe, ptok[probe], "ch03_topics.ipynb")
                await pk.start()
                await pk.run("import labkit")
                lat, done = [], []

                async def probing():
                    while not done:
                        t0 = time.monotonic()
                        await pk.run("labkit.ros2('node list').stdout")
                        lat.append(time.monotonic() - t0)
                        await asyncio.sleep(0.5)

                async def learners():
                    t0 = time.monotonic()
                    res = await asyncio.gather(*(_run_notebook(hub, u, toks[u], "ch03_topics.ipynb",
                                                               load()) for u in group))
                    done.append(1)
                    return time.monotonic() - t0, [w for _, w in res]
                (wall, walls), _ = await asyncio.gather(learners(), probing())
                pk.ws.close()
                return lat, walls
            lat, walls = asyncio.run(round_())
            lat.sort()
            fig["latency"][n] = {
                "median_ms": round(statistics.median(lat) * 1000),
                "p95_ms": round(lat[int(0.95 * (len(lat) - 1))] * 1000),
                "ch03_wall_s": round(max(walls), 1)}
            for u in group:
                hub.request("DELETE", f"/hub/api/users/{u}/server", toks[u])
            time.sleep(3)
        hub.request("DELETE", f"/hub/api/users/{probe}/server", ptok[probe])
    finally:
        hub.stop()
        shutil.rmtree(tmp, ignore_errors=True)

    per_mb = max(fig["ch03_after_mb"], fig["ch14_after_mb"], fig["ch03_peak_mb"], fig["ch14_peak_mb"])
    fig["fit_by_memory_24gb"] = int(24 * 1024 * 0.8 // per_mb)
    active = max(fig["ch03_cpu_s"] / fig["ch03_wall_s"], fig["ch14_cpu_s"] / fig["ch14_wall_s"])
    idle = max(fig["ch03_after_idle_cpu_pct"], fig["ch14_after_idle_cpu_pct"]) / 100
    fig["active_cpu_cores"] = round(active, 2)
    fig["idle_cpu_cores"] = round(idle, 3)
    fig["fit_by_cpu_all_running"] = int(2 * 0.8 // active)
    fig["fit_by_cpu_quarter_running"] = int(2 * 0.8 // (0.25 * active + 0.75 * idle))
    print(f"{'machine':34s} {fig['cpus']} CPUs, {fig['ram_gb']} GB")
    print(f"{'server idle (no kernel)':34s} {fig['server_idle_mb']} MB, {fig['server_idle_cpu_pct']} % CPU")
    for name in ("ch03", "ch14"):
        print(f"{name + ' live: wall / CPU / peak':34s} {fig[name + '_wall_s']} s / "
              f"{fig[name + '_cpu_s']} CPU-s / {fig[name + '_peak_mb']} MB")
        print(f"{name + ' after, idle: memory / CPU':34s} {fig[name + '_after_mb']} MB / "
              f"{fig[name + '_after_idle_cpu_pct']} % CPU")
    for n, row in fig["latency"].items():
        print(f"{str(n) + ' learners run ch03 live at once':34s} probe cell median {row['median_ms']} ms,"
              f" p95 {row['p95_ms']} ms; slowest ch03 {row['ch03_wall_s']} s")
    print(f"{'fit 24 GB (80 %) by memory':34s} {fig['fit_by_memory_24gb']} learners")
    print(f"{'fit 2 cores, all running cells':34s} {fig['fit_by_cpu_all_running']} learners")
    print(f"{'fit 2 cores, 1/4 running, rest idle':34s} {fig['fit_by_cpu_quarter_running']} learners")
    if args.out:
        Path(args.out).write_text(json.dumps(fig, indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
