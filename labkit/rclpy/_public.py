"""Reprs and tracebacks name rclpy's modules (`rclpy.exceptions.X`, `rclpy.qos.QoSProfile`),
not labkit's files, as generated message classes already do for theirs."""

PREFIX = 'labkit.rclpy'


def present(namespace):
    """Give every class defined in this module rclpy's module name (call it at the end)."""
    here = namespace['__name__']
    public = 'rclpy' + here[len(PREFIX):]
    todo = list(namespace.values())
    while todo:
        value = todo.pop()
        if isinstance(value, type) and value.__module__ == here:
            value.__module__ = public
            todo.extend(vars(value).values())      # nested classes (Parameter.Type)
