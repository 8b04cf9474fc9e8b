"""A static picture of a URDF model (what RViz would show), drawn with matplotlib for
the book's page: boxes, cylinders, spheres and STL/COLLADA meshes in their material
colours, each link's frame as a small axis triad.

matplotlib's 3D axes paint whole collections in one order, so a chassis drawn as one
collection covers the wheel in front of it. Here every face of every link goes into ONE
collection, large faces cut into small pieces, and matplotlib sorts the pieces by depth:
the wheel that faces the camera is painted over the chassis, the far one under it.

The figure is the book's column wide (720 px) and its smallest text is 10 px or more.
"""
import os
import re
import struct

import numpy as np

COLUMN_PX = 720            # the book's text column
DPI = 100
FIGSIZE = (COLUMN_PX / DPI, 4.6)
TICK_PT = 8                # 8 pt at 100 dpi: 11 px
LABEL_PT = 10
TITLE_PT = 11
ELEVATION, AZIMUTH = 22, -55

_GREY = (0.8, 0.8, 0.8, 1.0)          # RViz draws a link without material light grey
_DARK = (0.25, 0.25, 0.25, 1.0)       # a mesh without material (its file's own colours)


def _mesh_faces(path):
    """Triangles of a binary STL, or of every <triangles> block of a COLLADA file."""
    if path.lower().endswith(".stl"):
        with open(path, "rb") as handle:
            data = handle.read()
        n = struct.unpack("<I", data[80:84])[0]
        rec = np.frombuffer(data[84:84 + 50 * n],
                            dtype=np.dtype([("v", "<f4", (12,)), ("a", "<u2")]))
        return list(rec["v"][:, 3:].reshape(-1, 3, 3).astype(float))
    with open(path, encoding="utf-8") as handle:
        text = handle.read()
    faces = []
    for arr, idx in zip(re.findall(r"<float_array[^>]*>([^<]*)<", text),
                        re.findall(r"<p>([^<]*)</p>", text)):
        v = np.array(arr.split(), float).reshape(-1, 3)
        faces += list(v[np.array(idx.split(), int).reshape(-1, 3)])
    return faces


def _grid(a, b, c, d, pieces):
    """The quad a-b-c-d cut into pieces x pieces smaller quads."""
    out = []
    for i in range(pieces):
        for j in range(pieces):
            s0, s1, t0, t1 = i / pieces, (i + 1) / pieces, j / pieces, (j + 1) / pieces

            def at(s, t):
                return (1 - s) * ((1 - t) * a + t * d) + s * ((1 - t) * b + t * c)
            out.append(np.array([at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1)]))
    return out


def _outward(faces):
    """Faces of a convex shape centred on its origin, each wound so that its normal points
    out (matplotlib shades a face by its normal: inward ones come out dark)."""
    out = []
    for f in faces:
        normal = np.cross(f[1] - f[0], f[2] - f[0])
        out.append(f[::-1] if normal @ f.mean(axis=0) < 0 else f)
    return out


def faces_of(shape, base_dir=None, piece=0.03):
    """A URDF geometry as polygons in its own frame; no polygon much larger than
    `piece` metres, so that sorting by depth paints them right."""
    from urdf_parser_py import urdf as U
    u = np.linspace(0, 2 * np.pi, 25)
    if isinstance(shape, U.Box):
        x, y, z = (s / 2 for s in shape.size)
        c = np.array([[i * x, j * y, k * z] for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)])
        out = []
        for f in ([0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4],
                  [1, 3, 7, 5]):
            quad = c[f]
            size = max(np.linalg.norm(quad[1] - quad[0]), np.linalg.norm(quad[3] - quad[0]))
            out += _grid(*quad, max(1, int(np.ceil(size / piece))))
        return _outward(out)
    if isinstance(shape, U.Cylinder):
        r, h = shape.radius, shape.length / 2
        ring = np.stack([r * np.cos(u), r * np.sin(u)], 1)
        side = [np.array([[*ring[i], -h], [*ring[i + 1], -h], [*ring[i + 1], h], [*ring[i], h]])
                for i in range(24)]
        caps = [np.array([[0, 0, z], [*ring[i], z], [*ring[i + 1], z]])
                for z in (-h, h) for i in range(24)]
        return _outward(side + caps)
    if isinstance(shape, U.Sphere):
        v, r = np.linspace(0, np.pi, 13), shape.radius

        def p(a, b):
            return r * np.array([np.cos(a) * np.sin(b), np.sin(a) * np.sin(b), np.cos(b)])
        # (the rows at the poles start with two equal points: wind by the other three)
        return [q if np.cross(q[2] - q[1], q[3] - q[1]) @ q.mean(axis=0) >= 0 else q[::-1]
                for q in (np.array([p(u[i], v[j]), p(u[i + 1], v[j]), p(u[i + 1], v[j + 1]),
                                    p(u[i], v[j + 1])]) for i in range(24) for j in range(12))]
    if isinstance(shape, U.Mesh):
        from labkit.robots.packages import resolve_uri
        scale = np.array(shape.scale or (1.0, 1.0, 1.0))
        return [f * scale for f in _mesh_faces(resolve_uri(shape.filename, base_dir))]
    return []


