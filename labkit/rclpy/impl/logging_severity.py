from enum import IntEnum


class LoggingSeverity(IntEnum):
    """The severity levels of rcutils logging."""

    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
