"""Lidar points as a meshcat scene command, for the 3D viewer (labkit/viz/meshcat_view.py).

`set_scan_command(points)` returns the `set_object` command meshcat's viewer
understands (a three.js Points object); the viewer can store and push it like
its own objects. Ids are deterministic so stored notebooks do not change.
"""
import numpy as np

SCAN_PATH = "/meshcat/scan"
_counter = [0]


def _uuid(kind):
    _counter[0] += 1
    return f"labkit-scan-{kind}-{_counter[0]:06d}"


def _float32_array(values):
    import umsgpack
    data = np.ascontiguousarray(values, dtype=np.float32).tobytes()
    # 0x17: meshcat's msgpack extension code for a Float32Array
    return {"itemSize": 3, "type": "Float32Array", "array": umsgpack.Ext(0x17, data),
            "normalized": False}


def scan_object(points, color=(1.0, 0.0, 0.0), size=0.05, matrix=None):
    """A three.js Points object of (N, 3) points (e.g. world2d.scan_points())."""
    points = np.asarray(points, dtype=np.float32).reshape(-1, 3)
    colors = np.tile(np.asarray(color, dtype=np.float32), (len(points), 1))
    geometry = {"uuid": _uuid("geometry"), "type": "BufferGeometry",
                "data": {"attributes": {"position": _float32_array(points),
                                        "color": _float32_array(colors)}}}
    material = {"uuid": _uuid("material"), "type": "PointsMaterial", "color": 0xFFFFFF,
                "size": float(size), "vertexColors": 2}
    matrix = np.eye(4) if matrix is None else np.asarray(matrix, dtype=float)
    return {"metadata": {"version": 4.5, "type": "Object"},
            "geometries": [geometry], "materials": [material], "textures": [], "images": [],
            "object": {"uuid": _uuid("object"), "type": "Points",
                       "geometry": geometry["uuid"], "material": material["uuid"],
                       "matrix": [float(v) for v in matrix.T.flatten()]}}


def set_scan_command(points, path=SCAN_PATH, **kwargs):
    return {"type": "set_object", "path": path, "object": scan_object(points, **kwargs)}
