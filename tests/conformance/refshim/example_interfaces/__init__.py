"""Reference-only shim (never used under labkit).

ROS 2 Jazzy has no example_interfaces wheel on PyPI. test_msgs/action/Fibonacci has
exactly example_interfaces/action/Fibonacci's definition (int32 order / int32[] sequence /
int32[] sequence), so the reference run uses it under this name. Scripts therefore print
field values, never reprs or type names of these classes.
"""
