"""The REAL ros2cli (Jazzy) against labkit's nodes, line by line next to real rclpy nodes.

Opt-in: no ros2cli wheel exists on PyPI, so this runs only when LABKIT_ROS2CLI_PATH
names a folder holding ros2cli, ros2node, ros2topic, ros2service, ros2action and
rosidl_runtime_py installed from their sources (recipe: benchmarks/README.md, "Checking
against the real ros2cli"); the reference venv's Python runs them. The same program
(talker, listener, and a node with a service, a client, an action server and an
action client) runs once under `labkit exec` and once under real rclpy, each on its
own domain; every verb must print the same lines for both, except what differs by
nature (gids, the counter in the echoed message) and what only Jazzy's nodes have
(the get_type_description service). Then labkit's own verbs, run on the real nodes,
must print what real ros2cli prints about them (less Jazzy's "Topic type hash" line,
which Humble's ros2cli does not print)."""
import os
import re
import subprocess

import pytest

from tests.dds.test_real_peers import (ROSREF, _domains, _env, finish, labkit, labkit_ros2,
                                       needs_rosref, real)

CLI_PATH = os.environ.get("LABKIT_ROS2CLI_PATH")
pytestmark = [needs_rosref, pytest.mark.skipif(
    not CLI_PATH, reason="set LABKIT_ROS2CLI_PATH to a folder where ros2cli and "
    "rosidl_runtime_py (Jazzy) are installed from source (benchmarks/README.md, "
    "'Checking against the real ros2cli') to run the real ros2 verbs against labkit")]

DEMO = """
from rclpy.action import ActionClient, ActionServer
from rclpy.executors import SingleThreadedExecutor
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger
SHARE = '__SHARE__'
if SHARE:      # labkit reads test_msgs from its .action file
    from labkit.interfaces.registry import add_share_path
    add_share_path(SHARE)
from test_msgs.action import Fibonacci

rclpy.init(args=[])
talker = rclpy.create_node('talker')
pub = talker.create_publisher(String, 'chatter', 10)
count = [0]
def tick():
    count[0] += 1
    pub.publish(String(data=f'Hello World: {count[0]}'))
talker.create_timer(0.5, tick)
listener = rclpy.create_node('listener')
listener.create_subscription(String, 'chatter', lambda m: None, 10)
server = rclpy.create_node('server')
server.create_service(SetBool, 'set_flag', lambda req, resp: resp)
server.create_client(Trigger, 'trigger')
ActionServer(server, Fibonacci, 'fibonacci', lambda goal: Fibonacci.Result())
ActionClient(server, Fibonacci, 'other_fibonacci')
executor = SingleThreadedExecutor()
for n in (talker, listener, server):
    executor.add_node(n)
end = time.monotonic() + 120
while time.monotonic() < end:      # the test ends it
    executor.spin_once(timeout_sec=0.1)
"""

DIRECT = ["--no-daemon", "--spin-time", "2"]
VERBS = [["node", "list", *DIRECT], ["node", "info", "/talker", *DIRECT],
         ["node", "info", "/listener", *DIRECT], ["node", "info", "/server", *DIRECT],
         ["topic", "info", "-v", "/chatter", *DIRECT], ["topic", "list", "-t", *DIRECT],
         ["service", "list", "-t", *DIRECT], ["topic", "echo", "/chatter", "--once", *DIRECT],
         ["topic", "info", "-v", "/rosout", *DIRECT],
         ["topic", "info", "-v", "/parameter_events", *DIRECT],
         ["topic", "type", "/chatter", *DIRECT], ["service", "type", "/trigger"],
         # the action verbs have no --no-daemon: they start the daemon (stopped at the end)
         ["action", "list", "-t"], ["action", "info", "-t", "/fibonacci"],
         ["action", "info", "-t", "/other_fibonacci"]]


def ros2(domain, argv):
    env = _env(domain, PYTHONPATH=CLI_PATH)
    env.pop("ROS_DISTRO", None)
    code = "import sys; from ros2cli.cli import main; sys.argv[0] = 'ros2'; sys.exit(main())"
    run = subprocess.run([str(ROSREF), "-c", code, *argv], env=env, capture_output=True,
                         text=True, timeout=60)
    return run.stdout + run.stderr


def normalise(text):
    text = re.sub(r"^GID: [0-9a-f.]+$", "GID: <gid>", text, flags=re.M)
    text = re.sub(r"Hello World: \d+", "Hello World: <n>", text)
    text = re.sub(r"_ros2cli_\d+", "_ros2cli_<pid>", text)     # ros2cli's own node
    text = "".join(line for line in text.splitlines(True) if "get_type_description" not in line)
    # `topic info -v` lists endpoints in the order discovery found them: compare as sets
    blocks, run = [], []
    for block in text.split("\n\n"):
        if block.startswith("Node name:"):
            run.append(block)
            continue
        blocks += sorted(run) + [block]
        run = []
    return "\n\n".join(blocks + sorted(run))


def test_real_ros2_verbs_print_the_same_for_labkit_as_for_real_nodes(tmp_path):
    share = tmp_path / "share" / "test_msgs" / "action"
    share.mkdir(parents=True)
    share.joinpath("Fibonacci.action").write_text(
        (ROSREF.parent.parent / "share" / "test_msgs" / "action" / "Fibonacci.action").read_text())
    lk_domain, real_domain = next(_domains) % 200 + 20, next(_domains) % 200 + 20
    lk = labkit(tmp_path, "lk_demo", DEMO.replace("__SHARE__", str(tmp_path / "share")),
                lk_domain)
    ref = real(tmp_path, "real_demo", DEMO.replace("__SHARE__", ""), real_domain)
    try:
        for argv in VERBS:
            for _ in range(4):      # ros2cli waits --spin-time for discovery, then reads
                want, got = ros2(real_domain, argv), ros2(lk_domain, argv)
                if normalise(got) == normalise(want) and got.strip():
                    break
            assert normalise(got) == normalise(want), "ros2 " + " ".join(argv)
            if argv[:2] == ["topic", "info"]:
                assert "Topic type hash: RIHS01_" in got and "INVALID" not in got
            if argv[:2] == ["node", "info"]:
                assert ("get_type_description" in want) and ("get_type_description" not in got)
        # and labkit's own verbs (Humble's texts) on the real nodes print what real ros2cli
        # prints, less Jazzy's type hash line (not /rosout, /parameter_events: each CLI and
        # the daemon publish there themselves)
        for argv in VERBS:
            if "/rosout" in argv or "/parameter_events" in argv:
                continue
            argv = [a for a in argv if a not in DIRECT]
            for _ in range(4):
                want = ros2(real_domain, argv)
                want = "".join(line for line in want.splitlines(True)
                               if not line.startswith("Topic type hash:"))
                got = labkit_ros2(real_domain, *argv, timeout=60)
                if normalise(got.stdout) == normalise(want) and want.strip():
                    break
            assert normalise(got.stdout) == normalise(want), "labkit ros2 " + " ".join(argv)
    finally:
        for domain in (lk_domain, real_domain):
            ros2(domain, ["daemon", "stop"])
        for proc in (lk, ref):
            proc.terminate()
            finish(proc)
