"""Reprs and tracebacks name rclpy's modules (`rclpy.exceptions.X`, `rclpy.qos.QoSProfile`),
not labkit's files, as generated message classes already do for theirs."""

PREFIX = 'labkit.rclpy'


def present(namespace):
    """Give every class defined in this module rclpy's module name (call it at the end)."""
    here = namespace['__name__']
    public = 'rclpy' + here[len(PREFIX):]
    for value in list(namespace.values()):
        if isinstance(value, type) and value.__module__ == here:
            value.__module__ = public
