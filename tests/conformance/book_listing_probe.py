"""Run one node listing of the book for a moment and report what it made (used by
tests/conformance/test_book_listings_real.py, under real rclpy and under labkit exec).

    python book_listing_probe.py LISTING.py SECONDS

`rclpy.spin` (and an executor's spin) runs for SECONDS, then the probe prints one line
`PROBE {json}` (each node's name, publishers, subscriptions, services, parameters) and
ends the spin as Ctrl+C would (KeyboardInterrupt), so the listing's own clean-up runs."""
import importlib.util
import json
import sys
import time

import rclpy
from rclpy.node import Node

LISTING, SECONDS = sys.argv[1], float(sys.argv[2])
sys.argv = [LISTING]
_nodes = []
_node_init = Node.__init__


def _init(self, *args, **kwargs):
    _node_init(self, *args, **kwargs)
    _nodes.append(self)


Node.__init__ = _init


def _report():
    out = []
    for node in _nodes:
        name, ns = node.get_name(), node.get_namespace()
        out.append({
            'node': node.get_fully_qualified_name(),
            'publishers': sorted(n for n, _ in
                                 node.get_publisher_names_and_types_by_node(name, ns)),
            'subscriptions': sorted(n for n, _ in
                                    node.get_subscriber_names_and_types_by_node(name, ns)),
            'services': sorted(n for n, _ in node.get_service_names_and_types_by_node(name, ns)),
            'parameters': sorted(node._parameters),
        })
    return out


_reported = []


def _spin_for_a_while(spin_once):
    end = time.monotonic() + SECONDS
    while time.monotonic() < end:
        spin_once(0.02)
    if not _reported:
        _reported.append(1)
        print('PROBE ' + json.dumps(_report()), flush=True)
    raise KeyboardInterrupt


def _spin(node, executor=None):
    _spin_for_a_while(lambda t: rclpy.spin_once(node, executor=executor, timeout_sec=t))


rclpy.spin = _spin
from rclpy import executors  # noqa: E402
for _cls in (executors.SingleThreadedExecutor, executors.MultiThreadedExecutor):
    _cls.spin = lambda self: _spin_for_a_while(lambda t: self.spin_once(timeout_sec=t))

spec = importlib.util.spec_from_file_location('book_listing', LISTING)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)
try:
    module.main()
except KeyboardInterrupt:
    pass
if not _reported:
    print('PROBE ' + json.dumps(_report()), flush=True)
