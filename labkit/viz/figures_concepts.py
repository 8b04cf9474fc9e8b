"""Concept pictures for the chapters that had none but turtle canvases.

Each function draws from what labkit really has at that moment (the folders of a
workspace, the interface files of a package, a node's own endpoints, the ament
prefixes, rosdep's rule tables, ros2doctor's checks, the DDS port formula) and
returns an `SVG` 720 px wide, the book's column, no label under 12 px. The SVG is
both faces at once: JupyterLab shows it live, the HTML book stores it as it is.

- `installed_layout()`              ch01: what `apt install ros-humble-desktop` puts where
- `parameter_services(node)`        ch07: the six parameter services every node carries
- `workspace_layout(ws)`            ch11: src / build / install / log, and who makes each
- `rosidl_outputs(package_dir)`     ch12: what rosidl generates from .msg/.srv/.action
- `node_anatomy(node)`              ch13: init, node, callbacks, spin, Ctrl+C, shutdown
- `package_lookup(package)`         ch16: overlay and underlay: which prefix wins
- `rosdep_resolution(paths)`        ch17: package.xml keys -> rules -> apt packages
- `doctor_checks()`                 ch19: the five checks of `ros2 doctor` and their result
- `colcon_test_flow(ws)`            ch25: colcon test -> pytest -> results -> test-result
- `dds_discovery(domain_id)`        connect_real_ros: discovery, domains, what crosses the wire
"""
from __future__ import annotations

import os
import re

from labkit.viz.figures_part1 import SVG, WIDTH, _arrow, _cjk_width, _rect, _svg, _text

GREEN, BLUE, GREY, ORANGE, RED = "#e8f4e8", "#e8eef8", "#f2f2f2", "#fdf0dc", "#fbe3e3"
LEFT, RIGHT = 14, WIDTH - 14


def _fit(s: str, width: float, size: float) -> str:
    """s, cut with an ellipsis so that it fits `width` px at `size`."""
    if _cjk_width(s, size) <= width:
        return s
    while s and _cjk_width(s + "…", size) > width:
        s = s[:-1]
    return s + "…"


def _box(x, y, w, h, title, lines=(), fill=BLUE, size=13, mono_lines=True, dash=False,
         title_mono=False):
    """A box with a bold title and lines below it (each cut to the box's width)."""
    body = [_rect(x, y, w, h, fill=fill, dash=dash),
            _text(x + 10, y + 20, _fit(title, w - 20, size), size, weight="bold",
                  mono=title_mono)]
    for k, line in enumerate(lines):
        body.append(_text(x + 10, y + 40 + k * 18, _fit(line, w - 20, 12), 12,
                          mono=mono_lines, fill="#333"))
    return body


def _heading(y, text):
    return _text(LEFT, y, text, 14, weight="bold")


# ----------------------------------------------------------------- ch01: what is installed where
def installed_layout() -> SVG:
    """/opt/ros/humble as apt lays it out, with labkit's own counts of what is in it."""
    from labkit import plugins
    from labkit.ament import index

    plugins.register_all()          # every room's executables and packages, as ros2 pkg sees them
    names = index.bundled_package_names()
    from labkit import executables

    execs = len(executables.executables())
    body = [_heading(24, "apt install ros-humble-desktop 之后，东西都在哪里")]
    y = 44
    # top: the apt side and the shell side
    half = (RIGHT - LEFT - 16) / 2
    body += _box(LEFT, y, half, 100, "apt 的配置（只做一次）", [
        "/etc/apt/sources.list.d/ros2.list",
        "/usr/share/keyrings/ros-archive-keyring.gpg",
        "sudo apt update && sudo apt install ..."], fill=GREY)
    body += _box(LEFT + half + 16, y, half, 100, "~/.bashrc（每开一个终端都执行）", [
        "source /opt/ros/humble/setup.bash",
        "→ 之后 ros2 命令、import rclpy 才找得到"], fill=ORANGE)
    body.append(_arrow(LEFT + half / 2, y + 100, LEFT + half / 2, y + 116))
    body.append(_arrow(LEFT + half * 1.5 + 16, y + 100, LEFT + half * 1.5 + 16, y + 116))
    y += 116
    # below: the install prefix
    x = LEFT
    w = RIGHT - x
    body.append(_rect(x, y, w, 216, fill=GREEN))
    body.append(_text(x + 10, y + 20, "/opt/ros/humble/   （底层 underlay）", 13, weight="bold",
                      mono=False))
    rows = [
        ("setup.bash", "设置环境变量：PATH、PYTHONPATH、AMENT_PREFIX_PATH…"),
        ("bin/", "ros2 这样的命令行工具"),
        ("lib/<功能包>/", "ros2 run 找的可执行文件（turtlesim_node…）"),
        ("lib/python3.10/", "rclpy、消息类的 Python 代码（site-packages）"),
        ("share/<功能包>/", "package.xml、msg/srv/action、launch 文件"),
        ("share/ament_index/", "功能包索引：ros2 pkg list 读这里"),
        ("include/、lib*.so", "C++ 头文件和库（rclcpp 节点用）"),
    ]
    for k, (name, note) in enumerate(rows):
        ry = y + 46 + k * 24
        body.append(_text(x + 14, ry, name, 12, mono=True, weight="bold", fill="#1d5a1d"))
        body.append(_text(x + 190, ry, _fit(note, w - 200, 12), 12, fill="#333"))
    y += 232
    count = f"本书的 labkit 里，这个前缀下登记了 {len(names)} 个功能包"
    if execs:
        count += f"、{execs} 个可执行文件"
    body.append(_text(LEFT, y + 14, count + "：和真机一样，靠 ament 索引找到它们。", 13))
    return _svg(body, y + 30, "ch01: what apt installs where")


