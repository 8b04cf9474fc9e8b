from labkit.graph import names


def topic_or_service_is_hidden(name):
    """True if any token of the name starts with '_' (rcl's hidden-name rule)."""
    return names.is_hidden(name)
