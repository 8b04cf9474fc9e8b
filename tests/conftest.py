"""Shared test set-up: virtual time unless a test says otherwise, and a clean
graph after every test (nothing left running)."""
import os
import sys

os.environ.setdefault("LABKIT_TIME", "virtual")
# `labkit exec` joins DDS in live time like a ROS 2 process; tests (and the programs they
# start) stay in-process unless they ask (tests/dds sets LABKIT_DDS=on, a domain each)
os.environ.setdefault("LABKIT_DDS", "off")

import signal  # noqa: E402

import pytest  # noqa: E402

# A suite started in the background (`make test &`, some CI runners) inherits SIGINT
# ignored, and so would every program it starts: the tests that press Ctrl+C on a
# `labkit exec` program (as a terminal does) need SIGINT as an interactive shell has it.
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)


@pytest.fixture(autouse=True)
def _labkit_clean_graph():
    yield
    # Only if the test touched the runtime: importing it here would slow pure tests.
    if "labkit.process" in sys.modules:
        sys.modules["labkit.process"].reset_all()


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_call(item):
    # pytest swaps sys.stdout/stderr when a test's call phase starts, which drops
    # labkit's per-process output proxy; put it back so Process.output keeps
    # collecting what processes print during the test.
    process = sys.modules.get("labkit.process")
    if process is not None:
        process.install_output_proxy()


def _wine_module(session):
    for item in session.items:
        module = getattr(item, "module", None)      # notebook cells (nbval) have none
        if module is not None and module.__name__.endswith("test_windows_wine"):
            return module
    return None


def pytest_collection_finish(session):
    # With LABKIT_WINE_EARLY=1 the Windows job (tests/platform/test_windows_wine.py, ~6 min
    # under Wine) starts now, in the background on the second core, instead of when the
    # suite reaches it: the suite takes ~5 min less. Off by default: under the Linux
    # suite's load, `colcon test` inside Wine (ch16) was seen to fail once without a result
    # file, and CI must not be flaky.
    module = _wine_module(session)
    if module is not None and not session.config.option.collectonly \
            and os.environ.get("LABKIT_WINE_EARLY") == "1":
        module.start_windows_pytest()


def pytest_sessionfinish(session):
    module = sys.modules.get("test_windows_wine") or next(
        (m for n, m in sys.modules.items() if n.endswith("test_windows_wine")), None)
    job = getattr(module, "_JOB", None)
    if job and job["proc"].poll() is None:     # the suite stopped before it was read
        job["proc"].kill()
        job["proc"].wait()