# ----------------------------------------------------------------- ch07: parameter services
PARAM_SERVICES = [
    ("describe_parameters", "DescribeParameters", "ros2 param describe"),
    ("get_parameter_types", "GetParameterTypes", "（类型查询）"),
    ("get_parameters", "GetParameters", "ros2 param get"),
    ("list_parameters", "ListParameters", "ros2 param list"),
    ("set_parameters", "SetParameters", "ros2 param set / load"),
    ("set_parameters_atomically", "SetParametersAtomically", "（一次全改或全不改）"),
]


def parameter_services(node_name: str) -> SVG:
    """The node's own parameter services, read from the live graph, and who calls them."""
    from labkit.commands import CliNode

    name = node_name if node_name.startswith("/") else "/" + node_name
    ns, _, base = name.rpartition("/")
    found = {}
    with CliNode("_labkit_figure") as probe:   # hidden, gone when the picture is drawn
        try:
            for srv, types in probe.get_service_names_and_types_by_node(base, ns or "/"):
                found[srv] = types[0] if types else ""
        except Exception:
            found = {}
    body = [_heading(24, f"每个节点都自带 6 个参数服务：{name} 的（从计算图里读出来的）")]
    y = 44
    node_w = 160
    body += _box(LEFT, y + 60, node_w, 96, name, ["参数存在节点身上", "别人通过服务读写"],
                 fill=ORANGE, mono_lines=False, title_mono=True)
    x = LEFT + node_w + 24
    w = RIGHT - x
    row = 30
    for k, (srv, typ, cli) in enumerate(PARAM_SERVICES):
        full = f"{name}/{srv}"
        there = full in found
        ry = y + k * row
        body.append(_rect(x, ry, w, row - 6, fill=GREEN if there else RED, rx=4))
        body.append(_text(x + 8, ry + 17, _fit(full, 330, 12), 12, mono=True,
                          fill="#222" if there else "#a00"))
        body.append(_text(x + 346, ry + 17, _fit(cli if there else "（没有找到）", w - 352, 12),
                          12, fill="#444"))
        body.append(f'<line x1="{LEFT + node_w}" y1="{y + 108}" x2="{x}" y2="{ry + 12}" '
                    'stroke="#999" stroke-width="1"/>')
    y += len(PARAM_SERVICES) * row + 12
    body.append(_text(LEFT, y + 14, "类型都在 rcl_interfaces/srv/ 里；参数一变，节点还会在话题 "
                      "/parameter_events 上广播一条消息。", 13))
    body.append(_text(LEFT, y + 36, "ros2 param 命令自己就是一个客户端：它调用的正是上面这些服务。",
                      13))
    return _svg(body, y + 52, f"ch07: the parameter services of {name}")


