"""rqt_console: /rosout in a table; filters, pause/clear; --log-level honoured end to end."""
import sys
import types

import pytest

import labkit
from labkit import executables
from labkit.viz import console as console_mod
from labkit.viz.console import ConsoleView, LogEntry, MessageFilter, severity_level

PKG = "labkit_console_test"


def _loud_main(args=None):
    """A node logging one line per severity every 0.5 s."""
    from labkit import rclpy
    from labkit.rclpy.executors import ExternalShutdownException
    rclpy.init(args=args)
    node = rclpy.create_node("loud")
    log = node.get_logger()

    def tick():
        log.debug("debug line")
        log.info("info line")
        log.warning("warn line")
        log.error("error line")

    node.create_timer(0.5, tick)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


@pytest.fixture
def loud_executable():
    module = types.ModuleType("labkit_console_test_nodes")
    module.main = _loud_main
    sys.modules[module.__name__] = module
    executables.register(PKG, "loud", f"{module.__name__}:main")
    yield
    executables.unregister_package(PKG)
    sys.modules.pop(module.__name__, None)


def _by_node(view, node):
    return [e.severity_label for e in view.visible() if e.node == node]


def test_console_receives_rosout_with_transient_local_history():
    labkit.ros2("run turtlesim turtlesim_node")
    view = ConsoleView()            # started after turtlesim logged: history is replayed
    messages = [e.message for e in view.visible()]
    assert messages[0] == "Starting turtlesim with node name /turtlesim"
    assert messages[1].startswith("Spawning turtle [turtle1] at x=[5.544445]")
    entry = view.visible()[0]
    assert (entry.severity_label, entry.node) == ("Info", "turtlesim")
    assert entry.stamp == (1704067200, 0)
    assert entry.stamp_string() == "00:00:00.000000000 (2024-01-01)"
    assert entry.location.count(":") >= 2 and entry.location.endswith(f":{entry.line}")
    # later messages arrive during waits
    labkit.ros2("service call /spawn turtlesim/srv/Spawn '{x: 2.0, y: 2.0, name: t2}'")
    labkit.sleep(0.5)
    assert view.visible()[-1].message.startswith("Spawning turtle [t2]")
    # the console is a node on the graph, as rqt_console is
    assert any(n.startswith("/rqt_gui_py_node_") for n in
               labkit.ros2("node list").stdout.split())


def test_subscription_qos_is_reliable_transient_local():
    view = ConsoleView()
    qos = view._subscription.qos_profile
    assert qos.reliability.name == "RELIABLE"
    assert qos.durability.name == "TRANSIENT_LOCAL"
    assert qos.depth == 1000
    view.stop()
    assert not view.receiving
    assert console_mod.views() == []


def test_log_level_warn_shows_only_warn_and_above(loud_executable):
    view = ConsoleView()
    labkit.ros2(f"run {PKG} loud --ros-args --log-level WARN")
    labkit.sleep(1.1)
    assert _by_node(view, "loud") == ["Warn", "Error", "Warn", "Error"]


def test_log_level_per_logger_debug(loud_executable):
    view = ConsoleView()
    labkit.ros2(f"run {PKG} loud --ros-args --log-level loud:=DEBUG")
    labkit.sleep(0.6)
    assert _by_node(view, "loud") == ["Debug", "Info", "Warn", "Error"]


def test_default_level_is_info(loud_executable):
    view = ConsoleView()
    labkit.ros2(f"run {PKG} loud")
    labkit.sleep(0.6)
    assert _by_node(view, "loud") == ["Info", "Warn", "Error"]


def test_exclude_highlight_pause_clear(loud_executable):
    labkit.ros2("run turtlesim turtlesim_node")
    view = ConsoleView()
    labkit.ros2(f"run {PKG} loud")
    labkit.sleep(0.6)
    assert view.nodes() == ["loud", "turtlesim"]
    view.exclude(severities=["Info"])
    assert [e.severity_label for e in view.visible()] == ["Warn", "Error"]
    view.clear_filters()
    view.exclude(nodes=["/turtlesim"])
    assert {e.node for e in view.visible()} == {"loud"}
    view.clear_filters()
    view.highlight(text="error")
    html = view.table_html()
    assert "#bbbbbb" in html and html.count("color:#c00000") == 1   # only the error row in colour
    view.pause()
    before = len(view.messages)
    labkit.sleep(1.0)
    assert len(view.messages) == before      # nothing taken while paused
    view.resume()
    labkit.sleep(0.5)
    assert len(view.messages) == before + 3
    view.clear()
    assert view.visible() == [] and "Displaying 0 of 0 messages" in view.table_html()


