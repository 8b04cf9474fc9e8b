"""Pictures for Part 1 of the book (chapters 6, 8 and 9), drawn from live labkit data.

Each function returns an `SVG` picture 720 px wide (the book's column), so a
label drawn at `font-size` N is N px on the page; no label is smaller than 12 px.

- `message_on_the_wire(msg)`: an interface file, the class rosidl makes of it,
  and the CDR bytes of this very message, byte by byte, coloured per field.
- `workspace_overlays()`: the workspaces the session has sourced, on top of
  /opt/ros/humble, in the order `ros2 run` and `import` search them.
- `name_expansion(node, namespace, names)`: how relative, private (`~`) and
  absolute names expand for a node in a namespace (rcl's own rules).
"""
from __future__ import annotations

import os
import struct
from html import escape

WIDTH = 720
FONT = "font-family=\"'Noto Sans CJK SC','Source Han Sans SC','PingFang SC','Microsoft YaHei',sans-serif\""
MONO = "font-family=\"'DejaVu Sans Mono',Menlo,Consolas,monospace\""
MIN_FONT = 12
# one colour per field (colour-blind friendly, readable behind black text)
PALETTE = ["#a6cee3", "#b2df8a", "#fdbf6f", "#cab2d6", "#fb9a99", "#ffff99", "#8dd3c7",
           "#bebada", "#fccde5", "#d9d9d9"]


class SVG:
    """An SVG picture: Jupyter shows it (`_repr_svg_`), `str()` is the markup."""

    def __init__(self, markup: str, text: str = "<labkit picture>"):
        self.markup = markup
        self.text = text

    def _repr_svg_(self):
        return self.markup

    def __repr__(self):
        return self.text

    def __str__(self):
        return self.markup


def _text(x, y, s, size=13, anchor="start", mono=False, weight=None, fill="#222"):
    size = max(size, MIN_FONT)
    w = f' font-weight="{weight}"' if weight else ""
    return (f'<text x="{x:.1f}" y="{y:.1f}" font-size="{size}" text-anchor="{anchor}" '
            f'{MONO if mono else FONT}{w} fill="{fill}">{escape(s)}</text>')


def _rect(x, y, w, h, fill="#fff", stroke="#555", rx=6, dash=False):
    d = ' stroke-dasharray="5 4"' if dash else ""
    return (f'<rect x="{x:.1f}" y="{y:.1f}" width="{w:.1f}" height="{h:.1f}" rx="{rx}" '
            f'fill="{fill}" stroke="{stroke}"{d}/>')


def _arrow(x1, y1, x2, y2, color="#555"):
    return (f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" stroke="{color}" '
            f'stroke-width="1.6" marker-end="url(#arrow)"/>')


def _svg(body: list[str], height: float, title: str) -> SVG:
    head = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0f}" '
            f'viewBox="0 0 {WIDTH} {height:.0f}" role="img">'
            f'<title>{escape(title)}</title>'
            '<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" '
            'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" '
            'fill="#555"/></marker></defs>'
            f'<rect width="{WIDTH}" height="{height:.0f}" fill="#fff"/>')
    return SVG(head + "".join(body) + "</svg>", text=f"<{title}>")


def _cjk_width(s: str, size: float) -> float:
    """A generous estimate of a label's drawn width."""
    return sum(size if ord(c) > 0x2E7F else size * 0.62 for c in s)


# ----------------------------------------------------------------- ch6: .msg -> class -> CDR
_PRIM = {"boolean": "?", "octet": "B", "char": "B", "int8": "b", "uint8": "B", "int16": "h",
         "uint16": "H", "int32": "i", "uint32": "I", "int64": "q", "uint64": "Q",
         "float": "f", "double": "d"}


class _Walker:
    """Where each field of a message lies in its CDR bytes (XCDR1 little endian).

    Offsets count from the end of the 4-byte encapsulation header, as CDR's
    alignment does. Supports basic types, strings, nested messages and arrays
    or sequences of those; anything else raises ValueError.
    """

    def __init__(self):
        self.pos = 0
        self.spans: list[tuple[str, int, int, int]] = []   # (field path, start, end, pad before)

    def _align(self, n):
        pad = (-self.pos) % n
        self.pos += pad
        return pad

    def value(self, idl: str, value):
        from labkit.interfaces import is_message
        if idl in _PRIM:
            n = struct.calcsize("<" + _PRIM[idl])
            self._align(n)
            self.pos += n
        elif idl == "string" or idl.startswith("string<"):
            self._align(4)
            self.pos += 4 + len(value.encode("utf-8")) + 1
        elif idl.startswith("sequence<"):
            inner = idl[len("sequence<"):-1].split(",")[0].strip()
            self._align(4)
            self.pos += 4
            for item in value:
                self.value(inner, item)
        elif idl.endswith("]"):
            inner = idl[:idl.index("[")]
            for item in value:
                self.value(inner, item)
        elif is_message(value):
            self.message(value, record=False)
        else:
            raise ValueError(f"cannot lay out field type {idl!r}")

    def message(self, msg, prefix="", record=True):
        for name, idl in msg.get_fields_and_field_types().items():
            value = getattr(msg, name)
            start = self.pos
            pad = 0
            if idl in _PRIM:
                pad = (-self.pos) % struct.calcsize("<" + _PRIM[idl])
            elif idl == "string" or idl.startswith(("string<", "sequence<")):
                pad = (-self.pos) % 4
            self.value(idl, value)
            if record:
                self.spans.append((prefix + name, start + pad, self.pos, pad))