# ----------------------------------------------------------------- ch11: workspace layout
WS_FOLDERS = [
    ("src", "你写的源码：每个功能包一个文件夹", "你自己建（mkdir -p src）", "#333"),
    ("build", "每个包的中间文件（CMake 缓存、复制的 Python 代码）", "colcon build 生成", "#777"),
    ("install", "每个包装好的结果 + setup.bash：source 的就是它", "colcon build 生成", "#1d5a1d"),
    ("log", "每次 colcon 命令的日志，latest 指向最近一次", "colcon 每次运行都写", "#777"),
]


def workspace_layout(ws: str = "~/ros2_ws") -> SVG:
    """A workspace's four folders as they are on disk now, and who makes each."""
    from labkit.ament import files

    root = files.expand(ws)
    shown = files.display(root)
    body = [_heading(24, f"工作空间 {shown}/ 的四个文件夹（按磁盘上现在的样子画）")]
    y = 44
    for k, (name, what, who, colour) in enumerate(WS_FOLDERS):
        path = os.path.join(root, name)
        exists = os.path.isdir(path)
        try:
            inside = sorted(e for e in os.listdir(path) if not e.startswith(".")) if exists else []
        except OSError:
            inside = []
        h = 62
        body.append(_rect(LEFT, y, RIGHT - LEFT, h, fill=GREEN if exists else GREY,
                          dash=not exists))
        body.append(_text(LEFT + 12, y + 22, name + "/", 14, mono=True, weight="bold",
                          fill=colour if exists else "#999"))
        body.append(_text(LEFT + 110, y + 22, what, 13))
        body.append(_text(RIGHT - 12, y + 22, who, 12, anchor="end", fill="#555"))
        if exists:
            text = "  ".join(e + ("/" if os.path.isdir(os.path.join(path, e)) else "")
                             for e in inside) or "（空）"
        else:
            text = "还没有：第一次 colcon build 时出现" if name != "src" else "还没有"
        body.append(_text(LEFT + 110, y + 46, _fit(text, RIGHT - LEFT - 130, 12), 12,
                          mono=exists, fill="#333" if exists else "#888"))
        y += h + 8
    body.append(_text(LEFT, y + 16, "只有 src/ 要放进版本管理（git）；build/ install/ log/ "
                      "随时可以删掉，再 colcon build 一次就回来了。", 13))
    body.append(_text(LEFT, y + 38, "命令都在工作空间顶层执行：在 src/ 里 colcon build，"
                      "会在 src/ 里面再长出一套 build/ install/ log/。", 13))
    return _svg(body, y + 54, f"ch11: the folders of {shown}")


# ----------------------------------------------------------------- ch12: what rosidl generates
def _snake(name: str) -> str:
    """rosidl's camel-case to snake-case (FaceResult -> face_result, IMUData -> imu_data)."""
    s = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1_\2", name)
    s = re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", s)
    return s.lower()


