"""rqt_console in a notebook: the `/rosout` messages of the whole graph, as a table.

    from labkit.viz.console import ConsoleView
    console = ConsoleView()                  # subscribes to /rosout (its own node)
    console.exclude(severities=["Debug"])    # rqt_console's "Exclude Messages"
    console.highlight(nodes=["turtlesim"])   # "Highlight Messages": others are greyed
    console.show()                           # live widget + static HTML table, one output
    console.messages                         # every LogEntry received (unless paused)

Like rqt_console it is a node (`rqt_gui_py_node_<pid>`) subscribed to
`/rosout` (rcl_interfaces/msg/Log) reliable and transient local, so it also
receives what nodes logged shortly before it started (the /rosout publishers
keep 1000 messages for 10 s). Unlike rqt_console's depth 10, the subscription
keeps 1000 messages: in virtual time a node may log many lines before the
console's turn comes.

Live time: the console's process thread sleeps in its executor until a message
arrives (no CPU when idle); the widget is redrawn at most every 0.2 s.
Virtual time: messages arrive during waits (`labkit.sleep`, ...); `show()` and
the widget reflect what had arrived when drawn. Times are shown as rqt_console
shows them, `hh:mm:ss.nnnnnnnnn (yyyy-MM-dd)`: local time in live mode, UTC in
virtual mode (the same text on every machine).
"""
from __future__ import annotations

import html
import os
import itertools
import threading
import time
import weakref
from dataclasses import dataclass

__all__ = ["ConsoleView", "LogEntry", "SEVERITY_LABELS", "views", "stop_all", "main"]

# rqt_console's labels for rcl_interfaces/msg/Log levels
SEVERITY_LABELS = {10: "Debug", 20: "Info", 30: "Warn", 40: "Error", 50: "Fatal"}
_LEVEL_OF = {label.lower(): level for level, label in SEVERITY_LABELS.items()}
_LEVEL_OF.update({"warning": 30})
_COLOURS = {10: "#6a6a6a", 20: "#000000", 30: "#b36b00", 40: "#c00000", 50: "#800080"}

RENDER_PERIOD_S = 0.2      # at most this often the live widget is redrawn
SHOWN_ROWS = 200           # the table shows the newest rows (all are kept up to `limit`)


def severity_level(value) -> int:
    """10/20/30/40/50 from a level, 'Warn', 'WARN', 'warning' or a LoggingSeverity."""
    if isinstance(value, str):
        try:
            return _LEVEL_OF[value.strip().lower()]
        except KeyError:
            raise ValueError(f"unknown severity {value!r}: one of "
                             f"{', '.join(SEVERITY_LABELS.values())}") from None
    level = int(value)
    if level not in SEVERITY_LABELS:
        raise ValueError(f"unknown severity {value!r}")
    return level


@dataclass(frozen=True)
class LogEntry:
    """One /rosout message as rqt_console lists it."""
    id: int
    message: str
    severity: int
    node: str
    stamp: tuple          # (sec, nanosec)
    file: str
    function: str
    line: int

    @classmethod
    def from_log(cls, id_, log):
        return cls(id_, log.msg, int(log.level), log.name,
                   (int(log.stamp.sec), int(log.stamp.nanosec)),
                   log.file, log.function, int(log.line))

    @property
    def severity_label(self) -> str:
        return SEVERITY_LABELS.get(self.severity, str(self.severity))

    @property
    def location(self) -> str:
        # rqt_console's location column: file:function:line (labkit's own files shown
        # relative to where labkit is installed, so no machine path is kept)
        return f"{_shown_file(self.file)}:{self.function}:{self.line}"

    def stamp_string(self, utc: bool = True) -> str:
        """rqt_console's 'hh:mm:ss.ZZZ (yyyy-MM-dd)', ZZZ being the 9-digit nanoseconds."""
        sec, nsec = self.stamp
        t = time.gmtime(sec) if utc else time.localtime(sec)
        return time.strftime("%H:%M:%S", t) + f".{nsec:09d}" + time.strftime(" (%Y-%m-%d)", t)


_LABKIT_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(__file__))).rstrip(os.sep)
_LABKIT_PARENT = os.path.dirname(_LABKIT_PARENT) + os.sep


def _shown_file(path):
    path = str(path or "")
    if path.startswith(_LABKIT_PARENT):
        return path[len(_LABKIT_PARENT):]
    try:
        from labkit.ament import files
        return files.display(path)
    except Exception:
        return path