def figure(model, positions=None, title=None):
    """The matplotlib Figure of a URDF model (a RobotModel, URDF text or a .urdf/.xacro
    path) at these joint positions ({joint: position}), with each link's frame."""
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    from urdf_parser_py import urdf as U

    from labkit import robots
    from labkit.robots.urdf import pose_matrix
    if not hasattr(model, "links"):
        title = title or os.path.basename(str(model))
        model = robots.load(model)
    base_dir = os.path.dirname(model.filename) if getattr(model, "filename", None) else None
    poses = model.link_poses(positions or {})
    fig = plt.figure(figsize=FIGSIZE, dpi=DPI)
    ax = fig.add_subplot(111, projection="3d")
    faces, colours, points = [], [], [np.zeros((1, 3))]
    for name, link in model.links.items():
        for visual in link.visuals:
            o = visual.origin
            m = poses[name] @ pose_matrix(o.xyz if o and o.xyz else (0, 0, 0),
                                          o.rpy if o and o.rpy else (0, 0, 0))
            mine = [(m[:3, :3] @ f.T).T + m[:3, 3] for f in faces_of(visual.geometry, base_dir)]
            if not mine:
                continue
            rgba = model.material_rgba(visual)
            if rgba is None:
                rgba = _DARK if isinstance(visual.geometry, U.Mesh) else _GREY
            points += mine
            faces += mine
            colours += [tuple(rgba)] * len(mine)
    if faces:
        # one collection: matplotlib sorts all faces of all links by depth together
        # (shaded by each face's normal, as a lit scene; pieces without seams)
        from matplotlib.colors import LightSource
        light = LightSource(azdeg=AZIMUTH + 90, altdeg=55)     # from above, behind the camera
        ax.add_collection3d(Poly3DCollection(faces, facecolors=colours, edgecolors=colours,
                                             linewidths=0.3, shade=True, lightsource=light))
    for m in poses.values():
        for k, colour in enumerate("rgb"):
            ax.plot(*zip(m[:3, 3], m[:3, 3] + 0.06 * m[:3, k]), color=colour, linewidth=1.4)
    allp = np.vstack(points)
    allp = allp[np.isfinite(allp).all(axis=1)]
    c = (allp.max(0) + allp.min(0)) / 2
    r = max((allp.max(0) - allp.min(0)).max() / 2, 0.12)
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=ELEVATION, azim=AZIMUTH)
    ax.set_xlabel("x", fontsize=LABEL_PT)
    ax.set_ylabel("y", fontsize=LABEL_PT)
    ax.set_zlabel("z", fontsize=LABEL_PT)
    ax.tick_params(labelsize=TICK_PT)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(plt.MaxNLocator(4))
    if title:
        ax.set_title(title, fontsize=TITLE_PT)
    fig.subplots_adjust(left=0, right=1, bottom=0.02, top=0.93)
    return fig


def draw(model, positions=None, title=None):
    """Show the picture in the notebook (the chapter's "what RViz shows")."""
    import matplotlib.pyplot as plt
    figure(model, positions, title)
    plt.show()


def smallest_text_px(fig, column_px=COLUMN_PX):
    """The smallest visible text of a figure in px once the book fits it in its column."""
    from matplotlib.text import Text
    width_px = fig.get_figwidth() * fig.dpi
    scale = min(1.0, column_px / width_px)
    fig.canvas.draw()
    sizes = [t.get_fontsize() * fig.dpi / 72.0 * scale for t in fig.findobj(Text)
             if t.get_visible() and t.get_text().strip()]
    return min(sizes) if sizes else None
