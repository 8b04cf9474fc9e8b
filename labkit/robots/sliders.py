"""The joint_state_publisher_gui window, as an ipywidgets panel: one slider per
free joint (limits from the URDF, continuous joints -pi..pi), plus Randomize and
Center buttons like the Qt GUI. The node keeps running in its process; the
panel just writes positions into it.

`panel()` returns the panel of the most recent joint_state_publisher_gui
(None if there is none); the book shows it with `display(panel())`.
"""
import random

_panels = []


def attach(node):
    """Build (lazily, when first shown) the slider panel of a JointStatePublisher node."""
    _panels.append(node)
    node.set_robot_description_update_cb(lambda: _rebuild(node))


def panel(node=None):
    """The ipywidgets panel of `node` (default: the latest GUI node still alive)."""
    if node is None:
        if not _panels:
            return None
        node = _panels[-1]
    if getattr(node, "_labkit_panel", None) is None:
        node._labkit_panel = _build(node)
    return node._labkit_panel


def _rebuild(node):
    if getattr(node, "_labkit_panel", None) is not None:
        node._labkit_panel.children = _build(node).children


def _build(node):
    import ipywidgets as widgets
    rows = {}
    for name in node.joint_list:
        joint = node.free_joints.get(name)
        if joint is None:          # mimic joints follow their parent, no slider
            continue
        slider = widgets.FloatSlider(
            value=float(joint["position"]), min=joint["min"], max=joint["max"],
            step=(joint["max"] - joint["min"]) / 1000.0 or 0.001, description=name,
            readout_format=".2f", continuous_update=True,
            style={"description_width": "initial"}, layout=widgets.Layout(width="420px"))
        slider.observe(lambda change, n=name: node.set_position(n, change["new"]), "value")
        rows[name] = slider

    def randomize(_):
        for name, slider in rows.items():
            slider.value = random.uniform(slider.min, slider.max)

    def center(_):
        for name, slider in rows.items():
            slider.value = node.free_joints[name]["zero"]

    buttons = widgets.HBox([widgets.Button(description="Randomize"),
                            widgets.Button(description="Center")])
    buttons.children[0].on_click(randomize)
    buttons.children[1].on_click(center)
    box = widgets.VBox(list(rows.values()) + [buttons])
    box.sliders = rows
    return box