class MessageFilter:
    """A rule over severities, node names and message text; empty parts match anything."""

    def __init__(self, severities=(), nodes=(), text=None):
        self.severities = frozenset(severity_level(s) for s in severities)
        self.nodes = frozenset(n.lstrip("/") for n in nodes)
        self.text = text or None

    def matches(self, entry: LogEntry) -> bool:
        if self.severities and entry.severity not in self.severities:
            return False
        if self.nodes and entry.node.lstrip("/") not in self.nodes:
            return False
        if self.text and self.text not in entry.message:
            return False
        return True

    def __repr__(self):
        parts = []
        if self.severities:
            parts.append("severities=" + str(sorted(SEVERITY_LABELS[s] for s in self.severities)))
        if self.nodes:
            parts.append("nodes=" + str(sorted(self.nodes)))
        if self.text:
            parts.append(f"text={self.text!r}")
        return f"MessageFilter({', '.join(parts)})"


def _live_mode():
    from labkit.graph import world
    return world.mode() == "live"


_VIEWS = weakref.WeakSet()
_view_ids = itertools.count(1)


def views():
    """Every console still receiving, oldest first (`ros2 run rqt_console rqt_console`'s too)."""
    return sorted((v for v in list(_VIEWS) if v.receiving), key=lambda v: v._order)


def stop_all():
    for view in views():
        view.stop()


