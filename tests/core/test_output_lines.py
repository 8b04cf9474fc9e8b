"""Output reaches the notebook as a terminal shows it: whole lines, one writer's line
never cut by another's, a started line shown at the cell's end; finished jobs freed."""
import gc
import io
import sys
import weakref

import pytest

import labkit
from labkit import process


class Writes(io.StringIO):
    """A stream that remembers each write (what the notebook would get as one piece)."""

    def __init__(self):
        super().__init__()
        self.pieces = []

    def write(self, text):
        self.pieces.append(text)
        return super().write(text)


@pytest.fixture
def terminal(monkeypatch):
    """What the notebook gets: (stdout, stderr) as written pieces. Call it in the test's
    body (pytest swaps sys.stdout when the call starts)."""
    def attach():
        out, err = Writes(), Writes()
        process.install_output_proxy()
        for name, target in (("stdout", out), ("stderr", err)):
            monkeypatch.setattr(getattr(sys, name), "_target", target)
            monkeypatch.setitem(process._original, name, target)
        return out, err
    return attach


def _program(*pieces):
    def main(args=None):
        for piece in pieces:
            sys.stdout.write(piece)
        labkit.sleep(1.0)
    return main


def test_a_line_printed_in_pieces_reaches_the_notebook_whole(terminal):
    out, _ = terminal()
    proc = process.start(main=_program("Parameter name:", " ", "background_g\n",
                                       "  Type: integer\n"), name="describe")
    labkit.sleep(0.1)
    assert out.pieces == ["Parameter name: background_g\n", "  Type: integer\n"]
    proc.stop()


def test_lines_of_two_writers_never_interleave_mid_line(terminal):
    out, _ = terminal()

    def a(args=None):
        sys.stdout.write("aaa")
        labkit.sleep(0.01)
        sys.stdout.write("AAA\n")
        labkit.sleep(1.0)

    def b(args=None):
        labkit.sleep(0.005)
        sys.stdout.write("bbbBBB\n")
        labkit.sleep(1.0)

    pa = process.start(main=a, name="a")
    pb = process.start(main=b, name="b")
    labkit.sleep(0.1)
    assert out.getvalue() == "bbbBBB\naaaAAA\n"
    assert all(piece.endswith("\n") for piece in out.pieces)
    pa.stop()
    pb.stop()


def test_a_started_line_shows_at_the_end_of_the_cell_and_of_the_process(terminal):
    out, _ = terminal()
    proc = process.start(main=_program("prompt> "), name="prompt")
    labkit.sleep(0.1)
    assert out.getvalue() == ""             # waiting for its newline
    process.flush_echo_all()                # what the post_run_cell hook does
    assert out.pieces == ["prompt> "]
    proc.stop()
    ended = process.start(main=lambda args=None: sys.stdout.write("no newline"), name="x")
    labkit.sleep(0.1)
    assert out.pieces[-1] == "no newline" and not ended.running


def test_process_output_keeps_a_bounded_tail(monkeypatch, terminal):
    terminal()
    monkeypatch.setattr(process, "MAX_OUTPUT_LINES", 10)

    def flood(args=None):
        for i in range(100):
            print(i)
        labkit.sleep(1.0)
    proc = process.start(main=flood, name="flood")
    labkit.sleep(0.1)
    assert 10 <= len(proc.output) <= 20 and proc.output[-1] == "99"
    proc.stop()


def test_ros2_magic_writes_whole_lines(monkeypatch):
    from labkit.cli import magics
    out = Writes()
    monkeypatch.setattr(sys, "stdout", out)
    labkit.ros2("run turtlesim turtlesim_node")
    magics.ros2_magic("param describe /turtlesim background_g")
    assert out.getvalue().startswith("Parameter name: background_g\n  Type: integer\n")
    assert out.pieces and all(piece.endswith("\n") for piece in out.pieces)


def test_stopped_jobs_and_their_processes_are_freed():
    job = labkit.ros2("run turtlesim turtlesim_node")
    ref = weakref.ref(job.process)
    job.stop()
    del job
    labkit.ros2("run demo_nodes_py listener")      # the next job: the shell forgets the old
    gc.collect()
    assert ref() is None
    from labkit.cli.ros2 import jobs
    assert [j.command for j in jobs.all_jobs()] == ["ros2 run demo_nodes_py listener"]
    labkit.reset()
    assert jobs.all_jobs() == []


