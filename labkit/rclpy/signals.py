"""No OS signal handling inside labkit: stopping a process plays the part of SIGINT."""
from enum import IntEnum


class SignalHandlerOptions(IntEnum):
    NO = 0
    SIGINT = 1
    SIGTERM = 2
    ALL = 3


def install_signal_handlers(options=SignalHandlerOptions.ALL):
    pass


def get_current_signal_handlers_options():
    return SignalHandlerOptions.NO


def uninstall_signal_handlers():
    pass


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
