"""The pub/sub graph view: what rqt_graph shows, as a notebook picture.

    from labkit.viz.graph_view import GraphView, concept_figure
    GraphView().show()                         # live widget + static SVG in one output
    GraphView(services=True, actions=True).svg()
    GraphView(nodes_only=True).edges(labels=True)
    concept_figure("action")                   # a small graph started for the picture

Like rqt_graph it asks the graph through the public rclpy Node API from a
hidden node of its own (`/_labkit_graph_view`, in a context of its own, as if
it were the rqt_graph process), then draws the "Nodes/Topics (all)" view with
Graphviz `dot`: nodes as ellipses, topics as boxes, namespaces as clusters,
debug entities, dead sinks and leaf topics hidden by default, topics whose
publisher and subscription QoS cannot match drawn red.

A picture placed in the text is a snapshot, as a screenshot of rqt_graph
would be: `GraphView()` as a cell's last line, or `.show()`, draws the graph as
it is at that moment and stores only that picture (the same face in JupyterLab,
after save and reload, and in the HTML book), so it keeps showing what the text
beside it describes after the chapter has started other nodes. A view that
follows the graph is asked for: `GraphView(live=True)` or `.show(live=True)`
(and `ros2 run rqt_graph rqt_graph`) give a widget that scales to its cell's
width; in live time a background thread polls the graph's change counter every
0.5 s and lays out again only when the graph really changed. In virtual time
nothing changes between cells by itself, so it stays the graph as drawn.
"""
from __future__ import annotations

import threading
import weakref

from labkit.viz._graph_filter import ViewGraph, ViewOptions, build_view
from labkit.viz._graph_model import GraphSnapshot, join_name, query_snapshot
from labkit.viz._graph_render import fit_svg, img_html, render_svg

__all__ = ["GraphView", "GraphSnapshot", "concept_figure", "stop_all"]

QUERY_NODE_NAME = "_labkit_graph_view"
POLL_PERIOD_S = 0.5


# ------------------------------------------------------------ the query node

class _QueryNode:
    """The viewer's hidden node, shared by every view; created on demand.

    Static pictures create it, query, and destroy it again, so nothing of the
    viewer stays on the graph; live views hold it while they poll.
    """

    def __init__(self):
        self._lock = threading.RLock()
        self._context = None
        self._node = None
        self._holders = 0

    def _alive(self):
        try:
            return self._node is not None and self._context.ok()
        except Exception:
            return False

    def _create(self):
        from labkit import rclpy
        context = rclpy.context.Context()
        rclpy.init(args=[], context=context)
        try:
            self._node = rclpy.create_node(QUERY_NODE_NAME, context=context,
                                           enable_rosout=False, start_parameter_services=False)
        except BaseException:
            context.try_shutdown()
            raise
        self._context = context

    def _destroy(self):
        node, context, self._node, self._context = self._node, self._context, None, None
        try:
            if node is not None and context is not None and context.ok():
                node.destroy_node()
        finally:
            if context is not None:
                context.try_shutdown()

    def hold(self):
        with self._lock:
            self._holders += 1

    def release(self):
        with self._lock:
            self._holders = max(0, self._holders - 1)
            if self._holders == 0 and self._node is not None:
                self._destroy()

    def snapshot(self) -> GraphSnapshot:
        with self._lock:
            if not self._alive():   # first use, or labkit.reset() shut our context down
                self._node = self._context = None
                self._create()
            try:
                fqn = join_name(self._node.get_namespace(), self._node.get_name())
                return query_snapshot(self._node, exclude={fqn})
            finally:
                if self._holders == 0:
                    self._destroy()


_QUERY = _QueryNode()


def _graph_version():
    """The middleware's change counter: cheap to poll. None if unavailable."""
    try:
        from labkit.graph.registry import GRAPH
        return GRAPH.version
    except (ImportError, AttributeError):
        return None


def _settle():
    """In virtual time, let just-started processes reach their first wait point."""
    try:
        from labkit.graph import world
        if world.mode() == "virtual":
            world.settle()
    except ImportError:
        pass


def _live_mode():
    try:
        from labkit.graph import world
        return world.mode() == "live"
    except ImportError:
        return False


# ------------------------------------------------------------ the view

