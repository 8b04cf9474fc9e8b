"""Shared by the live-view tests here: live time for one test, and a bounded wait."""
import time

import pytest

import labkit
from labkit.graph import world


@pytest.fixture
def live_time():
    """Live time (real threads, real waits) for one test; virtual again after it."""
    labkit.reset()
    world.set_mode("live")
    yield
    labkit.reset()
    world.set_mode("virtual")


def wait_until(predicate, seconds=10.0):
    """Poll `predicate` until it holds (or `seconds` pass); its last value."""
    end = time.monotonic() + seconds
    while time.monotonic() < end and not predicate():
        time.sleep(0.02)
    return predicate()


@pytest.fixture
def until():
    return wait_until
