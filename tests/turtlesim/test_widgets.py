"""The teleop keyboard widget: real key events and buttons reach turtle_teleop_key."""

from labkit import process
from labkit.sims.turtlesim import teleop
from labkit.viz.teleop_widget import TeleopWidget


def test_key_events_and_buttons_map_to_key_names():
    got = []
    w = TeleopWidget(got.append)
    for key in ("ArrowUp", "ArrowLeft", "g", "G", "x", "Shift", "q"):
        w._on_key({"type": "keydown", "key": key})
    assert got == ["up", "left", "g", "q"]          # capitals are not keys, as in the terminal
    buttons = [b for row in w.box.children[1].children if hasattr(row, "children")
               for b in row.children if hasattr(b, "click")]
    # the key help is the node's own output (printed once), not repeated in the pad;
    # no box of the pad scrolls
    assert not any("Use arrow keys" in getattr(c, "value", "") for c in w.box.children)
    assert w.box.layout.overflow == "visible"
    by_label = {b.description: b for b in buttons}
    by_label["\u2193"].click()
    by_label["F"].click()
    assert got[-2:] == ["down", "f"]
    assert "last key: f" in w.status.value
    assert set(w.events.watched_events) == {"keydown"}
    w.close()


def test_widget_drives_a_running_teleop():
    sim = process.start(["turtlesim", "turtlesim_node"], echo=False)
    tele = process.start(["turtlesim", "turtle_teleop_key"], echo=False)
    try:
        node = teleop.running()[-1]
        published = []
        real_publish = node.twist_pub.publish
        node.twist_pub.publish = lambda msg: (published.append(msg), real_publish(msg))
        w = TeleopWidget(node.press)
        w._on_key({"type": "keydown", "key": "ArrowDown"})
        assert published[-1].linear.x == -2.0 and published[-1].angular.z == 0.0
        w._on_key({"type": "keydown", "key": "ArrowRight"})
        assert published[-1].angular.z == -2.0
        w.close()
    finally:
        tele.stop()
        sim.stop()
