"""The 3D views are framed for the reader.

Every 3D view stored in the book (the static face: the `<iframe srcdoc>` saved in the
notebook, the very HTML the built book shows) is opened in headless Chromium at the
book's column (688 x 420 px) and measured from the picture: the model covers a good
share of the view and is not cut off, the camera looks from above the floor grid, and no
two frame names overlap. The live face gets the same scene (`RobotView.commands()`), and
its names are placed again whenever /tf moves the frames: checked without a browser."""
import json
import os
import sys

import numpy as np
import pytest

from labkit.robots.urdf import pose_matrix
from labkit.viz import meshcat_view

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "book"))
import meshcat_measure  # noqa: E402
BOOK = os.path.join(ROOT, "book")
WIDTH, HEIGHT = 688, 420


def stored_views():
    """(notebook, cell index, iframe html) of every stored 3D view of the book."""
    found = []
    for part in sorted(os.listdir(BOOK)):
        folder = os.path.join(BOOK, part)
        if not os.path.isdir(folder) or part.startswith("_"):
            continue
        for name in sorted(os.listdir(folder)):
            if not name.endswith(".ipynb"):
                continue
            with open(os.path.join(folder, name), encoding="utf-8") as handle:
                nb = json.load(handle)
            for index, cell in enumerate(nb["cells"]):
                for output in cell.get("outputs", []):
                    text = (output.get("data") or {}).get("text/html")
                    text = "".join(text) if isinstance(text, list) else (text or "")
                    if 'title="meshcat"' in text:
                        found.append((name, index, text))
    return found


VIEWS = stored_views()

@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from book_cdp import Browser, find_chromium
    binary = find_chromium()
    if binary is None:
        pytest.skip("chromium is not installed")
    base = tmp_path_factory.mktemp("framing")
    profile = base / "profile"
    profile.mkdir()
    b = Browser(binary, profile)
    page = b.page()
    page.call("Emulation.setDeviceMetricsOverride", width=WIDTH + 40, height=HEIGHT + 80,
              deviceScaleFactor=1, mobile=False)
    yield page, base
    page.close()
    b.close()


def test_the_book_stores_3d_views():
    names = {name for name, _, _ in VIEWS}
    assert {"ch22_tf2.ipynb", "ch23_urdf.ipynb"} <= names


@pytest.mark.parametrize("name,index,frame", VIEWS,
                         ids=[f"{n}-cell{i}" for n, i, _ in VIEWS])
def test_stored_3d_view_is_framed_for_the_reader(browser, name, index, frame):
    page, base = browser
    path = base / f"{name}-{index}.html"
    path.write_text('<!DOCTYPE html><html><head><meta charset="utf-8"></head>'
                    f'<body style="margin:0;padding:20px;width:{WIDTH}px">{frame}</body></html>',
                    encoding="utf-8")
    page.open(path.as_uri())
    assert meshcat_measure.count(page) == 1
    assert meshcat_measure.problems(page) == []
    assert page.errors() == []


def _frames_view():
    view = meshcat_view.RobotView(frame_scale=1.2, fixed_frame="world")
    view.set_frame_poses({"world": np.eye(4),
                          "turtle1": pose_matrix((5.5, 5.5, 0), (0, 0, 0)),
                          "carrot1": pose_matrix((5.5, 7.5, 0), (0, 0, 0)),
                          "turtle2": pose_matrix((4.0, 2.0, 0), (0, 0, 0.5))})
    return view


def _disjoint(boxes):
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if meshcat_view._overlap(boxes[a], boxes[b], margin=0.0):
                return False
    return True


def test_camera_is_framed_from_the_bounding_box():
    view = _frames_view()
    lo, hi = view.bounds()
    assert lo[0] == pytest.approx(0.0) and hi[1] == pytest.approx(7.5 + 1.2)
    cam = view.camera()
    np.testing.assert_allclose(cam.centre, (lo + hi) / 2)
    assert cam.position[2] > hi[2]                       # above everything
    _, _, points = view._extent()
    assert len(points) >= 4 * 4                         # origin and three axis tips a frame
    px = np.array([cam.project(p)[:2] for p in points])
    # the scene fills its share: its farthest point from the view's centre is at FILL
    reach = max(np.abs(px[:, 0] / (cam.width / 2) - 1).max(),
                np.abs(px[:, 1] / (cam.height / 2) - 1).max())
    assert reach == pytest.approx(meshcat_view.FILL, abs=1e-6)
    # what the page gets: the scene shifted to the orbit target, the camera above it
    commands = view.commands()
    shift = next(c for c in commands if c["path"] == "/meshcat" and c["type"] == "set_transform")
    np.testing.assert_allclose(np.array(shift["matrix"]).reshape(4, 4).T[:3, 3], -cam.centre,
                               rtol=1e-6)
    camera = next(c for c in commands if c["path"] == "/Cameras/default/rotated/<object>")
    assert camera["value"][1] > 0                        # meshcat's camera frame is Y up


