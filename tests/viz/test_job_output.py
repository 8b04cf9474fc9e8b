"""A background job's own output area (live JupyterLab): its lines stay with the job,
not with whatever cell runs next; its Stop button and its handle stop it."""
import pytest

import labkit
from labkit.viz import job_output


@pytest.fixture
def live_kernel(live_time, monkeypatch):
    """Live time, and labkit believing it runs in a Jupyter kernel."""
    monkeypatch.setattr(job_output, "enabled", lambda: True)
    shown = []
    monkeypatch.setattr("labkit.viz.display.display", lambda obj, **kw: shown.append(obj))
    return shown


def test_job_lines_go_to_the_jobs_own_area(live_kernel, capsys, until):
    shown = live_kernel
    job = labkit.ros2("run turtlesim turtlesim_node")
    echo = labkit.ros2("topic echo /turtle1/color_sensor")
    assert job.view is not None and echo.view is not None and job.view is not echo.view
    assert until(lambda: echo.view.text_value().count("---") >= 20)
    assert "r: " in echo.view.text_value() and "---" not in job.view.text_value()
    assert "Starting turtlesim" in job.view.text_value()
    assert "r: " not in capsys.readouterr().out            # nothing leaks into the cell
    assert len(echo.view.lines) <= job_output.MAX_LINES    # a bounded tail, not a flood
    views = [b for b in shown if "application/vnd.jupyter.widget-view+json" in b]
    assert [v["text/plain"] for v in views] == [job.line(), echo.line()]
    assert until(lambda: echo.view.renders >= 1 and "r: " in echo.view.text.value)


def test_stop_button_and_handle_stop_the_job(live_kernel, until):
    shown = live_kernel
    echo = labkit.ros2("topic echo /rosout")
    echo.view.button.click()
    assert not echo.running() and echo.state == "stopped"
    assert until(lambda: echo.view.button.disabled and "stopped" in echo.view.title.value)
    job = labkit.ros2("run turtlesim turtlesim_node")

    class Window:                       # what turtlesim's canvas registers in a kernel
        def _ipython_display_(self):
            shown.append({"window": True})
    job.process.windows.append(Window())
    before = len(shown)
    again = labkit.ros2("run turtlesim turtlesim_node")     # the cell runs again
    assert again.job is job and "already running" in again.stdout
    # the learner gets the output area (and the windows it opened) back, not only a line
    again_shown = shown[before:]
    assert again_shown[0] == {"window": True}
    assert [b["application/vnd.jupyter.widget-view+json"]["model_id"] for b in again_shown[1:]] \
        == [job.view.box.model_id]
    job.stop()
    assert not job.running()
