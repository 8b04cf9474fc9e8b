"""Check cells for the book's exercises.

A chapter's exercise ends with a cell like

    from labkit.exercises import Checker
    c = Checker("练习 3.1")
    c.node("/turtlesim")
    c.topic("/turtle1/cmd_vel", "geometry_msgs/msg/Twist", publishers=1)
    c.report()

Each check looks at the live graph (through a hidden node, as the ros2 CLI
does) and records one line in Chinese: what is right, or what is missing and
a hint. `report()` prints the lines and a summary and returns True when all
passed, so a notebook can also `assert c.report()`.

A check never crashes
---------------------
Whatever a learner's code leaves behind (a scalar where a list was meant, a
name defined only inside a function, a server that died), the check must
judge it, not show a traceback. Two guards do that:

* In a notebook (IPython), creating a Checker arms a handler for the rest of
  that cell: an exception escaping the cell before `report()` becomes one
  ``[错]`` line naming it (``检查时出错：TypeError: ...``, one line), the
  report is printed, and the cell ends normally (no traceback, "Run All"
  goes on). The handler is disarmed when the cell ends.
* Anywhere, ``with Checker("练习 2.2") as c: ...`` does the same: the block's
  exception is recorded as a failed item and the report is printed on exit
  (unless the block already called `report()` after its last check).

Machine-readable results (for grading)
--------------------------------------
``Checker.result()`` returns a dict::

    {"exercise": "练习 2.2",          # the title, as printed in 【】
     "passed": False,                 # every item passed (and there was one)
     "passed_items": ["节点 /heartbeat 正在运行", ...],
     "failed_items": [{"text": "...the whole [错] line...",
                       "hint": "...the part after the first '：', or the whole line"}]}

Every `report()` also hands that dict to each callable in `REPORT_HOOKS`
(``labkit.exercises.REPORT_HOOKS.append(fn)``) and, when the environment
variable ``LABKIT_EXERCISE_LOG`` names a file, appends it there as one JSON
line (UTF-8, ``ensure_ascii=False``) with two more keys: ``"notebook"`` (the
value of ``LABKIT_NOTEBOOK`` if set, else null) and ``"time"`` (Unix seconds,
wall clock). A hook that raises is ignored: grading never breaks a check.
"""
from __future__ import annotations

import json
import os
import time

_node = None

#: callables that receive every report's `Checker.result()` dict
REPORT_HOOKS: list = []
#: the environment variable naming a file that gets one JSON line per report
LOG_ENV = "LABKIT_EXERCISE_LOG"

# plain characters every Chinese font has (an emoji needs a font the reader may lack),
# legible the same in the stored text, the HTML book and a terminal
PASS = "  [对] "
FAIL = "  [错] "


def _graph_node():
    """A hidden node of the notebook's own process, created once."""
    global _node
    import labkit.rclpy as rclpy
    from labkit.graph import world
    from labkit.rclpy.context import default_domain_id

    domain = default_domain_id()
    if _node is not None and _node.context.ok() and _node.context.get_domain_id() == domain:
        world.settle()
        return _node
    if _node is not None and _node.context.ok():   # the notebook joined another domain
        _node.destroy_node()
    ctx = rclpy.get_default_context()
    if not ctx.ok():
        rclpy.init()
    if ctx.get_domain_id() != domain:
        # the default context stays on the domain it was started on (as in ROS); the
        # checker looks where the notebook is now (after labkit.connect(domain_id=N))
        ctx = rclpy.Context()
        ctx.init(args=[], domain_id=domain)
    _node = rclpy.create_node("_labkit_exercise_checker", context=ctx,
                              start_parameter_services=False)
    world.settle()
    return _node


class Verdict:
    """What report() returns: true when every check passed (`assert c.report()`
    works), and nothing more in the cell's output than the report itself (a
    bare True/False under the report would only distract)."""

    __slots__ = ("passed",)

    def __init__(self, passed: bool):
        self.passed = bool(passed)

    def __bool__(self) -> bool:
        return self.passed

    def __eq__(self, other) -> bool:
        return self.passed == bool(other)

    def __hash__(self) -> int:
        return hash(self.passed)

    def __repr__(self) -> str:
        return repr(self.passed)

    def _ipython_display_(self):
        pass


