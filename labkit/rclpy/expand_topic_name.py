from labkit.graph import names


def expand_topic_name(topic_name, node_name, node_namespace):
    """Expand a topic name with the node's name and namespace (raises ValueError if invalid)."""
    if names.validate_node_name(node_name) is not None:
        raise ValueError('node name is invalid')
    if names.validate_namespace(node_namespace) is not None:
        raise ValueError('node namespace is invalid')
    if names.validate_topic_name(topic_name) is not None:
        raise ValueError('topic name is invalid')
    return names.expand_topic_name(topic_name, node_name, node_namespace)
