"""The keyboard of turtle_teleop_key in a notebook: a focusable box that takes real
key presses (ipyevents) and also shows on-screen buttons.

Click the box (it gets a focus outline), then use the arrow keys and
G B V C D E R T / F / Q exactly as in the terminal; or click the buttons.
"""
import html

import ipywidgets as widgets

from labkit.sims.turtlesim.keys import key_name

# button label, key name, tooltip
_ROTATIONS = [("E", "e"), ("R", "r"), ("T", "t"), ("D", "d"), ("F", "f"), ("G", "g"),
              ("C", "c"), ("V", "v"), ("B", "b")]
_ARROWS = [("", None), ("\u2191", "up"), ("", None),
           ("\u2190", "left"), ("\u2193", "down"), ("\u2192", "right")]


def _spacer():
    return widgets.Label("", layout=widgets.Layout(width="24px"))


def _keys_html(rows):
    key = ("display:inline-block;width:30px;height:26px;line-height:26px;margin:2px;"
           "text-align:center;border:1px solid #888;border-radius:4px;background:#f4f4f4;"
           "font-family:monospace")
    gap = "display:inline-block;width:34px"
    out = []
    for row in rows:
        cells = "".join(f"<span style='{key}'>{html.escape(label)}</span>" if label
                        else f"<span style='{gap}'></span>" for label in row)
        out.append(f"<div>{cells}</div>")
    return "".join(out)


def static_keypad_html():
    """The teleop keys as a still picture (what the live widget looks like)."""
    arrows = _keys_html([["", "\u2191", ""], ["\u2190", "\u2193", "\u2192"]])
    rotations = _keys_html([["E", "R", "T"], ["D", "F", "G"], ["C", "V", "B"]])
    cell = "display:inline-block;vertical-align:middle;margin-right:18px"
    return ("<div style='border:1px solid #888;padding:6px;display:inline-block'>"
            "<b>turtle_teleop_key</b><br>"
            f"<div style='{cell}'>{arrows}</div><div style='{cell}'>{rotations}</div>"
            f"<div style='{cell}'>{_keys_html([['Q']])}</div></div>")


class TeleopWidget:
    """Calls `press(key_name)` for every key pressed or button clicked."""

    def __init__(self, press, title="turtle_teleop_key"):
        from ipyevents import Event
        self._press = press
        self.pressed = []            # key names seen, newest last (for display and tests)
        self.status = widgets.HTML(self._status_text())
        # boxes sized to their keys, never scrolled (ipywidgets boxes scroll by default)
        grid = dict(grid_template_columns="repeat(3, 44px)", grid_gap="4px",
                    overflow="visible")
        arrows = widgets.GridBox([self._button(label, key) for label, key in _ARROWS],
                                 layout=widgets.Layout(**grid))
        rotations = widgets.GridBox([self._button(label, key) for label, key in _ROTATIONS],
                                    layout=widgets.Layout(**grid))
        quit_button = self._button("Q", "q", width="60px")
        # the key help (BANNER) is printed once, by turtle_teleop_key itself, like in its
        # terminal: the pad does not repeat it
        self.box = widgets.VBox(
            [widgets.HTML("<b>%s</b> &mdash; click here, then type" % title),
             widgets.HBox([arrows, _spacer(), rotations, _spacer(), quit_button],
                          layout=widgets.Layout(align_items="center", overflow="visible")),
             self.status],
            layout=widgets.Layout(border="1px solid #888", padding="6px", width="fit-content",
                                  overflow="visible"))
        self.events = Event(source=self.box, watched_events=["keydown"],
                            prevent_default_action=True)
        self.events.on_dom_event(self._on_key)

    def _button(self, label, key, width="44px"):
        if key is None:
            return widgets.Label("", layout=widgets.Layout(width=width))
        button = widgets.Button(description=label, layout=widgets.Layout(width=width),
                                tooltip=key)
        button.on_click(lambda _: self.press(key))
        return button

    def _on_key(self, event):
        key = event.get("key", "")
        # the terminal version reads lower-case letters only (and arrows)
        if len(key) == 1 and not key.islower():
            return
        if key_name(key) is not None:
            self.press(key)

    def press(self, key):
        name = key_name(key)
        if name is None:
            return
        self.pressed.append(name)
        self.status.value = self._status_text()
        self._press(name)

    def _status_text(self):
        last = self.pressed[-1] if self.pressed else "none"
        return "<span style='font-size:11px;color:#555'>last key: %s</span>" % last

    def show(self):
        from labkit.viz.display import register_window, show
        register_window(self)           # shown again if the cell that started it re-runs
        # Static face (HTML book): a picture of the key pad. The banner itself is
        # already in the process output, so it is not repeated here.
        show(self.box, text="<turtle_teleop_key keyboard>", html=static_keypad_html())

    def _ipython_display_(self):
        self.show()

    def close(self):
        self.events.close()
        self.box.close()


class KeyPad:
    """A key pad for a keyboard node that reads single characters (teleop_twist_keyboard):
    a focusable box taking real key presses, and a button for each key in `groups`
    (rows of characters). `press(char)` gets each character as the terminal would."""

    def __init__(self, press, title, groups, accept=lambda ch: len(ch) == 1):
        from ipyevents import Event
        self._press = press
        self._accept = accept
        self.title = title
        self.groups = groups
        self.pressed = []
        self.status = widgets.HTML(self._status_text())
        pads = []
        for rows in groups:
            width = max(len(row) for row in rows)
            keys = [self._button(ch) for row in rows for ch in row.ljust(width)]
            pads.append(widgets.GridBox(keys, layout=widgets.Layout(
                grid_template_columns=f"repeat({width}, 44px)", grid_gap="4px",
                overflow="visible")))
            pads.append(_spacer())
        self.box = widgets.VBox(
            [widgets.HTML("<b>%s</b> &mdash; click here, then type" % html.escape(title)),
             widgets.HBox(pads[:-1], layout=widgets.Layout(align_items="center",
                                                           overflow="visible")),
             self.status],
            layout=widgets.Layout(border="1px solid #888", padding="6px", width="fit-content",
                                  overflow="visible"))
        self.events = Event(source=self.box, watched_events=["keydown"],
                            prevent_default_action=True)
        self.events.on_dom_event(lambda event: self.press(event.get("key", "")))

    def _button(self, ch):
        if ch == " ":
            return widgets.Label("", layout=widgets.Layout(width="44px"))
        button = widgets.Button(description=ch, layout=widgets.Layout(width="44px"))
        button.on_click(lambda _: self.press(ch))
        return button

    def press(self, ch):
        if not self._accept(ch):
            return
        self.pressed.append(ch)
        self.status.value = self._status_text()
        self._press(ch)

    def _status_text(self):
        last = self.pressed[-1] if self.pressed else "none"
        return "<span style='font-size:11px;color:#555'>last key: %s</span>" % html.escape(last)

    def static_html(self):
        cell = "display:inline-block;vertical-align:middle;margin-right:18px"
        pads = "".join(f"<div style='{cell}'>{_keys_html([list(r) for r in rows])}</div>"
                       for rows in self.groups)
        return ("<div style='border:1px solid #888;padding:6px;display:inline-block'>"
                f"<b>{html.escape(self.title)}</b><br>{pads}</div>")

    def show(self):
        from labkit.viz.display import register_window, show
        register_window(self)
        show(self.box, text=f"<{self.title} keyboard>", html=self.static_html())

    def _ipython_display_(self):
        self.show()

    def close(self):
        self.events.close()
        self.box.close()
