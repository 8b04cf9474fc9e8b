"""Destroying a node removes exactly its own endpoints (the graph indexes them per node)
and the matches of the topics it used are right afterwards."""
from labkit.graph.registry import GRAPH
from labkit.rclpy.node import Node


def test_destroying_nodes_keeps_the_others_matched(rclpy, msgs):
    talker, other_talker, listener = Node('talker'), Node('other_talker'), Node('listener')
    pub = talker.create_publisher(msgs.String, 'chatter', 10)
    other = other_talker.create_publisher(msgs.String, 'chatter', 10)
    got = []
    listener.create_subscription(msgs.String, 'chatter', got.append, 10)
    assert pub.get_subscription_count() == other.get_subscription_count() == 1
    talker.destroy_node()
    assert other.get_subscription_count() == 1
    assert [ep.node.name for ep in GRAPH.endpoints_of('publisher', '/chatter', 0)] == \
        ['other_talker']
    other.publish(msgs.String(data='hi'))
    rclpy.spin_once(listener, timeout_sec=0)
    assert [m.data for m in got] == ['hi']
    listener.destroy_node()
    assert other.get_subscription_count() == 0
    names = {ep.node.name for kind in GRAPH.endpoints for eps in GRAPH.endpoints[kind].values()
             for ep in eps}
    assert names == {'other_talker'}
    other_talker.destroy_node()
    assert not GRAPH._by_node
