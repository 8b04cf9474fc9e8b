"""Sequence diagrams drawn from the traffic that really flowed in the graph.

    from labkit.viz.sequence import record

    with record("/add_two_ints") as trace:
        ...                      # call the service, send a goal, cancel it ...
    trace.show()                 # the diagram (SVG), readable in the book's column
    print(trace.text())          # the same events as lines of text

While the `with` block runs, every service request and response and every
message published on a topic whose name starts with one of the given prefixes
is noted: when (ROS time), from which node, to which node(s), and a short label
made from the message itself. Actions need no special case: their goal, result
and cancel calls are services and their feedback and status are topics under
`<action>/_action/`, so `record("/turtle1/rotate_absolute")` sees all five.

Real ROS 2 Humble has no service introspection (it came in Iron); on a real
machine `ros2 topic echo` shows the topic half of this and the service half
stays invisible. Here the recorder taps labkit's in-process middleware for the
duration of the block only, and puts everything back afterwards.
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass, field
from xml.sax.saxutils import escape, quoteattr

from labkit.viz._graph_render import COLUMN_PX, FONT_FAMILY

# figure geometry (SVG user units = pt; the figure is exactly the book's column wide)
WIDTH_PT = COLUMN_PX * 3.0 / 4.0      # 540 pt = 720 CSS px: drawn at 1:1 in the column
FONT = 11.0                           # 11 pt = 14.7 px in the column
SMALL_FONT = 10.0                     # 10 pt = 13.3 px
TIME_COL = 62.0
ROW = 30.0
HEAD = 48.0

_STATUS = {0: "UNKNOWN", 1: "ACCEPTED", 2: "EXECUTING", 3: "CANCELING",
           4: "SUCCEEDED", 5: "CANCELED", 6: "ABORTED"}
# ros2cli's hidden helper nodes get a readable stand-in on the lifeline
_HIDDEN_NAME = "ros2 (命令行)"


@dataclass
class Event:
    """One message on the wire: `kind` is request, response or message."""
    t_ns: int
    kind: str
    channel: str
    src: str
    dst: tuple
    label: str
    count: int = 1
    last_label: str = ""

    @property
    def key(self):
        return (self.kind, self.channel, self.src, self.dst)


def _fqn(node_info) -> str:
    fqn = node_info.fqn
    name = fqn() if callable(fqn) else fqn
    return _HIDDEN_NAME if name.rsplit("/", 1)[-1].startswith("_") else name


def _flow(msg, limit=34) -> str:
    """A message as a one-line YAML flow mapping, shortened to `limit` characters."""
    from labkit.interfaces.convert import message_to_ordereddict

    def one(value):
        if isinstance(value, dict):
            return "{" + ", ".join(f"{k}: {one(v)}" for k, v in value.items()) + "}"
        if isinstance(value, float):
            if value == int(value) and abs(value) < 1e6:
                return f"{value:.1f}"
            return f"{value:.3g}" if abs(value) < 1e4 else f"{value:.0f}"
        if isinstance(value, (list, tuple)):
            return "[" + ", ".join(one(v) for v in value[:4]) + (", ..." if len(value) > 4 else "") + "]"
        return repr(value) if isinstance(value, str) else str(value)
    try:
        text = one(dict(message_to_ordereddict(msg)))
    except Exception:                       # not a message: show its repr
        text = str(msg)
    return text if len(text) <= limit else text[: limit - 1] + "…"


def _label(channel: str, msg) -> str:
    """What the arrow says: action plumbing in words, anything else as its fields."""
    part = channel.rsplit("/_action/", 1)[-1] if "/_action/" in channel else None
    fields = getattr(msg, "get_fields_and_field_types", dict)()
    if part == "send_goal":
        if "goal" in fields:
            return "send_goal " + _flow(msg.goal, 28)
        return f"accepted: {msg.accepted}"
    if part == "get_result":
        if "result" in fields:
            return f"{_STATUS.get(msg.status, msg.status)} {_flow(msg.result, 24)}"
        return "get_result"
    if part == "cancel_goal":
        if "goals_canceling" in fields:
            return f"goals_canceling: {len(msg.goals_canceling)}"
        return "cancel_goal"
    if part == "feedback":
        return "feedback " + _flow(msg.feedback, 26)
    if part == "status":
        codes = [_STATUS.get(s.status, s.status) for s in msg.status_list]
        return "status: " + (codes[-1] if codes else "[]")
    return _flow(msg)


class Trace:
    """The events recorded by `record()`, merged and drawn."""

    def __init__(self, prefixes, merge=True):
        self.prefixes = tuple(prefixes)
        self.merge = merge
        self.events: list[Event] = []

    def wants(self, channel: str) -> bool:
        if not self.prefixes:
            return not channel.startswith(("/rosout", "/parameter_events")) and \
                channel.rsplit("/", 1)[-1] not in _PARAM_SERVICES
        return channel.startswith(self.prefixes)

    def add(self, t_ns, kind, channel, src, dst, msg):
        if not self.wants(channel) or not dst:
            return
        label = _label(channel, msg)
        event = Event(t_ns, kind, channel, src, tuple(sorted(set(dst))), label)
        last = self.events[-1] if self.events else None
        # a stream of the same message (62 feedbacks a second) becomes one arrow "×N"
        if self.merge and last is not None and last.key == event.key and kind == "message" \
                and label.split(" ", 1)[0] == last.label.split(" ", 1)[0] \
                and not channel.endswith("/status"):
            last.count += 1
            last.last_label = label
            return
        self.events.append(event)

    # -- views -------------------------------------------------------------------
    def participants(self) -> list[str]:
        order = []
        for e in self.events:
            for name in (e.src, *e.dst):
                if name not in order:
                    order.append(name)
        return order

    def _arrow_text(self, e: Event) -> str:
        if e.count == 1:
            return e.label
        last = e.last_label.split(" ", 1)[-1]
        if last.startswith("{") and last.count(": ") == 1:      # one field: its value is enough
            last = last[1:-1].split(": ", 1)[1]
        return f"{e.label} … {last} (×{e.count})"

    def text(self) -> str:
        """The events as lines: time since the first event, who to whom, what."""
        if not self.events:
            return "(没有记录到消息)"
        t0 = self.events[0].t_ns
        lines = []
        for e in self.events:
            short = e.channel.rsplit("/_action/", 1)[-1] if "/_action/" in e.channel else e.channel
            lines.append(f"{(e.t_ns - t0) / 1e9:7.3f} s  {e.src} -> {', '.join(e.dst)}  "
                         f"[{e.kind} {short}]  {self._arrow_text(e)}")
        return "\n".join(lines)

    def svg(self, title: str | None = None) -> str:
        people = self.participants()
        n = max(len(people), 1)
        height = HEAD + ROW * (len(self.events) + 1) + (22 if title else 0) + 30
        top = 22.0 if title else 0.0
        span = WIDTH_PT - TIME_COL - 20
        x = {p: TIME_COL + span * (i + 0.5) / n for i, p in enumerate(people)}
        box_w = min(span / n - 12, 190)
        out = [f'<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n'
               f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH_PT:.0f}pt" height="{height:.0f}pt" '
               f'viewBox="0 0 {WIDTH_PT:.0f} {height:.0f}" font-family={quoteattr(FONT_FAMILY)} '
               f'class="labkit-sequence">',
               '<defs><marker id="seq-head" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="7" '
               'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#333"/>'
               '</marker><marker id="seq-open" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="7" '
               'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10" fill="none" '
               'stroke="#b35900" stroke-width="1.5"/></marker></defs>',
               f'<rect width="{WIDTH_PT:.0f}" height="{height:.0f}" fill="white"/>']
        if title:
            out.append(f'<text x="{WIDTH_PT / 2:.1f}" y="15" text-anchor="middle" font-size="{FONT + 1:.0f}" '
                       f'font-weight="bold">{escape(title)}</text>')
        bottom = height - 26
        for p in people:
            out.append(f'<line x1="{x[p]:.1f}" y1="{top + HEAD - 12:.1f}" x2="{x[p]:.1f}" y2="{bottom:.1f}" '
                       f'stroke="#999" stroke-dasharray="4,3"/>')
            out.append(f'<rect x="{x[p] - box_w / 2:.1f}" y="{top + 8:.1f}" width="{box_w:.1f}" height="28" '
                       f'rx="14" fill="#eef3fb" stroke="#335"/>')
            out.append(f'<text x="{x[p]:.1f}" y="{top + 26:.1f}" text-anchor="middle" '
                       f'font-size="{FONT:.0f}">{escape(p)}</text>')
        out.append(f'<text x="6" y="{top + 26:.1f}" font-size="{SMALL_FONT:.0f}" fill="#555">时间 (s)</text>')
        t0 = self.events[0].t_ns if self.events else 0
        active = {n for e in self.events if e.kind != "message" for n in (e.src, *e.dst)}
        for row, e in enumerate(self.events):
            y = top + HEAD + ROW * (row + 0.8)
            out.append(f'<text x="6" y="{y + 4:.1f}" font-size="{SMALL_FONT:.0f}" fill="#555">'
                       f'{(e.t_ns - t0) / 1e9:.3f}</text>')
            x1 = x[e.src]
            # a topic reaches every subscriber: one arrow each; the label goes on the arrow to a
            # node that also takes part in the service calls (the goal's own client), else the farthest
            primary = next((d for d in e.dst if d in active), max(e.dst, key=lambda d: abs(x[d] - x1)))
            style = {"request": 'stroke="#333" marker-end="url(#seq-head)"',
                     "response": 'stroke="#333" stroke-dasharray="6,4" marker-end="url(#seq-head)"',
                     "message": 'stroke="#b35900" marker-end="url(#seq-open)"'}[e.kind]
            for d in e.dst:
                x2 = x[d]
                if abs(x2 - x1) < 1:        # a node talking to itself: a small loop
                    out.append(f'<path d="M{x1:.1f},{y - 6:.1f} h24 v12 h-24" fill="none" {style}/>')
                else:
                    out.append(f'<line x1="{x1:.1f}" y1="{y:.1f}" x2="{x2:.1f}" y2="{y:.1f}" '
                               f'stroke-width="1.4" {style}/>')
            mid = (x1 + x[primary]) / 2
            colour = "#b35900" if e.kind == "message" else "#111"
            out.append(f'<text x="{mid:.1f}" y="{y - 5:.1f}" text-anchor="middle" font-size="{FONT:.0f}" '
                       f'fill="{colour}">{escape(self._arrow_text(e))}</text>')
        legend_y = height - 8
        kinds = {e.kind for e in self.events}
        legend = "　".join(text for kind, text in (("request", "实线黑箭头：请求"), ("response", "虚线：应答"),
                                                  ("message", "橙色：话题消息（×N 表示连续 N 条）"))
                          if kind in kinds)
        out.append(f'<text x="6" y="{legend_y:.1f}" font-size="{SMALL_FONT:.0f}" fill="#555">{legend}</text>')
        out.append('</svg>')
        return "\n".join(out)

    def show(self, title: str | None = None):
        """Display the diagram (one SVG output; its text face lists the events)."""
        from labkit.viz.display import show
        show(svg=self.svg(title), text=self.text())

    def _repr_svg_(self):
        return self.svg()


_PARAM_SERVICES = {"describe_parameters", "get_parameter_types", "get_parameters",
                   "list_parameters", "set_parameters", "set_parameters_atomically"}


@contextmanager
def record(*prefixes: str, merge: bool = True):
    """Note every service call and topic message under these name prefixes while the block runs.

    Without prefixes everything is noted except /rosout, /parameter_events and the
    parameter services every node has. With `merge` (the default) a run of the same
    message stream (feedback at 62 Hz) is one arrow marked ×N; `merge=False` keeps each."""
    from labkit.graph import world
    from labkit.graph.registry import GRAPH, SUB
    from labkit.rclpy.client import Client
    from labkit.rclpy.publisher import Publisher
    from labkit.rclpy.service import Service

    trace = Trace(prefixes, merge)
    send, respond, publish = Client._send, Service.send_response, Publisher.publish

    def traced_send(self, request):
        ep = self._endpoint
        server = GRAPH.find_service(ep.name, ep.node.domain_id)
        if server is not None:
            trace.add(world.system_ns(), "request", ep.name, _fqn(ep.node), [_fqn(server.node)], request)
        return send(self, request)

    def traced_respond(self, response, header):
        client = getattr(getattr(header, "_reply", None), "__self__", None)
        if client is not None and isinstance(response, self.srv_type.Response):
            ep = self._endpoint
            trace.add(world.system_ns(), "response", ep.name, _fqn(ep.node),
                      [_fqn(client._endpoint.node)], response)
        return respond(self, response, header)

    def traced_publish(self, msg):
        ep = self._endpoint
        if trace.wants(ep.name) and ep.matched:
            readers = [_fqn(sub.node) for sub in GRAPH.endpoints_of(SUB, ep.name, ep.node.domain_id)
                       if sub.sink in ep.matched]
            trace.add(world.system_ns(), "message", ep.name, _fqn(ep.node), readers, msg)
        return publish(self, msg)

    Client._send, Service.send_response, Publisher.publish = traced_send, traced_respond, traced_publish
    try:
        yield trace
    finally:
        Client._send, Service.send_response, Publisher.publish = send, respond, publish
