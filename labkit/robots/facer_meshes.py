"""The two meshes of the facer robot, made here with numpy (no CAD program):

- `head.stl`: the camera head, a rounded block (a superellipsoid), binary STL;
- `wheel.dae`: a wheel along the y axis, a black tyre and a grey hub, COLLADA
  with its own colours (so the URDF needs no <material> for it).

`python -m labkit.robots.facer_meshes DIR` writes both into DIR; the files in
facer_description/meshes were made this way. Units are metres.
"""
import os
import struct
import sys

import numpy as np

HEAD_HALF = (0.045, 0.06, 0.035)      # half extents along x, y, z
WHEEL_RADIUS, WHEEL_WIDTH, HUB_RADIUS = 0.05, 0.03, 0.03


def _signed_power(v, p):
    return np.sign(v) * np.abs(v) ** p


def head_triangles(half=HEAD_HALF, exponent=0.4, rings=12, segments=24):
    """Triangles (n, 3, 3) of a superellipsoid: a box with rounded edges."""
    a, b, c = half
    eta = np.linspace(-np.pi / 2, np.pi / 2, rings + 1)
    omega = np.linspace(-np.pi, np.pi, segments + 1)
    ce, se = _signed_power(np.cos(eta), exponent), _signed_power(np.sin(eta), exponent)
    co, so = _signed_power(np.cos(omega), exponent), _signed_power(np.sin(omega), exponent)
    grid = np.stack([a * np.outer(ce, co), b * np.outer(ce, so),
                     c * np.outer(se, np.ones_like(omega))], axis=-1)
    tris = []
    for i in range(rings):
        for j in range(segments):
            p00, p01 = grid[i, j], grid[i, j + 1]
            p10, p11 = grid[i + 1, j], grid[i + 1, j + 1]
            if i > 0:
                tris.append((p00, p01, p11))
            if i < rings - 1:
                tris.append((p00, p11, p10))
    return np.array(tris)


def stl_bytes(triangles, name=b"facer head"):
    """Binary STL: 80-byte header, count, then normal + 3 vertices + 2 spare bytes each."""
    out = [name.ljust(80, b" "), struct.pack("<I", len(triangles))]
    for t in triangles:
        n = np.cross(t[1] - t[0], t[2] - t[0])
        length = np.linalg.norm(n)
        n = n / length if length > 0 else n
        out.append(struct.pack("<12fH", *n, *t[0], *t[1], *t[2], 0))
    return b"".join(out)


def _ring(radius, y, segments):
    t = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    return np.stack([radius * np.cos(t), np.full_like(t, y), radius * np.sin(t)], axis=1)


def wheel_parts(segments=32):
    """{part: (vertices, triangles)}: the tyre (tread and side walls) and the hub caps."""
    h = WHEEL_WIDTH / 2
    outer_l, outer_r = _ring(WHEEL_RADIUS, h, segments), _ring(WHEEL_RADIUS, -h, segments)
    inner_l, inner_r = _ring(HUB_RADIUS, h, segments), _ring(HUB_RADIUS, -h, segments)
    tyre_v = np.concatenate([outer_l, outer_r, inner_l, inner_r])
    tyre_t = []
    n = segments
    for k in range(n):
        m = (k + 1) % n
        tyre_t += [(k, n + k, n + m), (k, n + m, m)]                      # tread
        tyre_t += [(k, m, 2 * n + m), (k, 2 * n + m, 2 * n + k)]          # left wall
        tyre_t += [(n + k, 3 * n + m, n + m), (n + k, 3 * n + k, 3 * n + m)]  # right wall
    hub_v = np.concatenate([inner_l, inner_r, [[0, h, 0], [0, -h, 0]]])
    hub_t = []
    for k in range(n):
        m = (k + 1) % n
        hub_t += [(2 * n, m, k), (2 * n + 1, n + k, n + m)]
    return {"tyre": (tyre_v, np.array(tyre_t)), "hub": (hub_v, np.array(hub_t))}


_COLOURS = {"tyre": (0.08, 0.08, 0.08, 1.0), "hub": (0.6, 0.6, 0.62, 1.0)}


def dae_text(parts=None):
    """A COLLADA 1.4.1 document: one geometry per part, each with its own colour."""
    parts = parts or wheel_parts()
    fmt = lambda values: " ".join(f"{v:.5g}" for v in np.asarray(values).ravel())
    effects, materials, geometries, nodes = [], [], [], []
    for name, (verts, tris) in parts.items():
        effects.append(
            f'    <effect id="{name}-effect"><profile_COMMON><technique sid="common"><lambert>'
            f'<diffuse><color>{fmt(_COLOURS[name])}</color></diffuse>'
            f'</lambert></technique></profile_COMMON></effect>')
        materials.append(f'    <material id="{name}-material" name="{name}">'
                         f'<instance_effect url="#{name}-effect"/></material>')
        geometries.append(
            f'    <geometry id="{name}-mesh" name="{name}"><mesh>\n'
            f'      <source id="{name}-positions">'
            f'<float_array id="{name}-array" count="{verts.size}">{fmt(verts)}</float_array>'
            f'<technique_common><accessor source="#{name}-array" count="{len(verts)}" stride="3">'
            f'<param name="X" type="float"/><param name="Y" type="float"/>'
            f'<param name="Z" type="float"/></accessor></technique_common></source>\n'
            f'      <vertices id="{name}-vertices"><input semantic="POSITION" '
            f'source="#{name}-positions"/></vertices>\n'
            f'      <triangles material="{name}-material" count="{len(tris)}">'
            f'<input semantic="VERTEX" source="#{name}-vertices" offset="0"/>'
            f'<p>{" ".join(str(int(i)) for i in tris.ravel())}</p></triangles>\n'
            f'    </mesh></geometry>')
        nodes.append(
            f'      <node id="{name}" name="{name}"><instance_geometry url="#{name}-mesh">'
            f'<bind_material><technique_common><instance_material symbol="{name}-material" '
            f'target="#{name}-material"/></technique_common></bind_material>'
            f'</instance_geometry></node>')
    nl = "\n"
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><contributor><authoring_tool>labkit facer_meshes</authoring_tool></contributor>
    <unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_effects>
{nl.join(effects)}
  </library_effects>
  <library_materials>
{nl.join(materials)}
  </library_materials>
  <library_geometries>
{nl.join(geometries)}
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="wheel-scene">
{nl.join(nodes)}
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#wheel-scene"/></scene>
</COLLADA>
"""


def write(folder):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "head.stl"), "wb") as handle:
        handle.write(stl_bytes(head_triangles()))
    with open(os.path.join(folder, "wheel.dae"), "w", encoding="utf-8") as handle:
        handle.write(dae_text())


if __name__ == "__main__":
    write(sys.argv[1] if len(sys.argv) > 1 else ".")
