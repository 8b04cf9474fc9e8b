"""`make lab` opens a working copy of the book, and what JupyterLab saves there
reopens with static faces, never "model not found"."""
import json

import nbformat

from labkit.tools import lab

VIEW = lab.WIDGET_VIEW


def test_working_copy_copies_once_and_never_overwrites(tmp_path):
    book = tmp_path / "book"
    (book / "part1").mkdir(parents=True)
    (book / "part1" / "ch01.ipynb").write_text("shipped")
    (book / "_build").mkdir()
    (book / "_build" / "x.html").write_text("built")
    (book / "part1" / "_work").mkdir()
    (book / "part1" / "_work" / "scratch").write_text("run output")
    target = tmp_path / "lab"
    assert [str(p) for p in lab.working_copy(book, target)] == ["part1/ch01.ipynb"]
    (target / "part1" / "ch01.ipynb").write_text("the learner's version")
    assert lab.working_copy(book, target) == []
    assert (target / "part1" / "ch01.ipynb").read_text() == "the learner's version"
    assert not (target / "_build").exists() and not (target / "part1" / "_work").exists()


def test_lab_command_opens_the_copy_on_loopback_with_the_save_hook(tmp_path):
    cmd = lab.command(tmp_path / "lab")
    assert "--ip=127.0.0.1" in cmd and f"--notebook-dir={tmp_path / 'lab'}" in cmd
    assert "--ContentsManager.pre_save_hook=labkit.tools.lab.strip_live_views" in cmd


def test_saved_notebook_keeps_static_faces_without_widget_views(tmp_path):
    from jupyter_server.services.contents.filemanager import FileContentsManager
    manager = FileContentsManager(root_dir=str(tmp_path),
                                  pre_save_hook="labkit.tools.lab.strip_live_views")
    nb = nbformat.v4.new_notebook()
    cell = nbformat.v4.new_code_cell("TurtleCanvas.attach()")
    view = {"version_major": 2, "version_minor": 0, "model_id": "0123"}
    cell.outputs = [
        nbformat.v4.new_output("display_data", data={
            "image/png": "iVBORw0KGgo=", "text/plain": "<turtlesim canvas>", VIEW: view}),
        nbformat.v4.new_output("display_data", data={
            "text/plain": "[1] 4001 running ros2 run turtlesim turtlesim_node", VIEW: view}),
        nbformat.v4.new_output("stream", name="stdout", text="kept\n"),
    ]
    nb.cells.append(cell)
    manager.save({"type": "notebook", "content": json.loads(nbformat.writes(nb))}, "ch.ipynb")
    saved = nbformat.read(tmp_path / "ch.ipynb", as_version=4)
    outs = saved.cells[0].outputs
    assert [sorted(o.get("data", {})) for o in outs] == [
        ["image/png", "text/plain"], ["text/plain"], []]
    assert outs[2]["text"] == "kept\n"
