"""rclpy.logging: named loggers, levels (per labkit process, like rcutils per real process)."""
from pathlib import Path

from labkit.rclpy.impl.logging_severity import LoggingSeverity
from labkit.rclpy.impl import rcutils_logger
from labkit.rclpy.impl.rcutils_logger import RcutilsLogger

__all__ = ['LoggingSeverity', 'get_logger', 'set_logger_level', 'get_logger_effective_level',
           'get_logging_severity_from_string', 'initialize', 'shutdown', 'clear_config',
           'get_logging_directory']

_root_logger = RcutilsLogger()


def get_logger(name):
    if not name:
        raise ValueError('Logger name must not be empty.')
    return _root_logger.get_child(name)


def initialize():
    pass


def shutdown():
    pass


def clear_config():
    cfg = rcutils_logger._config()
    cfg.levels.clear()
    cfg.default_level = LoggingSeverity.INFO


def set_logger_level(name, level):
    level = LoggingSeverity(level)
    cfg = rcutils_logger._config()
    if name == '':
        cfg.default_level = level
    cfg.levels[name] = level


def get_logger_effective_level(name):
    return LoggingSeverity(rcutils_logger._config().effective_level(name))


def get_logging_severity_from_string(log_severity):
    upper = log_severity.upper()
    if upper == 'WARNING':
        upper = 'WARN'
    try:
        return LoggingSeverity[upper]
    except KeyError:
        raise RuntimeError(f'Failed to convert string to log severity: {log_severity}') from None


def get_logging_directory():
    return Path.home() / '.ros' / 'log'
