"""ament: packages and workspaces (layer 4).

- `create`: `ros2 pkg create` (Humble's arguments, output, files).
- `manifest`: read package.xml and check it as catkin_pkg does.
- `files`: the book's sandbox home folder and a few shell commands (`mkdir`,
  `cd`, `pwd`, `ls`, `cat`, `tree`) that print paths as a terminal in it would.
"""
from labkit.ament.files import (cat, cd, leave_home, ls, mkdir, pwd, tree,  # noqa: F401
                                use_home)
