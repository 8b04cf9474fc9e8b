import os

import pytest

import labkit.interfaces as li

from ifc_paths import DATA, TEST_SHARE  # noqa: F401


@pytest.fixture(scope='module')
def test_msgs():
    """test_msgs (rosidl's test interfaces) as an extra share root, removed afterwards."""
    li.add_share_path(TEST_SHARE)
    try:
        yield
    finally:
        li.remove_share_path(TEST_SHARE)
