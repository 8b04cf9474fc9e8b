"""The workspace fixtures of tests/workspace, for launch tests."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                'workspace'))

from conftest_ws import clean_env, facer, ws  # noqa: E402,F401
