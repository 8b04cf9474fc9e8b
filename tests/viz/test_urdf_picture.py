"""ch23's static "what RViz shows" pictures: painted in depth order (the wheel facing
the camera in front of the chassis, the far one behind it) and legible in the book's
720 px column (every text >= 10 px), as stored in the chapter."""
import base64
import io
import json
import os

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from labkit.viz import urdf_picture  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CH23 = os.path.join(ROOT, "book", "part3_tools", "ch23_urdf.ipynb")

# the facer's chassis and wheels (sizes of 03-origins.urdf), each in a colour of its own
CART = """<?xml version="1.0"?>
<robot name="cart">
  <link name="base_link">
    <visual><origin xyz="0 0 0.05"/><geometry><box size="0.3 0.2 0.08"/></geometry>
      <material name="chassis"><color rgba="0.5 0.5 0.5 {alpha}"/></material></visual>
  </link>
  <link name="right_wheel">
    <visual><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.05" length="0.03"/></geometry>
      <material name="red"><color rgba="1 0 0 1"/></material></visual>
  </link>
  <link name="left_wheel">
    <visual><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.05" length="0.03"/></geometry>
      <material name="blue"><color rgba="0 0 1 1"/></material></visual>
  </link>
  <joint name="right" type="continuous"><parent link="base_link"/><child link="right_wheel"/>
    <origin xyz="0.05 -0.115 0.05"/><axis xyz="0 1 0"/></joint>
  <joint name="left" type="continuous"><parent link="base_link"/><child link="left_wheel"/>
    <origin xyz="0.05 0.115 0.05"/><axis xyz="0 1 0"/></joint>
</robot>
"""


def _pixels(alpha):
    fig = urdf_picture.figure(CART.format(alpha=alpha), title="cart")
    fig.canvas.draw()
    rgb = np.asarray(fig.canvas.buffer_rgba())[:, :, :3].astype(int)
    import matplotlib.pyplot as plt
    plt.close(fig)
    # shading darkens a colour but keeps its hue: red wheel, blue wheel
    red = (rgb[:, :, 0] > 60) & (rgb[:, :, 0] > 3 * rgb[:, :, 1]) & (rgb[:, :, 0] > 3 * rgb[:, :, 2])
    blue = (rgb[:, :, 2] > 60) & (rgb[:, :, 2] > 3 * rgb[:, :, 0]) & (rgb[:, :, 2] > 3 * rgb[:, :, 1])
    return red.sum(), blue.sum()


def test_the_wheel_facing_the_camera_is_painted_over_the_chassis():
    # the camera looks from -y (azimuth -55): the right wheel is in front of the chassis
    red_alone, blue_alone = _pixels(alpha=0.0)       # chassis invisible: whole wheels
    red, blue = _pixels(alpha=1.0)
    assert red_alone > 500 and blue_alone > 100
    assert red >= 0.97 * red_alone, (red, red_alone)   # nothing covers the near wheel
    assert blue <= 0.7 * blue_alone, (blue, blue_alone)  # the chassis hides the far one


def test_the_picture_is_legible_in_the_column():
    fig = urdf_picture.figure(CART.format(alpha=1.0), title="cart")
    assert fig.get_figwidth() * fig.dpi == urdf_picture.COLUMN_PX
    assert urdf_picture.smallest_text_px(fig) >= 10.0
    import matplotlib.pyplot as plt
    plt.close(fig)


def test_the_measure_sees_small_text():
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(3.6, 3.6), dpi=72)      # the old picture: 259 px, 6 pt ticks
    ax = fig.add_subplot(111)
    ax.tick_params(labelsize=6)
    assert urdf_picture.smallest_text_px(fig) < 10.0
    plt.close(fig)


def _stored_pictures():
    with open(CH23, encoding="utf-8") as handle:
        nb = json.load(handle)
    for index, cell in enumerate(nb["cells"]):
        if cell["cell_type"] == "code" and "draw(" in "".join(cell["source"]) \
                and "def draw" not in "".join(cell["source"]):
            for output in cell.get("outputs", []):
                png = (output.get("data") or {}).get("image/png")
                if png:
                    yield index, base64.b64decode("".join(png) if isinstance(png, list) else png)


def test_ch23_stores_the_pictures_at_the_column_size():
    from PIL import Image
    found = list(_stored_pictures())
    assert len(found) >= 6                           # 01 .. 05 and the xacro one
    for index, png in found:
        width, _ = Image.open(io.BytesIO(png)).size
        # the notebook crops the figure's margins; never wider than the column (so never
        # scaled down: its text keeps its 11 px), and not the old 259 px stamp
        assert 400 <= width <= urdf_picture.COLUMN_PX, f"cell {index}: {width} px wide"


@pytest.mark.parametrize("name", ["03-origins.urdf", "05-meshes.urdf"])
def test_facer_pictures_draw_every_visual(name):
    from labkit import robots
    path = os.path.join(robots.share_directory("facer_description"), "urdf", name)
    fig = urdf_picture.figure(path)
    assert fig.axes[0].get_title() == name
    (collection,) = fig.axes[0].collections
    assert len(collection.get_facecolors()) > 500    # every link, its faces cut small
    import matplotlib.pyplot as plt
    plt.close(fig)
