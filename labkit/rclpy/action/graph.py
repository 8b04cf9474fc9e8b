"""rclpy.action.graph: action discovery, derived from the hidden feedback topics.

rcl_action finds actions by their `<action>/_action/feedback` topic (type
`pkg/action/X_FeedbackMessage`): servers publish it, clients subscribe to it.
"""
from typing import List, Tuple

__all__ = ['get_action_client_names_and_types_by_node', 'get_action_names_and_types',
           'get_action_server_names_and_types_by_node']

_NAME_SUFFIX = '/_action/feedback'
_TYPE_SUFFIX = '_FeedbackMessage'


def _actions_from_topics(topic_names_and_types) -> List[Tuple[str, List[str]]]:
    actions = []
    for name, types in topic_names_and_types:
        if not name.endswith(_NAME_SUFFIX):
            continue
        action_types = [t[:-len(_TYPE_SUFFIX)] if t.endswith(_TYPE_SUFFIX) else t
                        for t in types]
        actions.append((name[:-len(_NAME_SUFFIX)], action_types))
    return actions


def get_action_client_names_and_types_by_node(
        node, remote_node_name: str, remote_node_namespace: str) -> List[Tuple[str, List[str]]]:
    """Action names and types of the action clients of one node."""
    return _actions_from_topics(node.get_subscriber_names_and_types_by_node(
        remote_node_name, remote_node_namespace))


def get_action_server_names_and_types_by_node(
        node, remote_node_name: str, remote_node_namespace: str) -> List[Tuple[str, List[str]]]:
    """Action names and types of the action servers of one node."""
    return _actions_from_topics(node.get_publisher_names_and_types_by_node(
        remote_node_name, remote_node_namespace))


def get_action_names_and_types(node) -> List[Tuple[str, List[str]]]:
    """Every action name in the graph with its types."""
    return _actions_from_topics(node.get_topic_names_and_types())