def test_names_close_together_do_not_overlap_and_follow_the_frames_live(monkeypatch):
    view = _frames_view()
    view.commands()                                      # a page got the scene
    pushed = []
    monkeypatch.setattr(view, "_push", lambda commands: pushed.extend(commands))
    # turtle2 closes in on turtle1 and carrot1: the names stay apart at every step
    for k in range(12):
        x = 4.0 + 1.5 * k / 11
        y = 2.0 + 3.5 * k / 11
        view.set_frame_poses({"turtle2": pose_matrix((x, y, 0), (0, 0, 0.5 + k / 5))})
        boxes = view.label_boxes()
        assert set(boxes) == {"world", "turtle1", "carrot1", "turtle2"}
        assert _disjoint(boxes), boxes
    labels = [c for c in pushed if c["path"].endswith("/label")]
    assert labels and all(c["type"] == "set_transform" for c in labels)
    # the name sent last for turtle2 sits where label_boxes() says (in the view's pixels)
    last = [c for c in labels if c["path"] == "/meshcat/frames/turtle2/label"][-1]
    local = np.array(last["matrix"]).reshape(4, 4).T[:3, 3]
    pose = view._poses_now()["turtle2"]
    world = pose[:3, :3] @ local + pose[:3, 3]
    sx, sy, _ = view._view_camera.project(world)
    x, y, w, h = view.label_boxes()["turtle2"]
    assert x <= sx <= x + w and y <= sy <= y + h + 0.5 * h


def test_place_labels_keeps_names_apart_even_on_one_point():
    cam = meshcat_view.Camera(np.zeros(3), np.ones(3))
    anchors = {name: (300.0, 200.0) for name in ("carrot1", "turtle1", "turtle2", "world")}
    boxes = meshcat_view.place_labels(anchors, cam)
    assert _disjoint(boxes)
    for x, y, w, h in boxes.values():
        assert 0 <= x and x + w <= cam.width and 0 <= y and y + h <= cam.height


def test_robot_view_frames_the_robot_not_the_origin():
    from labkit.robots import facer
    view = meshcat_view.RobotView(facer.model_path())
    lo, hi = view.bounds()
    assert 0.2 < (hi - lo).max() < 0.6                   # the facer is ~0.3 m long
    assert view.camera().distance < 1.5
    drive = facer.drive_view(seconds=12.0, fps=10)
    lo, hi = drive.bounds()                              # the whole 1.2 m circle it drives
    assert 1.1 < hi[1] - lo[1] < 1.8


def test_snapshot_is_deterministic_with_names():
    view = _frames_view()
    assert view.iframe() == view.iframe()          # names placed the same way each time


def test_a_live_page_shown_before_anything_came_is_framed_when_frames_come(monkeypatch):
    """rviz2's view in JupyterLab: the page may be drawn before /tf or /robot_description
    arrive; the first frames bring their axes, names and a camera framed on them."""
    view = meshcat_view.RobotView(frame_scale=1.2, fixed_frame="world")
    view.commands()                                      # the page, on an empty scene
    pushed = []
    monkeypatch.setattr(view, "_push", lambda commands: pushed.extend(commands))
    view.set_frame_poses({"world": np.eye(4), "turtle1": pose_matrix((5.5, 5.5, 0), (0, 0, 0))})
    paths = [(c["type"], c["path"]) for c in pushed]
    assert ("set_object", "/meshcat/frames/turtle1/triad") in paths
    assert ("set_object", "/meshcat/frames/turtle1/label") in paths
    camera = [c for c in pushed if c["path"] == "/Cameras/default/rotated/<object>"]
    assert len(camera) == 1
    # world (0, 0) to turtle1 (5.5, 5.5) and its 1.2 m axes
    np.testing.assert_allclose(view._view_camera.centre[:2], (6.7 / 2, 6.7 / 2))
    # later moves do not take the reader's camera away again
    pushed.clear()
    view.set_frame_poses({"turtle1": pose_matrix((6.0, 5.5, 0), (0, 0, 0))})
    assert not [c for c in pushed if c["path"].startswith("/Cameras")]
    # a model that comes later (robot_description) is drawn, framed on it
    from labkit.robots import facer
    pushed.clear()
    view.set_model(facer.model_path())
    steps = [(c["type"], c["path"]) for c in pushed]
    assert steps.index(("delete", "/meshcat/robot")) < steps.index(
        ("set_object", "/meshcat/robot/base_link/visual_0"))