def test_table_html_columns_and_escaping():
    view = ConsoleView(node=None, location=False)
    view.stop()
    entry = LogEntry(1, "a <b> & c", 40, "n", (1704067261, 5), "/x/f.py", "fn", 7)
    view.messages.append(entry)
    html = view.table_html()
    assert "<th" in html and ">Message</th>" in html and ">Location</th>" not in html
    assert "a &lt;b&gt; &amp; c" in html and "00:01:01.000000005 (2024-01-01)" in html
    assert "title='/x/f.py:fn:7'" in html
    view.location = True
    assert ">Location</th>" in view.table_html() and ">/x/f.py:fn:7</td>" in view.table_html()
    assert view.text() == "[Error] [00:01:01.000000005 (2024-01-01)] [n]: a <b> & c"


def test_widget_controls_filter_the_table(loud_executable):
    view = ConsoleView()
    labkit.ros2(f"run {PKG} loud")
    labkit.sleep(0.6)
    widget = view.widget()
    parts = view._parts
    parts["severities"][20].value = True     # exclude Info and Warn
    parts["severities"][30].value = True
    assert [e.severity_label for e in view.visible()] == ["Error"]
    assert "warn line" not in parts["table"].value and "error line" in parts["table"].value
    parts["severities"][20].value = False
    parts["severities"][30].value = False
    assert len(view.visible()) == 3
    parts["text"].value = "warn"
    assert view.highlighted(view.visible()[1]) and not view.highlighted(view.visible()[0])
    parts["text"].value = ""
    assert view.highlights == []
    parts["nodes"].value = ("loud",)
    assert view.visible() == []
    parts["pause"].value = True
    assert view.paused
    assert widget.children[-1] is parts["table"]


def test_severity_names():
    assert severity_level("WARN") == severity_level("warning") == 30
    assert severity_level(50) == 50
    with pytest.raises(ValueError):
        severity_level("loud")
    rule = MessageFilter(severities=["Error"], nodes=["/a"])
    assert rule.matches(LogEntry(1, "m", 40, "a", (0, 0), "", "", 0))
    assert not rule.matches(LogEntry(1, "m", 30, "a", (0, 0), "", "", 0))


def test_rqt_console_executable_shows_a_console():
    job = labkit.ros2("run rqt_console rqt_console")
    labkit.ros2("run turtlesim turtlesim_node")
    labkit.sleep(0.2)
    views = console_mod.views()
    assert len(views) == 1
    assert "Starting turtlesim with node name /turtlesim" in views[0].text()
    labkit.reset()
    assert console_mod.views() == []


def test_widget_follows_new_messages_and_show_emits_both_faces(loud_executable, monkeypatch):
    view = ConsoleView()
    table = view.widget().children[-1]
    assert "Displaying 0 of 0 messages" in table.value
    labkit.ros2(f"run {PKG} loud")
    labkit.sleep(0.8)              # a tick at 0.5 s, the redraw 0.2 s after it
    assert "warn line" in table.value and "Displaying 3 of 3 messages" in table.value
    shown = []
    monkeypatch.setattr("labkit.viz.display.display", lambda data, raw: shown.append(data))
    view.show()
    (data,) = shown
    assert "warn line" in data["text/html"] and "<table" in data["text/html"]
    assert data["application/vnd.jupyter.widget-view+json"]["model_id"] == view.widget().model_id
    assert data["text/plain"] == "<ConsoleView: 3 of 3 messages>"
    assert " title=" not in data["text/html"]      # no machine paths in the stored picture
    assert " title='" in table.value


def test_rqt_console_executable_takes_history_before_its_first_picture(monkeypatch):
    labkit.ros2("run turtlesim turtlesim_node")
    shown = []
    monkeypatch.setattr(ConsoleView, "show", lambda self: shown.append(self.text()))
    monkeypatch.setattr(console_mod, "_in_kernel", lambda: True)
    labkit.ros2("run rqt_console rqt_console")
    assert len(shown) == 1
    assert "[Info] [00:00:00.000000000 (2024-01-01)] [turtlesim]: Starting turtlesim" in shown[0]


def test_a_new_console_replaces_the_previous_one_unless_asked():
    first = ConsoleView()
    second = ConsoleView()
    assert not first.receiving and console_mod.views() == [second]
    third = ConsoleView(replace=False)
    assert console_mod.views() == [second, third]
    nodes = [n for n in labkit.ros2("node list").stdout.split() if "rqt_gui_py_node" in n]
    assert len(nodes) == 2


def test_turtlesim_at_warn_level_shows_only_wall_warnings():
    """The rqt_console tutorial: turtlesim at WARN, driven into the wall."""
    view = ConsoleView()
    labkit.ros2("run turtlesim turtlesim_node --ros-args --log-level WARN")
    labkit.ros2("topic pub -r 1 /turtle1/cmd_vel geometry_msgs/msg/Twist "
                "'{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 0.0}}'")
    labkit.sleep(4.0)
    entries = [e for e in view.visible() if e.node == "turtlesim"]
    assert entries, "turtlesim should have hit the wall"
    assert {e.severity_label for e in entries} == {"Warn"}
    assert entries[0].message.startswith("Oh no! I hit the wall! (Clamping from [x=11.")