def _html(svg: str) -> str:
    """The live widget's HTML: the inline SVG scaled down to the cell's width (never up
    past its own size), the aspect kept by its viewBox, so nothing is cut at the right."""
    return ('<div class="labkit-graph-fit" style="width:100%;max-width:100%;overflow:hidden">'
            f'{fit_svg(svg)}</div>')


_LIVE_VIEWS = weakref.WeakSet()


class GraphView:
    """rqt_graph's "Nodes/Topics (all)" view of the running graph (or of a given snapshot).

    Options follow rqt_graph's check boxes: hide_debug ("Hide: Debug" and
    "Params"), hide_dead_sinks, hide_leaf_topics, hide_tf, group_tf,
    cluster_level ("Group: Namespaces" depth), nodes_only (the "Nodes only"
    graph: arrows from node to node labelled with the topic instead of topic
    boxes; the default is "Nodes/Topics (all)"). labkit adds `services` (client ->
    service -> server, a two-headed arrow; "request_response": the request client ->
    service -> server and the response back as two arrows, each named) and `actions`
    (False, True for one box per action, or "expand" for its hidden services and topics).
    """

    def __init__(self, services: bool | str = False, actions: bool | str = False,
                 hide_debug: bool = True, *, hide_dead_sinks: bool = True,
                 hide_leaf_topics: bool = True, hide_tf: bool = False, group_tf: bool = True,
                 cluster_level: int = 2, nodes_only: bool = False, rankdir: str = "auto",
                 snapshot: GraphSnapshot | dict | None = None, live: bool = False):
        self.options = ViewOptions(services=services, actions=actions, hide_debug=hide_debug,
                                   hide_dead_sinks=hide_dead_sinks,
                                   hide_leaf_topics=hide_leaf_topics, hide_tf=hide_tf,
                                   group_tf=group_tf, cluster_level=cluster_level,
                                   nodes_only=nodes_only)
        self.rankdir = rankdir
        self.follow = bool(live)     # what show() does by default: snapshot or live view
        if isinstance(snapshot, dict):
            snapshot = GraphSnapshot.from_dict(snapshot)
        self._fixed = snapshot
        self._lock = threading.Lock()
        self._last = None            # (snapshot, svg) of the latest drawing
        self._widget = None
        self._thread = None
        self._stop = threading.Event()

    # -- data
    def snapshot(self) -> GraphSnapshot:
        """What every node has on the graph now (or the snapshot given)."""
        if self._fixed is not None:
            return self._fixed
        if threading.current_thread() is threading.main_thread():
            _settle()
        return _QUERY.snapshot()

    def view(self, snapshot: GraphSnapshot | None = None) -> ViewGraph:
        """The vertices, arrows and clusters that will be drawn."""
        return build_view(snapshot if snapshot is not None else self.snapshot(), self.options)

    def edges(self, labels: bool = False) -> list[tuple[str, ...]]:
        """Every arrow as (start, end) ROS names, sorted: publisher -> topic -> subscriber,
        client -> service -> server, action client -> action -> action server.
        labels=True gives (start, label, end); the label is set in the nodes_only view."""
        return self.view().edges(labels)

    # -- pictures
    def _draw(self, snapshot: GraphSnapshot) -> str:
        with self._lock:
            if self._last is not None and self._last[0] == snapshot:
                return self._last[1]
        svg = render_svg(build_view(snapshot, self.options), rankdir=self.rankdir)
        with self._lock:
            self._last = (snapshot, svg)
        return svg

    def svg(self) -> str:
        """The SVG document of the graph now (same graph, same bytes)."""
        return self._draw(self.snapshot())

    def _repr_svg_(self):
        return self.svg()

    def widget(self):
        """An ipywidgets.HTML holding the picture (created once)."""
        if self._widget is None:
            import ipywidgets
            svg = self._last[1] if self._last is not None else self.svg()
            # the whole cell's width (an HTML widget is otherwise as wide as its content)
            self._widget = ipywidgets.HTML(value=_html(svg),
                                           layout=ipywidgets.Layout(width="100%", margin="0"))
            self._widget.add_class("labkit-graph-view")
        return self._widget

    def refresh(self) -> bool:
        """Query the graph again; redraw (and update the widget) if it changed."""
        before = self._last[1] if self._last else None
        svg = self.svg()
        if self._widget is not None and self._widget.value != _html(svg):
            self._widget.value = _html(svg)
        return svg != before

    def show(self, live: bool | None = None):
        """Display the graph as it is now.

        By default (live=None takes the `live` given to the constructor, False
        unless asked) this is a snapshot: one static SVG, the picture a reader
        sees beside the text in JupyterLab, after reload and in the HTML book,
        whatever starts later. live=True displays a widget that scales to the
        cell's width together with the same SVG as its static face; in live
        time the widget then follows the graph (in virtual time nothing
        changes between cells by itself, so it is not polled).
        """
        from labkit.viz.display import show
        follow = self.follow if live is None else bool(live)
        snapshot = self.snapshot()
        svg = self._draw(snapshot)
        text = f"<GraphView: {len(build_view(snapshot, self.options).vertices)} vertices>"
        # the static face twice: the SVG itself, and an <img> of it that fits the cell
        static = dict(svg=svg, html=img_html(svg, alt=text), text=text)
        if not follow:
            show(**static)
            return
        if self._widget is not None and self._widget.value != _html(svg):
            self._widget.value = _html(svg)
        show(self.widget(), **static)
        if _live_mode() and self._fixed is None:
            self.start()

    def _ipython_display_(self):
        # `GraphView()` as a cell's last line: a snapshot (`GraphView(live=True)`: live view)
        self.show()

    # -- live following
    def start(self):
        """Follow the graph from a background thread (poll the change counter every 0.5 s).

        Meant for live time. In virtual time only the notebook's own thread may
        start it: a poller started inside a labkit process would join that
        process's turn-taking and hold up the simulated world.
        """
        if self._thread is not None and self._thread.is_alive():
            return
        if not _live_mode() and threading.current_thread() is not threading.main_thread():
            return
        self._stop.clear()
        _QUERY.hold()
        self._thread = threading.Thread(target=self._follow, name="labkit-graph-view",
                                        daemon=True)
        _LIVE_VIEWS.add(self)
        self._thread.start()

    def stop(self):
        """Stop following the graph (the picture stays as it is)."""
        self._stop.set()
        thread, self._thread = self._thread, None
        if thread is not None and thread is not threading.current_thread():
            thread.join(timeout=5.0)

    def _follow(self):
        try:
            seen = None
            while not self._stop.wait(POLL_PERIOD_S):
                if self._widget is not None and getattr(self._widget, "comm", True) is None:
                    break        # the widget was closed
                version = _graph_version()
                if version is not None and version == seen:
                    continue     # nothing changed: no query, no layout
                try:
                    snap = _QUERY.snapshot()
                except Exception:
                    continue     # the graph is being torn down; try again next tick
                seen = version   # read before the query: a change meanwhile is seen next tick
                if self._last is None or snap != self._last[0]:
                    svg = self._draw(snap)
                    if self._widget is not None:
                        self._widget.value = _html(svg)
        finally:
            _QUERY.release()
            _LIVE_VIEWS.discard(self)

    @property
    def live(self) -> bool:
        return self._thread is not None and self._thread.is_alive()


