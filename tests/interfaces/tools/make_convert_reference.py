"""Digest YAML/CSV texts made by the real rosidl_runtime_py (humble convert.py), run by hand.

Humble's rosidl_runtime_py/convert.py was run with real rclpy messages (the samples of
rclpy_reference.json, deserialized by rclpy) and these options; its outputs were saved as
{"index|type|what": text}. This turns them into the digest fixture:

    python make_convert_reference.py OUTPUTS.json OUT.json
"""
import hashlib
import json
import sys

# what -> (function, keyword arguments)
CASES = {
    'yaml-default': ('message_to_yaml', {}),
    'yaml-trunc2': ('message_to_yaml', {'truncate_length': 2}),
    'yaml-noarr': ('message_to_yaml', {'no_arr': True}),
    'yaml-nostr': ('message_to_yaml', {'no_str': True}),
    'yaml-flow': ('message_to_yaml', {'flow_style': True}),
    'csv': ('message_to_csv', {}),
    'csv-trunc2-noarr': ('message_to_csv', {'truncate_length': 2, 'no_arr': True}),
    'csv-nostr': ('message_to_csv', {'no_str': True}),
}


def digest(text):
    return hashlib.sha256(text.encode()).hexdigest()[:16]


if __name__ == '__main__':
    with open(sys.argv[1]) as f:
        outputs = json.load(f)
    with open(sys.argv[2], 'w') as f:
        json.dump({k: digest(v) for k, v in outputs.items()}, f, indent=0, sort_keys=True)
