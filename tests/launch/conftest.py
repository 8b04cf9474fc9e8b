"""Fixtures for launch tests: tests/workspace's workspaces."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), 'workspace'))

from conftest_ws import clean_env, facer, ws  # noqa: E402,F401