def stop_all():
    """Stop every live graph view (labkit.reset() leaves them harmless, this ends them)."""
    for view in list(_LIVE_VIEWS):
        view.stop()


# ------------------------------------------------------------ concept figures

from labkit.viz._graph_concepts import CONCEPTS, concept_figure, concept_snapshot  # noqa: E402,F401


# ------------------------------------------------------------ `ros2 run rqt_graph rqt_graph`

def main(args=None):
    """rqt_graph as an executable: its own node (`rqt_gui_py_node_<pid>`, a debug
    name the view hides, as rqt_graph hides itself), the view shown in the
    notebook and following the graph until the process is stopped."""
    from labkit import process, rclpy
    rclpy.init(args=args)
    node = rclpy.create_node(f"rqt_gui_py_node_{process.current().pid}")
    view = GraphView()
    try:
        from IPython import get_ipython
        shell = get_ipython()
    except ImportError:
        shell = None
    if shell is not None and getattr(shell, "kernel", None) is not None:
        view.show(live=True)      # rqt_graph's window: follows the graph in live time
    elif _live_mode():
        view.start()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    except Exception as exc:      # ExternalShutdownException: the process was stopped
        if type(exc).__name__ != "ExternalShutdownException":
            raise
    finally:
        view.stop()
        node.destroy_node()
        rclpy.try_shutdown()