def test_a_job_handle_stops_its_job_and_shows_nothing_extra_in_its_own_cell():
    from IPython.core.interactiveshell import InteractiveShell
    ip = InteractiveShell.instance()
    if "labkit" not in ip.extension_manager.loaded:
        ip.run_line_magic("load_ext", "labkit")
    result = ip.run_cell("job = %ros2 run turtlesim turtlesim_node\njob")
    assert result.result is not None and result.result.job.running()
    handle = ip.user_ns["job"]
    assert repr(handle).startswith("[") and "ros2 run turtlesim turtlesim_node" in repr(handle)
    again = ip.run_cell("%ros2 run turtlesim turtlesim_node").result
    assert again.job is handle.job                  # the running job, not a second one
    handle.stop()
    assert not handle.running() and handle.state == "stopped"
    from labkit.cli import magics
    assert ip.display_formatter.format(handle) == ({}, {})   # same cell: already shown
    handle._cell = -1
    fmt = ip.display_formatter
    assert fmt.format(handle) == ({}, {})   # shown through _ipython_display_ (prints line)
    assert magics.JobHandle is type(handle)


def test_a_redirected_job_writes_stdout_to_the_file_and_stderr_whole_lines(terminal, tmp_path):
    from labkit.cli import magics
    _, err = terminal()
    target = tmp_path / "log.txt"
    magics.ros2_magic(f"run demo_nodes_py talker > {target}")
    labkit.sleep(2.5)
    assert err.pieces and all(p.endswith("\n") for p in err.pieces)
    assert "Publishing: \"Hello World: 1\"" in err.getvalue()
    assert target.read_text() == ""         # the talker logs to stderr; stdout stays empty
    labkit.reset()


class KernelStream(io.TextIOBase):
    """Like a kernel's stream: writes wait in a buffer; flush() sends them on the wire."""

    def __init__(self, name, wire):
        self.name, self.wire, self.buffer = name, wire, ""

    def write(self, text):
        self.buffer += text
        return len(text)

    def flush(self):
        if self.buffer:
            self.wire.append((self.name, self.buffer))
            self.buffer = ""


def _kernel_wire(monkeypatch):
    """The notebook's streams as kernel streams; returns the wire they flush onto."""
    wire = []
    out, err = KernelStream("stdout", wire), KernelStream("stderr", wire)
    process.install_output_proxy()
    for name, target in (("stdout", out), ("stderr", err)):
        monkeypatch.setattr(getattr(sys, name), "_target", target)
        monkeypatch.setitem(process._original, name, target)
    return wire


def test_what_the_cell_printed_first_reaches_the_notebook_first(monkeypatch):
    wire = _kernel_wire(monkeypatch)
    print("the cell prints first")          # waits in the kernel's stdout buffer
    proc = process.start(main=lambda args=None: sys.stderr.write("[INFO] then a node\n"),
                         name="node")
    labkit.sleep(0.1)
    assert wire == [("stdout", "the cell prints first\n"), ("stderr", "[INFO] then a node\n")]
    assert not proc.running


def test_the_cells_own_prints_and_log_lines_keep_their_order(monkeypatch):
    """A node of the notebook itself logs to stderr between two prints: the kernel gets
    them in that order (before, each stream went out on its own flush timer)."""
    wire = _kernel_wire(monkeypatch)
    monkeypatch.setattr(process, "_unflushed", {"stdout": False, "stderr": False})
    print("goal accepted")
    sys.stderr.write("[INFO] remaining: 0.5\n")
    sys.stderr.write("[INFO] remaining: 0.1\n")
    print("succeeded")
    sys.stdout.flush()
    sys.stderr.flush()
    assert wire == [("stdout", "goal accepted\n"),
                    ("stderr", "[INFO] remaining: 0.5\n[INFO] remaining: 0.1\n"),
                    ("stdout", "succeeded\n")]