class Checker:
    """Collects the results of the checks of one exercise."""

    def __init__(self, title: str):
        self.title = title
        self.results: list[tuple[bool, str]] = []
        self._reported_at = None        # len(results) when report() last ran
        _arm_cell_guard(self)

    # -- the record ---------------------------------------------------------
    def that(self, ok: bool, good: str, bad: str) -> bool:
        """Record a check of your own: `good` is said when ok, `bad` otherwise."""
        self.results.append((bool(ok), good if ok else bad))
        return bool(ok)

    def error(self, exc: BaseException, doing: str = "") -> bool:
        """Record an exception met while checking as one failed item (never a traceback)."""
        return self.that(False, "", _error_line(exc, doing))

    @property
    def passed(self) -> bool:
        return bool(self.results) and all(ok for ok, _ in self.results)

    def result(self) -> dict:
        """The report as data: exercise, passed, passed_items, failed_items (see the module doc)."""
        failed = []
        for ok, text in self.results:
            if not ok:
                head, sep, tail = text.partition("：")
                failed.append({"text": text, "hint": tail if sep and tail else text})
        return {"exercise": self.title, "passed": self.passed,
                "passed_items": [text for ok, text in self.results if ok],
                "failed_items": failed}

    def report(self) -> "Verdict":
        print(f"【{self.title}】")
        for ok, text in self.results:
            print((PASS if ok else FAIL) + text)
        missing = sum(1 for ok, _ in self.results if not ok)
        if not self.results:
            print("  （没有检查项）")
        elif missing:
            print(f"还差 {missing} 项，改好后再运行这个单元格。")
        else:
            print("全部正确！")
        self._reported_at = len(self.results)
        _publish(self.result())
        return Verdict(self.passed)

    # -- the guard ----------------------------------------------------------
    def __enter__(self) -> "Checker":
        return self

    def __exit__(self, etype, exc, tb) -> bool:
        if exc is not None and not isinstance(exc, Exception):
            return False                # KeyboardInterrupt, SystemExit: not ours to hide
        if exc is not None:
            self.error(exc)
        if exc is not None or self._reported_at != len(self.results):
            self.report()
        return True

    # -- the graph ----------------------------------------------------------
    def node(self, name: str) -> bool:
        """A node with this fully qualified name is running."""
        names = _node_names()
        return self.that(name in names, f"节点 {name} 正在运行",
                         f"没有找到节点 {name}（现在有：{', '.join(sorted(names)) or '无'}）")

    def no_node(self, name: str) -> bool:
        names = _node_names()
        return self.that(name not in names, f"节点 {name} 已经停止", f"节点 {name} 还在运行")

    def topic(self, name: str, type_name: str | None = None, *, publishers: int | None = None,
              subscribers: int | None = None) -> bool:
        """A topic exists, optionally with this type and these endpoint counts."""
        node = _graph_node()
        types = dict(node.get_topic_names_and_types())
        if name not in types:
            return self.that(False, "", f"没有找到话题 {name}")
        ok = self.that(True, f"话题 {name} 存在", "")
        if type_name is not None:
            ok &= self.that(type_name in types[name], f"{name} 的类型是 {type_name}",
                            f"{name} 的类型是 {', '.join(types[name])}，不是 {type_name}")
        if publishers is not None:
            n = node.count_publishers(name)
            ok &= self.that(n == publishers, f"{name} 有 {n} 个发布者",
                            f"{name} 应该有 {publishers} 个发布者，现在有 {n} 个")
        if subscribers is not None:
            n = node.count_subscribers(name)
            ok &= self.that(n == subscribers, f"{name} 有 {n} 个订阅者",
                            f"{name} 应该有 {subscribers} 个订阅者，现在有 {n} 个")
        return ok

    def service(self, name: str, type_name: str | None = None) -> bool:
        from labkit.graph.registry import GRAPH, SRV
        node = _graph_node()   # a server, not just clients (which the service list shows)
        with GRAPH.lock:
            types = dict(GRAPH.names_and_types([SRV], node.context.get_domain_id()))
        if name not in types:
            return self.that(False, "", f"没有找到服务 {name}")
        if type_name is None:
            return self.that(True, f"服务 {name} 存在", "")
        return self.that(type_name in types[name], f"服务 {name} 的类型是 {type_name}",
                         f"服务 {name} 的类型是 {', '.join(types[name])}，不是 {type_name}")

    def parameter(self, node_name: str, name: str, expected) -> bool:
        """A node's parameter has this value (asked through its get_parameters service)."""
        value = get_parameter(node_name, name)
        if value is _MISSING:
            return self.that(False, "", f"读不到 {node_name} 的参数 {name}")
        return self.that(value == expected, f"{node_name} 的参数 {name} = {value!r}",
                         f"{node_name} 的参数 {name} = {value!r}，期望 {expected!r}")

    def file(self, path: str, *, contains: str | None = None) -> bool:
        if not os.path.exists(path):
            return self.that(False, "", f"文件 {path} 不存在")
        if contains is None:
            return self.that(True, f"文件 {path} 存在", "")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        return self.that(contains in text, f"{path} 里有 {contains!r}",
                         f"{path} 里没有 {contains!r}")


    # -- traffic ------------------------------------------------------------
    def logs(self, node_name: str, seconds: float = 2.0, *, at_least: int = 1,
             contains: str | None = None) -> list:
        """A node writes log lines to /rosout while the graph runs `seconds`."""
        lines = logs(node_name, seconds)
        wanted = [m for m in lines if contains is None or contains in m.msg]
        what = f"包含 {contains!r} 的日志" if contains else "日志"
        self.that(len(wanted) >= at_least,
                  f"{seconds:g} 秒里 {node_name} 输出了 {len(wanted)} 条{what}",
                  f"{seconds:g} 秒里 {node_name} 只输出了 {len(wanted)} 条{what}，至少应该有 {at_least} 条")
        return wanted


