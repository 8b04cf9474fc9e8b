"""Digest `ros2 interface show` outputs produced by the real Humble verb (run by hand).

The real verb (ros2cli humble: ros2interface/verb/show.py) was run against the real
rosidl_adapter, with ros2interface's CLI imports stubbed and get_interface_path
pointed at labkit's share roots; its outputs were saved as {"pkg/kind/Name|mode": text}
(mode: default, all, none). This turns that file into the small digest fixture:

    python make_show_reference.py SHOW_OUTPUTS.json OUT.json
"""
import hashlib
import json
import sys


def digest(text):
    return hashlib.sha256(text.encode()).hexdigest()[:16]


if __name__ == '__main__':
    with open(sys.argv[1]) as f:
        outputs = json.load(f)
    with open(sys.argv[2], 'w') as f:
        json.dump({k: digest(v) for k, v in outputs.items()}, f, indent=0, sort_keys=True)
