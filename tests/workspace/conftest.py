"""Fixtures: a throw-away workspace folder; what `source` changes is put back afterwards."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from conftest_ws import clean_env, facer, ws  # noqa: E402,F401
