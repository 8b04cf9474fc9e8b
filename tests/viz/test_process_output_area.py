"""A process the notebook starts itself (`labkit.process.start(main=..., name=...)`, as
the book's chapters start their own nodes) gets its own output area in live
JupyterLab, as a `ros2 run` job does: its log lines never land in whatever cell
runs next (ch03 exercise 3.3 left a listener logging 5 lines a second into
every later cell), and its Stop button stops it."""
import pytest

from labkit import process
from labkit.cli import magics
from labkit.viz import job_output


@pytest.fixture
def live_kernel(live_time, monkeypatch):
    """Live time, labkit believing it runs in a Jupyter kernel, `%load_ext labkit` done."""
    monkeypatch.setattr(job_output, "enabled", lambda: True)
    shown = []
    monkeypatch.setattr("labkit.viz.display.display", lambda obj, **kw: shown.append(obj))
    monkeypatch.setattr(process, "live_view", magics._process_view)
    return shown


def chatty(args=None):
    """A node that prints a line every 10 ms (stops as a node does: Ctrl-C, shutdown)."""
    import labkit.rclpy as rclpy
    rclpy.init(args=args)
    node = rclpy.create_node("chatty")
    count = iter(range(10 ** 9))
    node.create_timer(0.01, lambda: print(f"line {next(count)}"))
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()


def test_process_lines_go_to_its_own_area(live_kernel, capsys, until):
    shown = live_kernel
    proc = process.start(main=chatty, name="chatty")
    try:
        assert proc.view is not None
        assert until(lambda: proc.view.text_value().count("line ") >= 20)
        assert "line " not in capsys.readouterr().out           # nothing in the cell
        views = [b for b in shown if "application/vnd.jupyter.widget-view+json" in b]
        assert [v["text/plain"] for v in views] == [f"{proc.pid} running chatty"]
        proc.view.button.click()                               # its Stop button
        assert not proc.running
        assert until(lambda: proc.view.button.disabled and "stopped" in proc.view.title.value)
    finally:
        proc.stop()


def test_no_area_for_a_quiet_process_or_outside_a_kernel(live_kernel, monkeypatch):
    quiet = process.start(main=chatty, name="quiet", echo=False)
    assert quiet.view is None
    quiet.stop()
    monkeypatch.setattr(job_output, "enabled", lambda: False)  # virtual time, scripts
    plain = process.start(main=chatty, name="plain")
    assert plain.view is None
    plain.stop()
