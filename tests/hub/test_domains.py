"""Isolation on the wire: two learners' `labkit exec` talkers on one host (DDS on,
loopback) on the domains the hub gives them do not hear each other; on one class
domain (LABKIT_CLASS_DOMAIN, a teacher's demo) they do."""
import pytest

from labkit.teacher.domain import domain_for
from tests.dds.test_real_peers import done, labkit, line_from

TALKER = """
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('talker')
pub = node.create_publisher(String, 'chatter', 10)
who = os.environ['LEARNER']
end = time.monotonic() + 40
print('ready', flush=True)
while time.monotonic() < end and not os.path.exists(os.environ['STOP_FILE']):
    pub.publish(String(data='from ' + who))
    rclpy.spin_once(node, timeout_sec=0.1)
"""

LISTENER = """
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('listener')
heard = set()
node.create_subscription(String, 'chatter', lambda m: heard.add(m.data), 10)
spin_until(node, lambda: len(heard) >= int(os.environ['WANT']), 8)
spin_until(node, lambda: False, 1.5)
print('heard', *sorted(heard), flush=True)
"""


def _run(tmp_path, domains, listen_on, want):
    stop = tmp_path / "stop"
    if stop.exists():
        stop.unlink()
    talkers = [labkit(tmp_path, f"talker_{who}", TALKER, dom,
                      env_extra={"LEARNER": who, "STOP_FILE": str(stop)})
               for who, dom in domains.items()]
    try:
        for t in talkers:
            assert "ready" in line_from(t.stdout, lambda line: "ready" in line, 30)
        result = done(labkit(tmp_path, "listener", LISTENER, listen_on,
                             env_extra={"WANT": str(want)}), timeout=40)
    finally:
        stop.write_text("")
        for t in talkers:
            done(t)
    assert result.returncode == 0, result.stderr
    return result.stdout.split()


def test_learners_apart_then_together(tmp_path):
    alice, bob = domain_for("alice", 1), domain_for("bob", 2)
    assert alice != bob
    heard = _run(tmp_path, {"alice": alice, "bob": bob}, alice, want=2)
    assert heard == ["heard", "from", "alice"]
    heard = _run(tmp_path, {"alice": alice, "bob": bob}, bob, want=2)
    assert heard == ["heard", "from", "bob"]
    shared = domain_for("alice", 1, class_domain="42")
    assert shared == domain_for("bob", 2, class_domain="42") == 42
    heard = _run(tmp_path, {"alice": shared, "bob": shared}, shared, want=2)
    assert heard == ["heard", "from", "alice", "from", "bob"]


def test_domain_rules():
    assert domain_for("x", 1) == 1 and domain_for("x", 101) == 101 and domain_for("x", 102) == 1
    assert len({domain_for("u", i) for i in range(1, 102)}) == 101
    assert all(1 <= domain_for(f"learner{i}") <= 101 for i in range(500))
    assert domain_for("alice") == domain_for("alice")
    assert domain_for("alice", 5, class_domain="0") == 0
    with pytest.raises(ValueError, match="LABKIT_CLASS_DOMAIN must be within 0-101, got 102"):
        domain_for("alice", class_domain="102")