def rosidl_outputs(package_dir: str) -> SVG:
    """The package's interface files and what rosidl makes of each on Humble, and where."""
    from labkit.ament import files

    root = files.expand(package_dir)
    pkg = os.path.basename(root.rstrip("/\\"))
    specs = []
    for kind in ("msg", "srv", "action"):
        folder = os.path.join(root, kind)
        if os.path.isdir(folder):
            specs += [(kind, f[: -len(kind) - 1]) for f in sorted(os.listdir(folder))
                      if f.endswith("." + kind)]
    body = [_heading(24, f"rosidl 从 {pkg} 的接口文件生成了什么，装到 install/{pkg}/ 的哪里")]
    y = 44
    parts = {"msg": [], "srv": ["_Request", "_Response"],
             "action": ["_Goal", "_Result", "_Feedback", "_SendGoal", "_GetResult",
                        "_FeedbackMessage"]}
    for kind, stem in specs:
        classes = [stem] + [stem + p for p in parts[kind]]
        snake = _snake(stem)
        outs = [
            ("Python", f"local/lib/python3.10/dist-packages/{pkg}/{kind}/_{snake}.py"),
            ("C++", f"include/{pkg}/{pkg}/{kind}/{snake}.hpp"),
            ("C", f"include/{pkg}/{pkg}/{kind}/{snake}.h"),
            ("定义", f"share/{pkg}/{kind}/{stem}.{kind} 和 {stem}.idl"),
        ]
        h = 30 + 20 * len(outs) + 28
        body.append(_rect(LEFT, y, RIGHT - LEFT, h, fill=GREEN))
        body.append(_rect(LEFT, y, RIGHT - LEFT, 28, fill=ORANGE))
        body.append(_text(LEFT + 10, y + 19, f"{kind}/{stem}.{kind}", 13, mono=True,
                          weight="bold"))
        body.append(_text(LEFT + 230, y + 19, _fit("→ 类 " + ", ".join(classes),
                                                  RIGHT - LEFT - 240, 12), 12, mono=True))
        for k, (lang, path) in enumerate(outs):
            ry = y + 46 + k * 20
            body.append(_text(LEFT + 10, ry, lang, 12, weight="bold"))
            body.append(_text(LEFT + 64, ry, _fit(path, RIGHT - LEFT - 74, 12), 12, mono=True,
                              fill="#333"))
        body.append(_text(LEFT + 10, y + h - 8, f"from {pkg}.{kind} import {stem}", 12,
                          mono=True, fill="#1d5a1d"))
        y += h + 10
    if not specs:
        body.append(_text(LEFT, y + 16, "（这个功能包里还没有接口文件）", 13, fill="#888"))
        y += 24
    body.append(_text(LEFT, y + 16, "路径相对 install/" + pkg + "/；生成的中间代码在 build/"
                      + pkg + "/rosidl_generator_*/。", 13))
    body.append(_text(LEFT, y + 38, "另有类型支持库 lib/lib" + pkg + "__rosidl_typesupport_*.so："
                      "消息在 DDS 上的样子由它们决定。", 13))
    return _svg(body, y + 54, f"ch12: what rosidl generates for {pkg}")


# ----------------------------------------------------------------- ch13: a node's anatomy
def _live_node(name: str):
    """The rclpy Node object of a node running in this kernel, found by its full name."""
    from labkit.graph.registry import GRAPH

    full = name if name.startswith("/") else "/" + name
    for info in list(GRAPH.nodes):
        if info.fqn == full and info.owner is not None:
            return info.owner
    raise LookupError(f"Node not found: {full}")


def node_anatomy(node) -> SVG:
    """The life of a node program, with this node's own timers and endpoints in the middle.

    `node` is an rclpy Node, or the full name of a node running in this kernel (one started
    with `%ros2 run` lives in its own process thread; its object is found in the graph)."""
    if isinstance(node, str):
        node = _live_node(node)
    name = node.get_fully_qualified_name()
    subs = [s.topic_name for s in getattr(node, "subscriptions", [])]
    pubs = [p.topic_name for p in getattr(node, "publishers", [])
            if p.topic_name not in ("/rosout", "/parameter_events")]
    timers = [t.timer_period_ns / 1e9 for t in getattr(node, "timers", [])]
    services = [s.srv_name for s in getattr(node, "services", [])
                if not re.search(r"/(describe|get|list|set)_parameter", s.srv_name)]
    body = [_heading(24, f"一个节点程序的一生（中间是 {name} 此刻真有的东西）")]
    y = 44
    steps = [
        ("rclpy.init(args=args)", "连上 ROS 2：解析 --ros-args，建好默认上下文", BLUE),
        (f"Node('{name.rsplit('/', 1)[-1]}')", "创建节点：在构造函数里建定时器、发布者、订阅者…", BLUE),
    ]
    for code, note, fill in steps:
        body.append(_rect(LEFT, y, RIGHT - LEFT, 34, fill=fill))
        body.append(_text(LEFT + 10, y + 22, code, 13, mono=True, weight="bold"))
        body.append(_text(LEFT + 250, y + 22, note, 12, fill="#333"))
        body.append(_arrow(LEFT + 40, y + 34, LEFT + 40, y + 46))
        y += 46
    # the spin loop with the node's callbacks
    items = ([f"定时器 每 {p:g} 秒" for p in timers] + [f"订阅 {t}" for t in subs]
             + [f"服务 {s}" for s in services])
    h = 62 + 18 * max(2, min(len(items), 5))
    body.append(_rect(LEFT, y, RIGHT - LEFT, h, fill=GREEN))
    body.append(_text(LEFT + 10, y + 22, "rclpy.spin(node)", 13, mono=True, weight="bold"))
    body.append(_text(LEFT + 250, y + 22, "循环：等事件 → 调用对应的回调 → 再等（程序停在这一行）",
                      12, fill="#333"))
    for k, item in enumerate(items[:5]):
        body.append(_text(LEFT + 40, y + 46 + k * 18, "→ " + item, 12, mono=True, fill="#1d5a1d"))
    if not items:
        body.append(_text(LEFT + 40, y + 46, "（这个节点没有定时器、订阅或服务：spin 只会一直等）",
                          12, fill="#888"))
    if pubs:
        body.append(_text(LEFT + 250, y + 46, _fit("回调里可以发布：" + ", ".join(pubs),
                                                   RIGHT - LEFT - 262, 12), 12, fill="#333"))
    y += h
    body.append(_arrow(LEFT + 40, y, LEFT + 40, y + 14))
    y += 14
    body.append(_rect(LEFT, y, RIGHT - LEFT, 52, fill=RED))
    body.append(_text(LEFT + 10, y + 22, "Ctrl+C", 13, mono=True, weight="bold"))
    body.append(_text(LEFT + 250, y + 22, "spin 抛出 KeyboardInterrupt（Humble 会打印 traceback）",
                      12, fill="#333"))
    body.append(_text(LEFT + 250, y + 42, "不捕获它，后面两行就不会执行", 12, fill="#a00"))
    body.append(_arrow(LEFT + 40, y + 52, LEFT + 40, y + 66))
    y += 66
    body.append(_rect(LEFT, y, RIGHT - LEFT, 34, fill=GREY))
    body.append(_text(LEFT + 10, y + 22, "node.destroy_node(); rclpy.try_shutdown()", 13,
                      mono=True, weight="bold"))
    body.append(_text(RIGHT - 12, y + 22, "放在 except / finally 里", 12, anchor="end",
                      fill="#333"))
    y += 34
    return _svg(body, y + 12, f"ch13: the anatomy of {name}")