def field_spans(msg):
    """[(field, first byte, end byte)] of a message's CDR bytes, counted from byte 0 of
    the whole serialized message (the 4 header bytes come first)."""
    w = _Walker()
    w.message(msg)
    return [(name, start + 4, end + 4) for name, start, end, _ in w.spans]


def message_on_the_wire(msg, *, definition: str | None = None) -> SVG:
    """The interface file, the generated class and this message's CDR bytes."""
    from labkit import interfaces

    type_name = interfaces.type_name(msg)
    if definition is None:
        definition = interfaces.get_interface_text(type_name)
    data = interfaces.serialize(msg)
    spans = field_spans(msg)
    cls = type(msg)
    colour = {name: PALETTE[i % len(PALETTE)] for i, (name, _, _) in enumerate(spans)}

    body: list[str] = []
    # --- top row: the file and the class ------------------------------------------------
    file_lines = [ln for ln in definition.rstrip("\n").splitlines()]
    fields = list(msg.get_fields_and_field_types().items())
    line_h = 19
    top = 38
    rows = max(len(file_lines), len(fields) + 2)
    box_h = 36 + rows * line_h
    pkg, _, short = type_name.split("/")
    body.append(_text(16, 24, f"① 接口文件 {pkg}/msg/{short}.msg", 14, weight="bold"))
    body.append(_rect(12, top, 300, box_h, fill="#f7f7f7"))
    for i, line in enumerate(file_lines):
        y = top + 26 + i * line_h
        field = line.split("#")[0].split()
        name = field[1] if len(field) >= 2 else None
        if name in colour:
            body.append(_rect(18, y - 14, 288, line_h - 1, fill=colour[name], stroke="none", rx=3))
        body.append(_text(24, y, line[:38], 13, mono=True))
    body.append(_arrow(318, top + box_h / 2, 392, top + box_h / 2))
    body.append(_text(355, top + box_h / 2 - 10, "rosidl", 12, anchor="middle", fill="#555"))
    body.append(_text(355, top + box_h / 2 + 20, "生成", 12, anchor="middle", fill="#555"))

    body.append(_text(402, 24, f"② Python 类 {cls.__module__.rsplit('.', 1)[0]}.{cls.__name__}",
                      14, weight="bold"))
    body.append(_rect(398, top, 310, box_h, fill="#f7f7f7"))
    body.append(_text(410, top + 26, f"class {cls.__name__}:", 13, mono=True))
    for i, (name, idl) in enumerate(fields):
        y = top + 26 + (i + 1) * line_h
        value = getattr(msg, name)
        shown = repr(value)
        if isinstance(value, float) and len(shown) > 10:     # a float32 read back: 7 digits say it
            shown = f"{value:.7g}"
        if len(shown) > 14:
            shown = shown[:13] + "…"
        body.append(_rect(418, y - 14, 284, line_h - 1, fill=colour.get(name, "#eee"),
                          stroke="none", rx=3))
        body.append(_text(424, y, f"{name} = {shown}", 13, mono=True))
        body.append(_text(698, y, idl, 12, anchor="end", fill="#444"))

    # --- bottom: the bytes ----------------------------------------------------------
    y0 = top + box_h + 34
    body.append(_arrow(WIDTH / 2, top + box_h + 4, WIDTH / 2, y0 + 2))
    body.append(_text(WIDTH / 2 + 10, top + box_h + 24,
                      "serialize_message(msg)：按 CDR 编码", 12))
    body.append(_text(16, y0 + 22, f"③ CDR 字节（共 {len(data)} 字节，每格一个字节，十六进制，小端序）",
                      14, weight="bold"))
    per_row = 16
    cell = 40
    x0 = (WIDTH - per_row * cell) / 2
    owner = {}
    for name, start, end in spans:
        for b in range(start, end):
            owner[b] = name
    rows_n = (len(data) + per_row - 1) // per_row
    grid_top = y0 + 36
    row_h = 62
    for r in range(rows_n):
        ry = grid_top + r * row_h
        body.append(_text(x0 - 6, ry + 21, f"{r * per_row:3d}", 12, anchor="end", mono=True,
                          fill="#777"))
        # field labels under runs of bytes
        b = r * per_row
        while b < min(len(data), (r + 1) * per_row):
            who = "header" if b < 4 else owner.get(b, "pad")
            e = b
            while e < min(len(data), (r + 1) * per_row) and (
                    ("header" if e < 4 else owner.get(e, "pad")) == who):
                e += 1
            fill = "#e0e0e0" if who == "header" else colour.get(who, "#ffffff")
            for k in range(b, e):
                cx = x0 + (k - r * per_row) * cell
                body.append(_rect(cx + 1, ry + 2, cell - 2, 28, fill=fill, stroke="#888", rx=2))
                body.append(_text(cx + cell / 2, ry + 21, f"{data[k]:02x}", 13, anchor="middle",
                                  mono=True))
            label = {"header": "封装头", "pad": "对齐"}.get(who, who)
            lx = x0 + (b - r * per_row) * cell
            width = (e - b) * cell
            if _cjk_width(label, 12) > width - 2:
                label = label[: max(1, int((width - 4) / 8))] + ("…" if width < 80 else "")
            body.append(_text(lx + width / 2, ry + 47, label, 12, anchor="middle", fill="#333"))
            b = e
    height = grid_top + rows_n * row_h + 8
    return _svg(body, height, f"{type_name}: .msg -> Python class -> CDR bytes")


