"""Measuring a stored 3D view (meshcat's static face: an `<iframe srcdoc>` titled
"meshcat") in a page open in headless Chromium: where the camera is, how much of the
view the model covers, where each frame name lands. Shared by
tests/viz/test_meshcat_framing.py (the notebooks' stored outputs) and
tests/book/test_meshcat_views.py (the built book's pages)."""
import base64
import io
import json
import time

import numpy as np

READY = """(() => { const f = document.querySelectorAll('iframe[title=meshcat]')[K];
  const w = f && f.contentWindow; const v = w && w.viewer;
  return !!(v && v.scene_tree.find(['meshcat']).object.children.length >= 1); })()"""

# show: 'all' | 'model' (no grid) | 'none' (background only) | a frame name (its name only)
SHOW = """(async (what, at) => {
  const w = document.querySelectorAll('iframe[title=meshcat]')[K].contentWindow, v = w.viewer;
  const root = v.scene_tree.find(['meshcat']).object;
  v.scene_tree.find(['Grid']).object.visible = (what === 'all');
  root.visible = (what !== 'none');
  root.traverse((o) => {
    if (o === root) return;
    const label = o.isSprite;
    if (what === 'all' || what === 'model') { if (o.isMesh || o.isLine || o.isSprite) o.visible = true; }
    else if (o.isMesh || o.isLine) o.visible = false;
    if (label && what !== 'all' && what !== 'model') {
      let n = o, name = null;
      while (n && n !== root) { if (n.parent && n.parent.name === 'frames') { name = n.name; } n = n.parent; }
      o.visible = (name === what);
    }
  });
  if (v.animator && v.animator.actions.length) { v.animator.pause(); v.animator.seek(at); }
  v.set_dirty();
  await new Promise((r) => w.requestAnimationFrame(() => w.requestAnimationFrame(r)));
  return true;
})"""

FACTS = """(() => { const w = document.querySelectorAll('iframe[title=meshcat]')[K].contentWindow, v = w.viewer;
  const V = v.camera.position.constructor;
  const cam = v.camera.getWorldPosition(new V());
  const grid = v.scene_tree.find(['Grid']).object.getWorldPosition(new V());
  const t = v.controls.target;
  const names = [];
  v.scene_tree.find(['meshcat']).object.traverse((o) => {
    if (o.isSprite && o.parent && o.parent.parent && o.parent.parent.parent &&
        o.parent.parent.parent.name === 'frames') names.push(o.parent.parent.name);
  });
  return {cam: [cam.x, cam.y, cam.z], grid_y: grid.y, target: [t.x, t.y, t.z],
          names: names, paused: !!(v.animator && v.animator.clips && v.animator.clips.length)};
})()"""


def _js(script, k):
    return script.replace("[K]", f"[{int(k)}]")


def _shot(page, k):
    from PIL import Image
    r = json.loads(page.evaluate(_js(
        "(() => { const f = document.querySelectorAll('iframe[title=meshcat]')[K];"
        " f.scrollIntoView({block: 'center'}); const b = f.getBoundingClientRect();"
        " return JSON.stringify({x: b.x + window.scrollX, y: b.y + window.scrollY,"
        " width: b.width, height: b.height}); })()", k)))
    data = page.call("Page.captureScreenshot", format="png", clip={
        "x": r["x"], "y": r["y"], "width": r["width"], "height": r["height"], "scale": 1})
    img = Image.open(io.BytesIO(base64.b64decode(data["data"]))).convert("RGB")
    return np.asarray(img, dtype=np.int16)


def _mask_box(picture, background):
    """(x0, y0, x1, y1) of the pixels that differ from the background, or None."""
    diff = np.abs(picture - background).sum(axis=2) > 40
    ys, xs = np.nonzero(diff)
    if not len(xs):
        return None
    return xs.min(), ys.min(), xs.max(), ys.max()


DURATION = """(() => { const a = document.querySelectorAll('iframe[title=meshcat]')[K].contentWindow.viewer.animator;
  return a && a.actions.length ? Math.max(...a.actions.map((x) => x._clip.duration)) : 0; })()"""


def _show(page, k, what, at=0.0):
    page.evaluate(f"({_js(SHOW, k)})({json.dumps(what)}, {at})")
    time.sleep(0.15)
    return _shot(page, k)


def count(page):
    return page.evaluate("document.querySelectorAll('iframe[title=meshcat]').length")


def problems(page, k=0, min_width=0.35, min_height=0.45):
    """What is wrong with the k-th 3D view of the open page (empty when it is framed for
    the reader): the camera above the floor grid looking down >= 15 deg, the model (over
    an animation's whole run) >= min_width of the view's width or >= min_height of its
    height and not cut off, no two frame names overlapping."""
    page.wait_for(_js(READY, k), timeout=60)
    time.sleep(0.5)
    found = []
    facts = page.evaluate(_js(FACTS, k))
    cam, target = np.array(facts["cam"]), np.array(facts["target"])
    if facts["cam"][1] <= facts["grid_y"]:
        found.append("the camera is below the floor grid")
    drop = (cam[1] - target[1]) / np.linalg.norm(cam - target)
    if drop < np.sin(np.radians(15)):
        found.append(f"the camera looks from {np.degrees(np.arcsin(drop)):.0f} deg")
    background = _show(page, k, "none")
    height, width = background.shape[:2]
    duration = page.evaluate(_js(DURATION, k)) or 0.0
    boxes = [_mask_box(_show(page, k, "model", duration * i / 8), background)
             for i in (range(8) if duration else [0])]
    if any(b is None for b in boxes):
        return found + ["nothing drawn"]
    x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
    x1, y1 = max(b[2] for b in boxes), max(b[3] for b in boxes)
    w, h = x1 - x0 + 1, y1 - y0 + 1
    if w < min_width * width and h < min_height * height:
        found.append(f"the model is {w} x {h} px in a {width} x {height} view")
    if not (x0 > 0 and y0 > 0 and x1 < width - 1 and y1 < height - 1):
        found.append(f"the model is cut off: {(x0, y0, x1, y1)}")
    names = {}
    for name in facts["names"]:
        box = _mask_box(_show(page, k, name), background)
        if box is None:
            found.append(f"the name {name} is not drawn")
        else:
            names[name] = box
    order = sorted(names)
    for i, a in enumerate(order):
        for b in order[i + 1:]:
            ba, bb = names[a], names[b]
            if not (ba[2] < bb[0] or bb[2] < ba[0] or ba[3] < bb[1] or bb[3] < ba[1]):
                found.append(f"the names {a} {ba} and {b} {bb} overlap")
    _show(page, k, "all")
    return found