# ----------------------------------------------------------------- ch16: which prefix wins
def package_lookup(package: str) -> SVG:
    """AMENT_PREFIX_PATH from top to bottom, and the first prefix that has the package."""
    from labkit.ament import index

    from labkit.ament import files

    body = [_heading(24, f"找 {package}：按 AMENT_PREFIX_PATH 从前往后，第一个有它的前缀胜出")]
    y = 44
    winner = None
    merged = [(files.display(p), os.path.isfile(os.path.join(p, index.RESOURCE_INDEX,
                                                             "packages", package)))
              for p in index.prefixes()]
    merged = [(shown, has) for shown, has in merged if shown != index.SHOWN_INSTALL_PREFIX]
    merged.append((index.SHOWN_INSTALL_PREFIX, package in index.bundled_package_names()))
    for k, (shown_prefix, has) in enumerate(merged):
        if has and winner is None:
            winner = k
            fill, note, colour = GREEN, "✔ 用这里的（ros2 run、ros2 pkg、import 都是）", "#1d5a1d"
        elif has:
            fill, note, colour = GREY, "也有，但被上面的遮住了：不会被用到", "#777"
        else:
            fill, note, colour = "#fff", "没有这个包，接着往下找", "#999"
        body.append(_rect(LEFT + 30, y, RIGHT - LEFT - 30, 48, fill=fill, dash=not has))
        body.append(_text(LEFT, y + 22, f"{k + 1}", 13, weight="bold"))
        body.append(_text(LEFT + 40, y + 20, _fit(shown_prefix, RIGHT - LEFT - 60, 12), 12,
                          mono=True))
        body.append(_text(LEFT + 40, y + 39, note, 12, fill=colour))
        y += 56
    if winner is None:
        body.append(_text(LEFT, y + 14, f"哪个前缀都没有 {package}：ros2 run 会说 "
                          f"Package '{package}' not found", 13, fill="#a00"))
        y += 22
    body.append(_text(LEFT, y + 14, "叠加层（overlay）的包遮住底层（underlay）的同名包，"
                      "而且是整个包一起遮住：", 13))
    body.append(_text(LEFT, y + 36, "可执行文件、launch 文件、接口都只从胜出的那个前缀里找。", 13))
    return _svg(body, y + 52, f"ch16: which prefix provides {package}")