def collect(topic: str, type_name: str, seconds: float = 1.0, qos=10, *, stamped: bool = False) -> list:
    """The messages that arrive on `topic` while the graph runs for `seconds`; with
    stamped=True, (arrival time in seconds of ROS time, message) pairs."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    from labkit.rclpy.duration import Duration

    node = _graph_node()
    got = []
    clock = node.get_clock()

    def arrived(msg):
        got.append((clock.now().nanoseconds * 1e-9, msg) if stamped else msg)

    sub = node.create_subscription(get_type(type_name), topic, arrived, qos)
    try:
        end = node.get_clock().now() + Duration(seconds=seconds)
        while node.get_clock().now() < end:
            rclpy.spin_once(node, timeout_sec=0.05)
    finally:
        node.destroy_subscription(sub)
    return got


def logs(node_name: str, seconds: float = 2.0) -> list:
    """The /rosout log messages (rcl_interfaces/msg/Log) a node writes during `seconds`."""
    logger = node_name.lstrip("/").replace("/", ".")
    return [m for m in collect("/rosout", "rcl_interfaces/msg/Log", seconds) if m.name == logger]


def turtle_pose(turtle: str = "turtle1"):
    """The turtle's latest pose as a dict (x, y, theta, ...), or None if nothing publishes it."""
    poses = collect(f"/{turtle}/pose", "turtlesim/msg/Pose", 0.1)
    if not poses:
        return None
    p = poses[-1]
    return {"x": p.x, "y": p.y, "theta": p.theta,
            "linear_velocity": p.linear_velocity, "angular_velocity": p.angular_velocity}


def crashed() -> list[tuple[str, int, str]]:
    """Background processes that ended with an error and were not reaped yet (a shell
    keeps a dead child's status until the next command): (name, returncode, its last
    error line), oldest first. What a check names when a server stopped answering."""
    from labkit import process

    out = []
    for proc in process.processes():
        if proc.returncode not in (None, 0, -2):
            lines = [line.strip() for line in proc.output if line.strip()]
            out.append((proc.name, proc.returncode, lines[-1] if lines else ""))
    return out