# ----------------------------------------------------------------- ch8: overlays
def _workspace_layers():
    """[(shown install folder, [packages])] of the sourced workspaces, last sourced first."""
    from labkit.ament import files, source
    layers = []
    for install_dir in reversed(source.sourced()):
        names = source.packages_in(install_dir)
        layers.append((files.display(install_dir), names))
    return layers


UNDERLAY_EXAMPLES = ("rclpy", "std_msgs", "geometry_msgs", "turtlesim", "ros2cli", "...")


def workspace_overlays(*, workspace_tree: bool = True) -> SVG:
    """The sourced workspaces stacked on /opt/ros/humble, searched top to bottom."""
    from labkit.ament import files, index

    layers = _workspace_layers()
    body: list[str] = []
    y = 14
    left = 14
    right = WIDTH - 14
    stack_right = right if not workspace_tree else 470
    body.append(_text(left, y + 14, "source 的顺序决定查找的顺序：后 source 的在上层，先被找到", 14,
                      weight="bold"))
    y += 34
    all_layers = [(shown, names, "overlay") for shown, names in layers]
    all_layers.append((index.SHOWN_INSTALL_PREFIX, list(UNDERLAY_EXAMPLES), "underlay"))
    box_h = 74
    for i, (shown, names, kind) in enumerate(all_layers):
        fill = "#e8f4e8" if kind == "overlay" else "#e8eef8"
        body.append(_rect(left + 40, y, stack_right - left - 40, box_h, fill=fill))
        label = "overlay（叠加层）" if kind == "overlay" else "underlay（底层）"
        body.append(_text(left + 52, y + 22, f"{label}  {shown}", 13, weight="bold"))
        width = stack_right - left - 64
        shown_names = list(names)
        while len(shown_names) > 1 and _cjk_width(", ".join(shown_names + ["…"]), 13) > width:
            shown_names.pop()
        if len(shown_names) < len(names):
            shown_names.append("…")
        text = ", ".join(shown_names) if names else "（空）"
        body.append(_text(left + 52, y + 50, text, 13, mono=True))
        if i < len(all_layers) - 1:
            body.append(f'<line x1="{left + 20}" y1="{y + box_h / 2}" x2="{left + 20}" '
                        f'y2="{y + box_h * 1.5 + 10}" stroke="#555" stroke-width="1.6" '
                        'marker-end="url(#arrow)"/>')
        y += box_h + 10
    # AMENT_PREFIX_PATH as `echo $AMENT_PREFIX_PATH` prints it, wrapped after a ':'
    lines, line = [], "AMENT_PREFIX_PATH="
    paths = index.search_paths_shown()
    for k, p in enumerate(paths):
        piece = p + (":" if k < len(paths) - 1 else "")
        if len(line) + len(piece) > 88 and not line.endswith("="):
            lines.append(line)
            line = "  "
        line += piece
    lines.append(line)
    for k, text in enumerate(lines):
        body.append(_text(left, y + 18 + k * 18, text, 12, mono=True, fill="#333"))
    y += (len(lines) - 1) * 18
    body.append(_text(left, y + 40, "ros2 run / ros2 pkg / import 从上往下找，先找到的同名功能包生效", 13))
    height = y + 54
    if workspace_tree:
        tx = stack_right + 16
        body.append(_rect(tx, 48, right - tx, box_h * 2 + 10, fill="#fafafa", dash=True))
        ws = _workspace_root(layers)
        body.append(_text(tx + 12, 72, (ws or "~/ros2_ws") + "/", 13, mono=True, weight="bold"))
        entries = [("src/", "你写的源码", "#333"), ("build/", "中间文件", "#777"),
                   ("install/", "装好的功能包", "#2a7a2a"), ("log/", "colcon 日志", "#777")]
        for k, (name, note, color) in enumerate(entries):
            ey = 98 + k * 24
            body.append(_text(tx + 24, ey, name, 13, mono=True, fill=color, weight="bold"))
            body.append(_text(tx + 110, ey, note, 12, fill="#444"))
        body.append(_text(tx + 12, 98 + 4 * 24 + 2, "colcon build 生成后三个", 12, fill="#444"))
        height = max(height, 48 + box_h * 2 + 20)
    return _svg(body, height, "workspace overlays: install/ on top of /opt/ros/humble")


