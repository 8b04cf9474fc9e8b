"""The class on a JupyterHub: each learner's ROS domain (`domain`), and the teacher's
command `labkit teacher ...` (`collect`: every learner's exercises as a CSV and an
HTML table, each learner's notebook re-run in its own sandboxed process)."""