# ----------------------------------------------------------------- ch17: rosdep resolution
def rosdep_resolution(paths) -> SVG:
    """package.xml keys -> rosdep rules -> the apt (or pip) packages, from labkit's tables."""
    from labkit.ament import files, rosdep

    if isinstance(paths, str):
        paths = [paths]
    keys = []
    try:
        for _pkg, pkg_keys in rosdep.package_keys([files.expand(p) for p in paths]):
            keys += [key for key in pkg_keys if key not in keys]
    except Exception:
        keys = []
    _, ros = rosdep.tables()
    body = [_heading(24, "rosdep：package.xml 里的键 → 规则 → 系统软件包")]
    y = 44
    body.append(_text(LEFT, y + 10, "package.xml 里的键", 12, weight="bold"))
    body.append(_text(224, y + 10, "rosdep 的规则（查表）", 12, weight="bold"))
    body.append(_text(414, y + 10, "Ubuntu 22.04（jammy）上装的", 12, weight="bold"))
    y += 22
    for key in keys[:10]:
        rule = rosdep.resolve(key)
        if rule is None:
            where, target, fill = "找不到规则", "ERROR: Cannot locate rosdep definition", RED
        elif key in ros and key not in rosdep.tables()[0]:
            where, target, fill = "ROS 功能包：humble.yaml", f"apt: {rule[1][0]}", GREEN
        else:
            kind, pkgs = rule
            source = "python.yaml" if kind == "pip" or key.startswith("python") else "base.yaml"
            where, target, fill = f"系统依赖：{source}", f"{kind}: {' '.join(pkgs)}", BLUE
        body.append(_rect(LEFT, y, 186, 28, fill=ORANGE, rx=4))
        body.append(_text(LEFT + 8, y + 19, _fit(key, 172, 12), 12, mono=True))
        body.append(_arrow(LEFT + 186, y + 14, 220, y + 14))
        body.append(_rect(224, y, 166, 28, fill=GREY, rx=4))
        body.append(_text(232, y + 19, _fit(where, 152, 12), 12))
        body.append(_arrow(390, y + 14, 410, y + 14))
        body.append(_rect(414, y, RIGHT - 414, 28, fill=fill, rx=4))
        body.append(_text(422, y + 19, _fit(target, RIGHT - 430, 12), 12, mono=True))
        y += 34
    if len(keys) > 10:
        body.append(_text(LEFT, y + 12, f"……另有 {len(keys) - 10} 个键", 12, fill="#555"))
        y += 20
    if not keys:
        body.append(_text(LEFT, y + 12, "（这里的 package.xml 没有依赖键）", 12, fill="#888"))
        y += 20
    body.append(_text(LEFT, y + 16, "规则表来自 rosdistro 仓库：sudo rosdep init 写下它们的地址，"
                      "rosdep update 把它们下载到本地缓存。", 13))
    return _svg(body, y + 32, "ch17: rosdep keys to system packages")


# ----------------------------------------------------------------- ch19: what doctor checks
DOCTOR_CHECKS = [
    ("NetworkCheck", "网络", "有没有可用的网卡、回环和多播"),
    ("PackageCheck", "功能包", "装的功能包是不是发行版里最新的版本"),
    ("PlatformCheck", "平台", "ROS_DISTRO 和系统是否相配、发行版是否还受支持"),
    ("QoSCompatibilityCheck", "QoS", "同一话题上有没有 QoS 不兼容的发布者和订阅者"),
    ("TopicCheck", "话题", "有没有只有发布者或只有订阅者的话题"),
]