def _node_names() -> set[str]:
    node = _graph_node()
    out = set()
    for name, ns in node.get_node_names_and_namespaces():
        if name.startswith("_"):
            continue
        out.add(ns.rstrip("/") + "/" + name)
    return out


_MISSING = object()


def get_parameter(node_name: str, name: str, timeout_sec: float = 5.0):
    """A parameter's Python value through `<node>/get_parameters`, or _MISSING."""
    from labkit.interfaces import get_type
    from labkit.rclpy.parameter import parameter_value_to_python

    node = _graph_node()
    GetParameters = get_type("rcl_interfaces/srv/GetParameters")
    client = node.create_client(GetParameters, node_name.rstrip("/") + "/get_parameters")
    try:
        if not client.wait_for_service(timeout_sec=timeout_sec):
            return _MISSING
        future = client.call_async(GetParameters.Request(names=[name]))
        import labkit.rclpy as rclpy
        rclpy.spin_until_future_complete(node, future, timeout_sec=timeout_sec)
        if not future.done() or not future.result().values:
            return _MISSING
        value = future.result().values[0]
        if value.type == 0:
            return _MISSING
        return parameter_value_to_python(value)
    finally:
        node.destroy_client(client)


# -- errors, publishing, the notebook cell guard -----------------------------
def _error_line(exc: BaseException, doing: str = "") -> str:
    """One line naming an exception: 检查时出错：TypeError: 'float' object is not iterable."""
    text = " ".join(str(exc).split())
    name = type(exc).__name__
    what = f"{name}: {text}" if text else name
    return f"检查时出错{('（' + doing + '）') if doing else ''}：{what}"


def _publish(result: dict) -> None:
    for hook in list(REPORT_HOOKS):
        try:
            hook(dict(result))
        except Exception:   # grading must never break a learner's check
            pass
    path = os.environ.get(LOG_ENV)
    if path:
        line = dict(result, notebook=os.environ.get("LABKIT_NOTEBOOK"), time=time.time())
        try:
            with open(path, "a", encoding="utf-8") as f:
                f.write(json.dumps(line, ensure_ascii=False) + "\n")
        except OSError:
            pass


_armed: list = []          # the checkers created in the running cell
_saved_handler = None      # IPython's custom-exception setting before we armed


def _arm_cell_guard(checker: "Checker") -> None:
    """In IPython: until this cell ends, an exception escaping it is judged by the
    checker (one [错] line, the report) instead of printed as a traceback."""
    global _saved_handler
    try:
        from IPython import get_ipython
        shell = get_ipython()
    except Exception:
        return
    if shell is None or not hasattr(shell, "set_custom_exc"):
        return
    _armed.append(checker)
    if len(_armed) > 1:
        return
    _saved_handler = (shell.custom_exceptions, shell.CustomTB)
    shell.set_custom_exc((Exception,), _cell_exception)
    shell.events.register("post_run_cell", _disarm)


def _cell_exception(shell, etype, value, tb, tb_offset=None):
    checker = _armed[-1] if _armed else None
    if checker is None or checker._reported_at == len(checker.results) and checker._reported_at:
        # the exception is not the check's (it came after the report): show it as usual
        shell.showtraceback((etype, value, tb), tb_offset=tb_offset)
        return []
    checker.error(value)
    checker.report()
    checker._handled_exception = True
    return []


def _disarm(result=None) -> None:
    global _saved_handler
    from IPython import get_ipython
    shell = get_ipython()
    handled = any(getattr(c, "_handled_exception", False) for c in _armed)
    _armed.clear()
    if shell is not None:
        try:
            shell.events.unregister("post_run_cell", _disarm)
        except ValueError:
            pass
        if _saved_handler is not None:
            exc_tuple, custom_tb = _saved_handler
            shell.custom_exceptions = exc_tuple
            shell.CustomTB = custom_tb
    _saved_handler = None
    if handled and result is not None and isinstance(result.error_in_exec, Exception):
        # the check judged the exception: the cell did its job, it did not fail
        result.error_in_exec = None
