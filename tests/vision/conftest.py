import os
import sys

import pytest

import labkit
from labkit.graph import world

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FACER_SRC = os.path.join(REPO, 'book', 'part2_facer', 'facer_src', 'src')
PACKAGES = ('facer_input', 'facer_handle', 'facer_output')


@pytest.fixture(scope='session')
def hook():
    """`import rclpy`, `import cv_bridge`, `import facer_interfaces.srv` resolve to labkit."""
    from labkit import compat
    import labkit.interfaces as ifc
    import labkit.vision
    compat.activate(quiet=True)
    labkit.vision.register()
    ifc.add_share_path(FACER_SRC)
    for pkg in PACKAGES:
        path = os.path.join(FACER_SRC, pkg)
        if path not in sys.path:
            sys.path.insert(0, path)
    yield


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
