"""launch_xml: the XML front-end of launch (the parser is labkit/launch/frontend.py)."""
