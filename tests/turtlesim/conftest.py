"""pytest swaps sys.stdout/sys.stderr when a test's call phase starts, which drops
labkit's per-process output proxy installed while fixtures started processes.
Put it back so `Process.output` keeps collecting log lines during the test."""
import sys

import pytest


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_call(item):
    process = sys.modules.get("labkit.process")
    if process is not None:
        process.install_output_proxy()
