"""nbval runs every notebook here in virtual time (deterministic outputs) and in
UTC, each kernel starting from the environment this session began with.

(The kernels nbval starts inherit this process's environment; `make test` sets
the first two too.)"""
import os

import pytest

os.environ.setdefault("LABKIT_TIME", "virtual")
os.environ.setdefault("TZ", "UTC")      # dates printed by tools do not depend on the machine

# Taken when this file is collected, before any test ran: a unit test that sourced
# a workspace (AMENT_PREFIX_PATH, ...) must not leak into the notebooks' kernels.
_CLEAN_ENV = dict(os.environ)


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_setup(item):
    if os.environ != _CLEAN_ENV:
        os.environ.clear()
        os.environ.update(_CLEAN_ENV)
