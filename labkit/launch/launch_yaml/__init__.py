"""launch_yaml: the YAML front-end of launch (the parser is labkit/launch/frontend.py)."""
