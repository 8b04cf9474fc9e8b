"""labkit's rclpy: the ROS 2 Humble Python client library API over labkit's in-process graph.

Module layout and public names mirror rclpy (humble); the import hook maps `rclpy` here.
"""
from labkit.rclpy.context import Context
from labkit.rclpy.signals import SignalHandlerOptions, install_signal_handlers  # noqa: F401
from labkit.rclpy.signals import uninstall_signal_handlers  # noqa: F401
from labkit.rclpy.task import Future
from labkit.rclpy.utilities import get_default_context
from labkit.rclpy.utilities import get_rmw_implementation_identifier  # noqa: F401
from labkit.rclpy.utilities import ok  # noqa: F401
from labkit.rclpy.utilities import remove_ros_args  # noqa: F401
from labkit.rclpy.utilities import shutdown as _shutdown
from labkit.rclpy.utilities import try_shutdown  # noqa: F401

try:
    from labkit.rclpy.parameter import Parameter  # noqa: F401
except ImportError:  # pragma: no cover
    pass

__all__ = ['init', 'shutdown', 'try_shutdown', 'ok', 'create_node', 'spin', 'spin_once',
           'spin_until_future_complete', 'get_global_executor', 'get_default_context',
           'Context', 'Future', 'Parameter', 'remove_ros_args']


def init(*, args=None, context=None, domain_id=None, signal_handler_options=None):
    """Initialize ROS communications for a given context (the process's default one)."""
    if context is None:
        context = get_default_context()
        _state().reset_by_labkit = False
    context.init(args, domain_id=domain_id)
    # Humble: signal handlers for SIGINT and SIGTERM unless told otherwise (rclpy.signals)
    install_signal_handlers(SignalHandlerOptions.ALL if signal_handler_options is None
                            else signal_handler_options)


from labkit import process as _process  # noqa: E402


def _state():
    return _process.current().rclpy


def get_global_executor():
    state = _state()
    if state.global_executor is None:
        from labkit.rclpy.executors import SingleThreadedExecutor
        executor = state.global_executor = SingleThreadedExecutor()
        context = get_default_context()

        def reset_executor():
            executor.shutdown()
            if state.global_executor is executor:
                state.global_executor = None
        context.on_shutdown(reset_executor)
    return state.global_executor


def shutdown(*, context=None, uninstall_handlers=None):
    """Shutdown a previously initialized context (and the global executor)."""
    _shutdown(context=context)
    if uninstall_handlers or (uninstall_handlers is None and context is None):
        uninstall_signal_handlers()


def create_node(node_name, *, context=None, cli_args=None, namespace=None,
                use_global_arguments=True, enable_rosout=True, start_parameter_services=True,
                parameter_overrides=None, allow_undeclared_parameters=False,
                automatically_declare_parameters_from_overrides=False):
    from labkit.rclpy.node import Node
    return Node(node_name, context=context, cli_args=cli_args, namespace=namespace,
                use_global_arguments=use_global_arguments, enable_rosout=enable_rosout,
                start_parameter_services=start_parameter_services,
                parameter_overrides=parameter_overrides,
                allow_undeclared_parameters=allow_undeclared_parameters,
                automatically_declare_parameters_from_overrides=(
                    automatically_declare_parameters_from_overrides))


def spin_once(node, *, executor=None, timeout_sec=None):
    """Execute one item of work or wait until a timeout expires."""
    if executor is None:
        executor = _process.current().rclpy.global_executor or get_global_executor()
    transient = getattr(executor, '_transient', _NOT_OURS)
    if transient is _NOT_OURS:             # a foreign executor: exactly rclpy's steps
        try:
            executor.add_node(node)
            executor.spin_once(timeout_sec=timeout_sec)
        finally:
            executor.remove_node(node)
        return
    if transient is node:
        executor._transient = None          # still attached from the previous call
    else:
        executor.add_node(node)
    try:
        executor.spin_once(timeout_sec=timeout_sec)
    finally:
        # removed lazily (see Executor._transient): same to observe, much cheaper
        executor._transient = node if node in executor._nodes else None


_NOT_OURS = object()


def spin(node, executor=None):
    """Execute work and block until the context associated with the executor is shutdown."""
    executor = get_global_executor() if executor is None else executor
    try:
        executor.add_node(node)
        while executor.context.ok():
            executor.spin_once()
    finally:
        executor.remove_node(node)


def spin_until_future_complete(node, future, executor=None, timeout_sec=None):
    """Execute work until the future is complete (or the timeout passes)."""
    executor = get_global_executor() if executor is None else executor
    node_added = False
    try:
        node_added = executor.add_node(node)
        executor.spin_until_future_complete(future, timeout_sec)
    finally:
        if node_added:
            executor.remove_node(node)
