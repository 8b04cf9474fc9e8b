"""A background job's own output area in live JupyterLab.

In a terminal each `ros2 run` has its own window; in a notebook the job's lines
must not land in whatever cell runs next. A `JobView` is displayed in the cell
that started the job: a title line with the job's state, a Stop button, and the
newest lines the job printed (a bounded tail, redrawn at most `fps` times a
second, so a 60 Hz `topic echo` costs the kernel and the notebook file little).

Only live time uses it (`enabled()`): in virtual time (nbval, book-exec) a job's
lines are stored as plain stream text, the same every run.
"""
import collections
import html
import threading

MAX_LINES = 200          # lines kept on screen (a terminal's scrollback, small)
FPS = 8                  # redraws a second at most


def enabled():
    """True in live time inside a Jupyter kernel (where widgets can show)."""
    from labkit.viz.display import live_kernel
    return live_kernel()


class JobView:
    """The output area of one job: title, Stop button, the newest lines."""

    def __init__(self, command, max_lines=MAX_LINES, fps=FPS):
        import ipywidgets as widgets
        self.command = command
        self.job = None
        self.lines = collections.deque(maxlen=max_lines)   # (stream name, text with \n)
        self.fps = fps
        self.renders = 0                # times the text was sent to the browser
        self._lock = threading.Lock()
        self._dirty = threading.Event()
        self._done = threading.Event()
        self.title = widgets.HTML(self._title_html())
        self.button = widgets.Button(description="Stop", icon="stop",
                                     tooltip="Stop this job (Ctrl-C in its terminal)",
                                     layout=widgets.Layout(width="80px"))
        self.button.on_click(lambda _: self.stop_job())
        self.text = widgets.HTML("", layout=widgets.Layout(width="100%"))
        self.box = widgets.VBox(
            [widgets.HBox([self.button, self.title], layout=widgets.Layout(align_items="center")),
             self.text],
            layout=widgets.Layout(border="1px solid #ccc", padding="4px", width="100%"))
        from labkit.viz.display import viewer_thread
        self._thread = viewer_thread(self._refresh, "labkit-job-view")

    # -- what the job prints (any thread) --------------------------------------------
    def attach(self, job):
        self.job = job
        self._dirty.set()

    def write(self, stream_name, text):
        with self._lock:
            for line in text.splitlines(keepends=True):
                self.lines.append((stream_name, line))
        self._dirty.set()

    def text_value(self):
        """What the area shows now, as plain text."""
        with self._lock:
            return "".join(line for _, line in self.lines)

    # -- the widget ---------------------------------------------------------------------
    def show(self):
        from labkit.viz.display import show
        show(self.box, text=self.job.line() if self.job is not None else self.command)

    def _ipython_display_(self):
        self.show()

    def stop_job(self):
        if self.job is not None and self.job.running():
            self.job.stop()
        self._dirty.set()

    def finish(self):
        """The job is gone (stopped, ended, labkit.reset()): last redraw, then rest."""
        self._done.set()
        self._dirty.set()

    def close(self):
        self.finish()
        self._thread.join(timeout=2.0)
        self.box.close()

    def _title_html(self):
        line = self.job.line() if self.job is not None else self.command
        return f"<code>{html.escape(line)}</code>"

    def _render(self):
        with self._lock:
            # a terminal shows both streams alike
            body = "".join(html.escape(line) for _, line in self.lines)
        # column-reverse keeps the newest line in sight, as a terminal scrolls
        self.text.value = (
            "<div style='display:flex;flex-direction:column-reverse;max-height:16em;"
            "overflow-y:auto'><pre style='margin:0;font-size:12px;line-height:1.3;"
            f"white-space:pre-wrap'>{body}</pre></div>") if body else ""
        self.title.value = self._title_html()
        self.button.disabled = self.job is not None and not self.job.running()
        self.renders += 1

    def _refresh(self):
        while True:
            self._dirty.wait(timeout=1.0)
            ended = self._done.is_set() or (self.job is not None and not self.job.running())
            if self._dirty.is_set() or ended:
                self._dirty.clear()
                try:
                    self._render()
                except Exception:       # a closed widget or a gone kernel
                    return
            if ended:
                return
            self._done.wait(1.0 / self.fps)