def doctor_checks() -> SVG:
    """ros2doctor's five checks, each run now on the live graph: passed or failed."""
    from labkit.doctor import api
    from labkit.doctor.network import NetworkCheck
    from labkit.doctor.package import PackageCheck
    from labkit.doctor.platform import PlatformCheck
    from labkit.doctor.qos_compatibility import QoSCompatibilityCheck
    from labkit.doctor.topic import TopicCheck

    classes = {"NetworkCheck": NetworkCheck, "PackageCheck": PackageCheck,
               "PlatformCheck": PlatformCheck, "QoSCompatibilityCheck": QoSCompatibilityCheck,
               "TopicCheck": TopicCheck}
    from labkit.commands import CliNode

    results = {}
    with CliNode("_labkit_figure") as node:    # as `ros2 doctor` does: hidden, gone after
        doctor = api.Doctor(node, lambda *a, **k: None)
        for name, _, _ in DOCTOR_CHECKS:
            try:
                result = classes[name]().check(doctor)
                results[name] = (result.error, result.warning)
            except Exception:
                results[name] = (1, 0)
    body = [_heading(24, "ros2 doctor 跑的 5 项检查（此刻在这个计算图上跑的结果）")]
    y = 44
    failed = 0
    for name, label, what in DOCTOR_CHECKS:
        bad, warn = results[name]
        failed += bool(bad)
        if bad:
            fill, verdict = RED, "失败"
        elif warn:
            fill, verdict = ORANGE, "有警告"
        else:
            fill, verdict = GREEN, "通过"
        body.append(_rect(LEFT, y, RIGHT - LEFT, 34, fill=fill))
        body.append(_text(LEFT + 10, y + 22, label, 13, weight="bold"))
        body.append(_text(LEFT + 70, y + 22, name, 12, mono=True, fill="#555"))
        body.append(_text(LEFT + 260, y + 22, _fit(what, 340, 12), 12))
        body.append(_text(RIGHT - 10, y + 22, verdict, 13, anchor="end", weight="bold"))
        y += 42
    total = len(DOCTOR_CHECKS)
    summary = (f"All {total} checks passed" if not failed
               else f"{failed}/{total} check(s) failed")
    body.append(_text(LEFT, y + 14, f"ros2 doctor 的最后一行就是：{summary}；"
                      "--report（-r）另外打印每一类的详细报告。", 13))
    return _svg(body, y + 30, "ch19: the checks of ros2 doctor")


# ----------------------------------------------------------------- ch25: colcon test
def colcon_test_flow(ws: str = "~/ros2_ws") -> SVG:
    """colcon test: each package's tests run by pytest, results into build/, read back."""
    from labkit.ament import files

    root = files.expand(ws)
    src = os.path.join(root, "src")
    packages = []
    if os.path.isdir(src):
        for dirpath, dirnames, filenames in os.walk(src):
            dirnames[:] = [d for d in dirnames if not d.startswith(".")]
            if "package.xml" in filenames:
                tests = os.path.join(dirpath, "test")
                names = sorted(f for f in os.listdir(tests) if f.startswith("test_")
                               and f.endswith(".py")) if os.path.isdir(tests) else []
                packages.append((os.path.basename(dirpath), names))
                dirnames[:] = []
    packages.sort()
    body = [_heading(24, "colcon test 怎么跑测试、结果去了哪里")]
    y = 44
    body.append(_rect(LEFT, y, 150, 40, fill=ORANGE))
    body.append(_text(LEFT + 10, y + 25, "colcon test", 13, mono=True, weight="bold"))
    x = LEFT + 190
    w = RIGHT - x
    for name, tests in packages[:4] or [("（工作空间里还没有功能包）", [])]:
        h = 48 + 18 * min(len(tests), 4)
        body.append(_arrow(LEFT + 150, 64, x, y + 20))
        body.append(_rect(x, y, w, h, fill=BLUE))
        body.append(_text(x + 10, y + 20, _fit(f"{name}：python3 -m pytest test/", w - 20, 13), 13,
                          weight="bold"))
        for k, t in enumerate(tests[:4]):
            body.append(_text(x + 24, y + 40 + k * 18, t, 12, mono=True, fill="#333"))
        body.append(_text(x + 10, y + h - 8, _fit(f"→ build/{name}/pytest.xml（JUnit XML）",
                                                  w - 20, 12), 12, mono=True, fill="#1d5a1d"))
        y += h + 8
    y += 6
    body.append(_rect(LEFT, y, RIGHT - LEFT, 40, fill=GREEN))
    body.append(_text(LEFT + 10, y + 25, "colcon test-result --all --verbose", 13, mono=True,
                      weight="bold"))
    body.append(_text(RIGHT - 10, y + 25, "读 build/ 里的 XML，汇总：N tests, E errors, F failures",
                      12, anchor="end"))
    y += 48
    body.append(_text(LEFT, y + 14, "ament_python 包的 test/ 里默认就有 test_copyright、test_flake8、"
                      "test_pep257 三个风格检查。", 13))
    body.append(_text(LEFT, y + 36, "colcon test 自己只说包的成败；每个测试的细节要看 test-result "
                      "或 log/latest_test/。", 13))
    return _svg(body, y + 52, "ch25: how colcon test runs and collects tests")


