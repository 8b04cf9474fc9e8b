"""Demo executables of a Humble desktop install (demo_nodes_*, examples_rclcpp_minimal_*).

Written as ordinary rclpy code; only the imports name labkit, so they run
whether or not the import hook is active.
"""
