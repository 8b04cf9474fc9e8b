"""ament: packages and workspaces (layer 4).

- `create`: `ros2 pkg create` (Humble's arguments, output, files).
- `manifest`: read package.xml and check it as catkin_pkg does.
- `files`: the book's sandbox home folder and a few shell commands (`mkdir`,
  `cd`, `pwd`, `ls`, `cat`, `tree`) that print paths as a terminal in it would.
"""
from labkit.ament.files import (cat, cd, leave_home, ls, mkdir, pwd, tree,  # noqa: F401
                                use_home)

# --- workspaces (colcon build, source, the ament index, rosdep) -------------------------------
# `ros2 pkg` asks labkit.ament for package_names() / package_prefix(); register() (called by
# labkit.plugins) adds the `ament_index_python` import name and the magics.
# Entry points: labkit.ament.colcon.run_command(command), labkit.ament.source.run(path),
# labkit.ament.rosdep.run_command(command).
from labkit.ament.index import package_names, package_prefix  # noqa: E402,F401


def register():
    """labkit.plugins hook: the `ament_index_python` import name and the magics."""
    from labkit import compat
    from labkit.plugins import register_magic
    compat.register_alias('ament_index_python', 'labkit.ament.ament_index_python')
    from labkit.ament import magics as ament_magics
    for name, fn in ament_magics.MAGICS.items():
        register_magic(name, fn)