# ----------------------------------------------------------------- connect_real_ros: DDS
def dds_ports(domain_id: int, participant_id: int = 0) -> dict:
    """The RTPS well-known ports (DDSI-RTPS 9.6.1.1, default PB 7400, DG 250, PG 2)."""
    pb, dg, pg, d0, d1, d2, d3 = 7400, 250, 2, 0, 10, 1, 11
    return {"discovery multicast": pb + dg * domain_id + d0,
            "discovery unicast": pb + dg * domain_id + d1 + pg * participant_id,
            "user multicast": pb + dg * domain_id + d2,
            "user unicast": pb + dg * domain_id + d3 + pg * participant_id}


def dds_discovery(domain_id: int = 0, *, localhost_only: bool = True) -> SVG:
    """Two computers, processes on a domain, and what goes over the wire between them."""
    ports = dds_ports(domain_id)
    body = [_heading(24, f"DDS 发现：同一个域（ROS_DOMAIN_ID={domain_id}）里的进程自己找到彼此")]
    y = 44
    host_w = 270
    for hx, host, procs in ((LEFT, "这台电脑", ["labkit exec talker.py", "labkit ros2 topic echo"]),
                            (RIGHT - host_w, "另一台电脑（机器人）",
                             ["真实 ROS 2：listener", "真实 ROS 2：turtlesim"])):
        other = localhost_only and hx != LEFT
        body.append(_rect(hx, y, host_w, 150, fill=GREY if other else BLUE, dash=other))
        body.append(_text(hx + 10, y + 20, host, 13, weight="bold"))
        for k, proc in enumerate(procs):
            body.append(_rect(hx + 14, y + 34 + k * 54, host_w - 28, 44, fill="#fff"))
            body.append(_text(hx + 24, y + 54 + k * 54, proc, 12, mono=True))
            body.append(_text(hx + 24, y + 70 + k * 54, f"一个 DDS participant，域 {domain_id}",
                              12, fill="#555"))
    mid = LEFT + host_w
    colour = "#bbb" if localhost_only else "#555"
    dash = ' stroke-dasharray="5 4"' if localhost_only else ""
    body.append(f'<line x1="{mid}" y1="{y + 60}" x2="{RIGHT - host_w}" y2="{y + 60}" '
                f'stroke="{colour}" stroke-width="1.6" marker-end="url(#arrow)"'
                f'{dash}/>')
    body.append(f'<line x1="{RIGHT - host_w}" y1="{y + 100}" x2="{mid}" y2="{y + 100}" '
                f'stroke="{colour}" stroke-width="1.6" marker-end="url(#arrow)"'
                f'{dash}/>')
    lines = (["默认只走回环：", "另一台电脑", "收不到"] if localhost_only
             else ["局域网：", "多播发现"])
    for k, line in enumerate(lines):
        body.append(_text(WIDTH / 2, y + 122 + k * 16, line, 12, anchor="middle",
                          fill="#a00" if localhost_only else "#1d5a1d"))
    y += 166
    rows = [
        ("SPDP 参与者发现", f"UDP {ports['discovery multicast']}（多播）/ "
         f"{ports['discovery unicast']}…（单播）：我在这里，域 {domain_id}"),
        ("SEDP 端点发现", "有哪些读写端：rt/chatter、rq/…Request、rr/…Reply 和它们的类型、QoS"),
        ("ros_discovery_info", "哪个节点拥有哪些读写端：ros2 node list 靠它"),
        ("用户数据", f"UDP {ports['user unicast']}…：消息的 CDR 字节，和真 ROS 2 一模一样"),
    ]
    for k, (what, how) in enumerate(rows):
        ry = y + k * 26
        body.append(_text(LEFT, ry + 14, what, 12, weight="bold"))
        body.append(_text(LEFT + 150, ry + 14, _fit(how, RIGHT - LEFT - 150, 12), 12,
                          fill="#333"))
    y += len(rows) * 26 + 6
    body.append(_text(LEFT, y + 14, f"域号决定端口：7400 + 250 × {domain_id} 起；域号不同，"
                      "端口不同，彼此就看不见。", 13))
    return _svg(body, y + 30, f"connect_real_ros: DDS discovery on domain {domain_id}")