class ConsoleView:
    """rqt_console's message list, filters, pause and clear; a widget and a static table.

    node=None starts the console's own process (a node `rqt_gui_py_node_<pid>`
    spinning in the background, stopped by `stop()` or `labkit.reset()`); it
    replaces the console started that way before (a re-run cell does not pile
    up consoles) unless replace=False. Given a node, the console subscribes
    through it and that node's owner spins it.
    """

    def __init__(self, node=None, *, limit: int = 20000, rows: int = SHOWN_ROWS,
                 location: bool = False, utc: bool | None = None, replace: bool = True):
        self.limit = limit                # rqt_console's message limit (oldest dropped)
        self.rows = rows
        self.location = location          # show file:function:line (on demand)
        self.utc = (not _live_mode()) if utc is None else utc   # virtual time: same text anywhere
        self.messages: list[LogEntry] = []
        self.excludes: list[MessageFilter] = []
        self.highlights: list[MessageFilter] = []
        self.paused = False
        self._order = next(_view_ids)
        self._lock = threading.Lock()
        self._next_id = 1
        self._widget = None
        self._parts = None
        self._timer = None
        self._render_pending = False
        self._process = None
        self._subscription = None
        self._node = None
        if node is not None:
            self.attach(node)
        else:
            if replace:
                for older in views():
                    if older._process is not None:
                        older.stop()
            self._start_process()
        _VIEWS.add(self)

    # ------------------------------------------------------------ receiving
    def attach(self, node):
        """Subscribe to /rosout through `node` (what rqt_console's plugin does)."""
        from labkit.rclpy.qos import (DurabilityPolicy, HistoryPolicy, QoSProfile,
                                      ReliabilityPolicy)
        from labkit.interfaces import get_type
        qos = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1000,
                         reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self._node = node
        self._subscription = node.create_subscription(
            get_type("rcl_interfaces/msg/Log"), "/rosout", self._on_log, qos)
        # one timer, idle (cancelled) until a message wants the widget redrawn
        self._timer = node.create_timer(RENDER_PERIOD_S, self._on_render_timer)
        self._timer.cancel()

    def _start_process(self):
        from labkit import process

        def rqt_console(args=None):
            from labkit import rclpy
            from labkit.rclpy.executors import ExternalShutdownException
            rclpy.init(args=args)
            node = rclpy.create_node(f"rqt_gui_py_node_{process.current().pid}")
            self.attach(node)
            try:
                rclpy.spin(node)
            except (KeyboardInterrupt, ExternalShutdownException):
                pass
            finally:
                node.destroy_node()
                rclpy.try_shutdown()

        self._process = process.start(main=rqt_console, name="rqt_console", echo=True)

    @property
    def receiving(self) -> bool:
        if self._process is not None:
            return self._process.running
        try:
            return self._node is not None and self._node.context.ok()
        except Exception:
            return False

    def _on_log(self, log):
        if self.paused:
            return                       # rqt_console drops what arrives while paused
        with self._lock:
            self.messages.append(LogEntry.from_log(self._next_id, log))
            self._next_id += 1
            if len(self.messages) > self.limit:
                del self.messages[:len(self.messages) - self.limit]
        if self._widget is not None and not self._render_pending:
            self._render_pending = True
            self._timer.reset()

    def _on_render_timer(self):
        self._timer.cancel()
        self._render_pending = False
        self.refresh()

    def stop(self):
        """Stop receiving (the console's own process ends; the table stays)."""
        if self._process is not None:
            self._process.stop()
        elif self._node is not None and self._subscription is not None:
            try:
                self._node.destroy_subscription(self._subscription)
                self._node.destroy_timer(self._timer)
            except Exception:
                pass
        self._subscription = None
        _VIEWS.discard(self)

    # ------------------------------------------------------------ controls
    def pause(self):
        self.paused = True
        self._sync_controls()

    def resume(self):
        self.paused = False
        self._sync_controls()

    def clear(self):
        """Forget every message received so far (rqt_console's Clear)."""
        with self._lock:
            self.messages = []
        self.refresh()

    def exclude(self, severities=(), nodes=(), text=None) -> MessageFilter:
        """Hide messages matching this rule (all given parts must match)."""
        rule = MessageFilter(severities, nodes, text)
        self.excludes.append(rule)
        self._sync_controls()
        self.refresh()
        return rule

    def highlight(self, severities=(), nodes=(), text=None) -> MessageFilter:
        """Grey out every message that matches no highlight rule."""
        rule = MessageFilter(severities, nodes, text)
        self.highlights.append(rule)
        self.refresh()
        return rule

    def clear_filters(self):
        self.excludes.clear()
        self.highlights.clear()
        self._sync_controls()
        self.refresh()

    # ------------------------------------------------------------ what is shown
    def _settle(self):
        """Virtual time, notebook thread: let the console take what was already published."""
        from labkit.graph import world
        if world.mode() == "virtual" and threading.current_thread() is threading.main_thread():
            world.settle()

    def visible(self) -> list[LogEntry]:
        """The messages no exclude rule hides, oldest first."""
        self._settle()
        with self._lock:
            entries = list(self.messages)
        return [e for e in entries if not any(rule.matches(e) for rule in self.excludes)]

    def highlighted(self, entry: LogEntry) -> bool:
        return not self.highlights or any(rule.matches(entry) for rule in self.highlights)

    def nodes(self) -> list[str]:
        """Node (logger) names seen so far, sorted."""
        with self._lock:
            return sorted({e.node for e in self.messages})

    def text(self) -> str:
        """The visible messages as plain lines, like rqt_console's copy-to-clipboard."""
        return "\n".join(f"[{e.severity_label}] [{e.stamp_string(self.utc)}] [{e.node}]: "
                         f"{e.message}" for e in self.visible())

    def table_html(self, titles: bool = True) -> str:
        """The table: # | Message | Severity | Node | Time [| Location], newest rows.

        titles=True gives each row its location as a hover text; the static face
        leaves it out (source paths differ from machine to machine)."""
        entries = self.visible()
        shown = entries[-self.rows:] if self.rows else entries
        head = ["#", "Message", "Severity", "Node", "Time"] + (["Location"] if self.location
                                                                 else [])
        cell = "border:1px solid #ccc;padding:2px 6px;text-align:left;vertical-align:top"
        out = ["<table class='labkit-console' style='border-collapse:collapse;"
               "font-family:monospace;font-size:12px'>",
               "<thead><tr>" + "".join(f"<th style='{cell};background:#eee'>{h}</th>"
                                       for h in head) + "</tr></thead><tbody>"]
        for e in shown:
            colour = _COLOURS.get(e.severity, "#000") if self.highlighted(e) else "#bbbbbb"
            values = [str(e.id), e.message, e.severity_label, e.node, e.stamp_string(self.utc)]
            if self.location:
                values.append(e.location)
            tds = "".join(f"<td style='{cell}'>{html.escape(v)}</td>" for v in values)
            title = f" title='{html.escape(e.location)}'" if titles else ""
            out.append(f"<tr style='color:{colour}'{title}>{tds}</tr>")
        out.append("</tbody></table>")
        hidden = len(entries) - len(shown)
        total = len(self.messages)
        note = f"Displaying {len(entries)} of {total} messages"
        if hidden:
            note += f" (newest {len(shown)} rows shown)"
        if self.paused:
            note += " (paused)"
        return (f"<div class='labkit-console-view'><div style='font-family:sans-serif;"
                f"font-size:12px;margin:2px 0'><b>rqt_console</b> &mdash; {html.escape(note)}"
                f"</div>{''.join(out)}</div>")

    def _repr_html_(self):
        return self.table_html(titles=False)

    def __repr__(self):
        return f"<ConsoleView: {len(self.visible())} of {len(self.messages)} messages>"

    # ------------------------------------------------------------ the widget
    def widget(self):
        """ipywidgets: Pause, Clear, Location; exclude by severity and node; highlight text;
        the table."""
        if self._widget is not None:
            return self._widget
        import ipywidgets as w
        pause = w.ToggleButton(value=self.paused, description="Pause", icon="pause",
                               layout=w.Layout(width="80px"))
        clear = w.Button(description="Clear", icon="trash", layout=w.Layout(width="80px"))
        location = w.ToggleButton(value=self.location, description="Location",
                                  tooltip="show file:function:line",
                                  layout=w.Layout(width="90px"))
        # rqt_console's "Exclude Messages ...with severities": a pressed button excludes it
        severities = {level: w.ToggleButton(value=False, description=label,
                                             tooltip=f"exclude {label} messages",
                                             layout=w.Layout(width="60px"))
                      for level, label in SEVERITY_LABELS.items()}
        nodes = w.SelectMultiple(options=self.nodes(), rows=3, description="Exclude nodes:",
                                 style={"description_width": "initial"})
        text = w.Text(value="", placeholder="text", description="Highlight containing:",
                      continuous_update=False, style={"description_width": "initial"})
        table = w.HTML(self.table_html())

        def on_pause(change):
            self.paused = change["new"]
            self.refresh()

        def on_location(change):
            self.location = change["new"]
            self.refresh()

        pause.observe(on_pause, "value")
        location.observe(on_location, "value")
        for button in severities.values():
            button.observe(lambda _: self._apply_widget_filters(), "value")
        nodes.observe(lambda _: self._apply_widget_filters(), "value")
        text.observe(lambda _: self._apply_widget_filters(), "value")
        clear.on_click(lambda _: self.clear())
        self._parts = {"pause": pause, "location": location, "severities": severities,
                       "nodes": nodes, "text": text, "table": table}
        self._widget_rules = ([], [])        # (exclude rules, highlight rules) it made
        controls = w.HBox([pause, clear, location, w.Label("Exclude:"),
                           *severities.values()])
        self._widget = w.VBox([controls, w.HBox([nodes, text]), table])
        self._widget.add_class("labkit-console")
        return self._widget

    def _apply_widget_filters(self):
        """The widget's rules are rules like any other, replaced when a control changes."""
        parts = self._parts
        for mine, rules in zip(self._widget_rules, (self.excludes, self.highlights)):
            for rule in mine:
                if rule in rules:
                    rules.remove(rule)
        excluded = [level for level, b in parts["severities"].items() if b.value]
        excludes = [MessageFilter(severities=excluded)] if excluded else []
        if parts["nodes"].value:
            excludes.append(MessageFilter(nodes=parts["nodes"].value))
        highlights = [MessageFilter(text=parts["text"].value)] if parts["text"].value else []
        self._widget_rules = (excludes, highlights)
        self.excludes.extend(excludes)
        self.highlights.extend(highlights)
        self.refresh()

    def _sync_controls(self):
        if self._parts is not None:
            self._parts["pause"].value = self.paused

    def refresh(self):
        """Redraw the widget's table (and refresh its node list)."""
        if self._parts is None:
            return
        nodes = self._parts["nodes"]
        names = tuple(self.nodes())
        if tuple(nodes.options) != names:
            keep = tuple(n for n in nodes.value if n in names)
            nodes.options = names
            nodes.value = keep
        self._parts["table"].value = self.table_html()

    def show(self):
        """Display the widget and the static HTML table in one output."""
        from labkit.viz.display import show
        widget = self.widget()
        self.refresh()
        show(widget, html=self.table_html(titles=False), text=repr(self))

    def _ipython_display_(self):
        self.show()


# ------------------------------------------------------------ `ros2 run rqt_console rqt_console`

def _in_kernel():
    """True inside a Jupyter kernel (where a picture can be shown)."""
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and getattr(shell, "kernel", None) is not None


def main(args=None):
    """rqt_console as an executable: its node subscribes to /rosout and the console is
    shown in the notebook running the command; `views()[-1]` gives it to code."""
    from labkit import process, rclpy
    from labkit.rclpy.executors import ExternalShutdownException
    rclpy.init(args=args)
    node = rclpy.create_node(f"rqt_gui_py_node_{process.current().pid}")
    view = ConsoleView(node=node)
    # take what /rosout's publishers kept for late joiners before the first picture
    for _ in range(view.limit):
        before = len(view.messages)
        rclpy.spin_once(node, timeout_sec=0)
        if len(view.messages) == before:
            break
    if _in_kernel():
        view.show()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        _VIEWS.discard(view)
        node.destroy_node()
        rclpy.try_shutdown()