def _workspace_root(layers):
    if not layers:
        return None
    shown = layers[0][0]
    return shown[:-len("/install")] if shown.endswith("/install") else os.path.dirname(shown)


# ----------------------------------------------------------------- ch9: name expansion
KIND_LABEL = {"relative": "相对名字", "private": "私有名字", "absolute": "绝对名字"}
SEG_COLOUR = {"ns": "#a6cee3", "node": "#fdbf6f", "name": "#b2df8a"}


def _kind(name: str) -> str:
    if name.startswith("/"):
        return "absolute"
    if name.startswith("~"):
        return "private"
    return "relative"


def name_expansion(node: str, namespace: str, names, *, remaps=()) -> SVG:
    """How each name a node uses becomes a full name (rcl_expand_topic_name, then remapping).

    `remaps` are `old:=new` rules as `--ros-args -r` takes them; a remapped row shows
    the rule and the final name.
    """
    from labkit.graph import arguments, names as rcl_names

    rules = arguments.parse(["--ros-args"] + [x for r in remaps for x in ("-r", r)]).remaps
    original = node
    node = arguments.remap_node_name([rules], node)
    namespace = rcl_names.normalize_namespace(arguments.remap_namespace([rules], original, namespace))
    body: list[str] = []
    fq = rcl_names.fully_qualified_node_name(namespace, node)
    top = 0
    if remaps:
        body.append(_text(14, 22, "ros2 run ... --ros-args " + " ".join("-r " + r for r in remaps),
                          13, mono=True, fill="#a02020"))
        top = 24
    body.append(_text(14, top + 24, f"节点 {node}，命名空间 {namespace}，完整节点名 {fq}", 14,
                      weight="bold"))
    lx = 14
    legend = [("ns", "命名空间"), ("node", "节点名"), ("name", "代码里写的名字")]
    for key, text in legend:
        body.append(_rect(lx, top + 36, 16, 16, fill=SEG_COLOUR[key], stroke="#888", rx=2))
        body.append(_text(lx + 22, top + 49, text, 12))
        lx += 30 + _cjk_width(text, 12) + 20
    y = top + 70
    topic_rules = [r for r in rules if r.kind & arguments.TOPIC]
    row_h = 84 if topic_rules else 62
    for name in names:
        kind = _kind(name)
        full = rcl_names.expand_topic_name(name, node, namespace)
        body.append(_rect(10, y, WIDTH - 20, row_h - 8, fill="#fafafa", stroke="#ccc"))
        body.append(_text(22, y + 22, KIND_LABEL[kind], 13, weight="bold"))
        body.append(_text(22, y + 44, name, 14, mono=True))
        body.append(_arrow(200, y + 27, 250, y + 27))
        # coloured segments of the result
        segments = []
        ns_part = namespace.rstrip("/")
        if kind == "absolute":
            segments = [("name", full)]
        elif kind == "private":
            segments = [("ns", ns_part), ("node", "/" + node), ("name", name[1:])]
        else:
            segments = [("ns", ns_part), ("name", "/" + name)]
        sx = 262
        for key, text in segments:
            if not text:
                continue
            w = len(text) * 8.6 + 8
            body.append(_rect(sx, y + 12, w, 26, fill=SEG_COLOUR[key], stroke="#888", rx=3))
            body.append(_text(sx + 4, y + 30, text, 14, mono=True))
            sx += w
        if topic_rules:
            final = arguments.remap_name([rules], arguments.TOPIC, full, node, namespace)
            if final != full:
                body.append(_text(262, y + 62, f"再经 -r 重映射 → {final}", 13, mono=False,
                                  fill="#a02020"))
        y += row_h
    return _svg(body, y + 4, f"name expansion for {fq}")
