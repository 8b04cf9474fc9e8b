import os
import sys

import pytest

import labkit
from labkit.graph import world

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FACER_SRC = os.path.join(REPO, 'book', 'part2_facer', 'facer_src', 'src')
PACKAGES = ('facer_input', 'facer_handle', 'facer_output')


@pytest.fixture(scope='module')
def hook():
    """`import rclpy`, `import cv_bridge`, `import facer_interfaces.srv` resolve to labkit."""
    from labkit import compat
    import labkit.interfaces as ifc
    import labkit.vision
    was_active = compat.is_active()
    compat.activate(quiet=True)
    labkit.vision.register()
    ifc.add_share_path(FACER_SRC)
    added = [os.path.join(FACER_SRC, pkg) for pkg in PACKAGES]
    sys.path[:0] = added
    yield
    for path in added:
        sys.path.remove(path)
    for name in [m for m in sys.modules if m.split('.')[0] in PACKAGES]:
        del sys.modules[name]
    ifc.remove_share_path(FACER_SRC)
    if not was_active:
        compat.deactivate()


@pytest.fixture
def virtual(hook):
    labkit.reset()
    world.set_mode('virtual')
    yield world
    labkit.reset()


@pytest.fixture
def bridge(hook):
    from cv_bridge import CvBridge
    return CvBridge()
