from test_msgs.action import Fibonacci  # noqa: F401  (see ../__init__.py)
