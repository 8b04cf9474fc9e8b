"""Named loggers with rcutils' filters (once, throttle, skip_first) and console format."""
import os
import sys

from labkit.graph import world
from labkit.rclpy.impl.logging_severity import LoggingSeverity

_HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _config():
    from labkit import process
    state = process.current().rclpy
    if state.logging is None:
        state.logging = _Config()
    return state.logging


class _Config:
    """Per-process logging state (rcutils' globals in a real process)."""

    def __init__(self):
        self.default_level = LoggingSeverity.INFO
        self.levels = {}             # logger name -> severity
        self.rosout = {}             # logger name -> [callable(severity, name, msg, func, file, line, ns)]
        self.stdout_logs = True
        self.rosout_logs = True

    def effective_level(self, name):
        levels = self.levels
        while True:
            level = levels.get(name)
            if level is not None and level != LoggingSeverity.UNSET:
                return level
            if not name:
                return self.default_level
            name = name.rpartition('.')[0]


def _format(severity, name, message, func, file, line, stamp_ns):
    fmt = os.environ.get('RCUTILS_CONSOLE_OUTPUT_FORMAT')
    sec, nsec = divmod(stamp_ns, 1_000_000_000)
    sev = LoggingSeverity(severity).name
    if not fmt:
        return f'[{sev}] [{sec}.{nsec:09d}] [{name}]: {message}'
    values = {'severity': sev, 'name': name, 'message': message, 'function_name': func,
              'file_name': file, 'line_number': str(line), 'time': f'{sec}.{nsec:09d}',
              'time_as_nanoseconds': str(stamp_ns)}
    out = fmt
    for key, value in values.items():
        out = out.replace('{' + key + '}', value)
    return out


def emit(severity, name, message, func='', file='', line=0):
    """What rcutils' output handlers do: console (stderr) and /rosout."""
    cfg = _config()
    stamp = world.system_ns()
    if cfg.stdout_logs:
        stream = sys.stdout if os.environ.get('RCUTILS_LOGGING_USE_STDOUT') == '1' else sys.stderr
        stream.write(_format(severity, name, str(message), func, file, line, stamp) + '\n')
        try:
            stream.flush()
        except Exception:
            pass
    if cfg.rosout_logs:
        for sink in list(cfg.rosout.get(name, ())):
            sink(int(severity), name, str(message), func, file, line, stamp)


class CallerId:
    __slots__ = ('function_name', 'file_path', 'line_number', 'last_index')

    def __init__(self, frame=None):
        if frame is None:
            frame = sys._getframe(1)
            while frame is not None and os.path.dirname(
                    os.path.abspath(frame.f_code.co_filename)) in (_HERE, os.path.join(_HERE, 'impl')):
                frame = frame.f_back
        code = frame.f_code if frame is not None else None
        self.function_name = code.co_name if code else '<unknown>'
        self.file_path = code.co_filename if code else '<unknown>'
        self.line_number = frame.f_lineno if frame is not None else 0
        self.last_index = frame.f_lasti if frame is not None else 0

    def _key(self):
        return (self.function_name, self.file_path, self.line_number, self.last_index)

    def __eq__(self, other):
        return isinstance(other, CallerId) and self._key() == other._key()

    def __hash__(self):
        return hash(self._key())


_FILTER_PARAMS = {
    'throttle': {'throttle_duration_sec': None, 'throttle_time_source_type': 'RCUTILS_STEADY_TIME'},
    'skip_first': {'skip_first': False},
    'once': {'once': False},
}


def _filters_from_kwargs(**kwargs):
    detected = []
    known = {p for params in _FILTER_PARAMS.values() for p in params}
    for key in kwargs:
        if key not in known:
            raise TypeError(f"parameter '{key}' is not one of the recognized logging options "
                            f"'{sorted(known)}'")
    if kwargs.get('throttle_duration_sec') is not None:
        detected.append('throttle')
    elif 'throttle_time_source_type' in kwargs:
        raise TypeError("required parameter 'throttle_duration_sec' was not specified, but "
                        "is required for logging filter 'throttle'")
    if kwargs.get('skip_first'):
        detected.append('skip_first')
    if kwargs.get('once'):
        detected.append('once')
    return detected


def _should_log(flt, ctx):
    if flt == 'once':
        if ctx.get('has_logged'):
            return False
        ctx['has_logged'] = True
        return True
    if flt == 'skip_first':
        if ctx.get('first_skipped'):
            return True
        ctx['first_skipped'] = True
        return False
    if flt == 'throttle':
        now = world.steady_ns()
        last = ctx.get('throttle_last_logged')
        period = int(ctx['throttle_duration_sec'] * 1e9)
        if last is None or now >= last + period:
            ctx['throttle_last_logged'] = now
            return True
        return False
    return True


class RcutilsLogger:
    def __init__(self, name=''):
        self.name = name
        self.contexts = {}

    def get_child(self, name):
        if not name:
            raise ValueError('Child logger name must not be empty.')
        if self.name:
            name = self.name + '.' + name
        return RcutilsLogger(name=name)

    def set_level(self, level):
        level = LoggingSeverity(level)
        _config().levels[self.name] = level

    def get_effective_level(self):
        return LoggingSeverity(_config().effective_level(self.name))

    def is_enabled_for(self, severity):
        severity = LoggingSeverity(severity)
        return severity >= _config().effective_level(self.name)

    def log(self, message, severity, **kwargs):
        if not self.is_enabled_for(severity):
            return False
        severity = LoggingSeverity(severity)
        name = kwargs.pop('name', self.name)
        filters = _filters_from_kwargs(**kwargs)
        caller = CallerId()
        ctx = self.contexts.get(caller)
        if ctx is None:
            ctx = {'name': name, 'severity': severity, 'filters': filters}
            for flt in filters:
                for p, default in _FILTER_PARAMS[flt].items():
                    ctx[p] = kwargs.get(p, default)
            self.contexts[caller] = ctx
        else:
            if severity != ctx['severity']:
                raise ValueError('Logger severity cannot be changed between calls.')
            if name != ctx['name']:
                raise ValueError('Logger name cannot be changed between calls.')
            if filters != ctx['filters']:
                raise ValueError('Requested logging filters cannot be changed between calls.')
            for flt in filters:
                for p, default in _FILTER_PARAMS[flt].items():
                    if ctx[p] != kwargs.get(p, default):
                        raise ValueError(
                            'Logging filter parameters cannot be changed between calls.')
        for flt in ctx['filters']:
            if not _should_log(flt, ctx):
                return False
        emit(severity, name, message, caller.function_name, caller.file_path, caller.line_number)
        return True

    def debug(self, message, **kwargs):
        return self.log(message, LoggingSeverity.DEBUG, **kwargs)

    def info(self, message, **kwargs):
        return self.log(message, LoggingSeverity.INFO, **kwargs)

    def warning(self, message, **kwargs):
        return self.log(message, LoggingSeverity.WARN, **kwargs)

    def warn(self, message, **kwargs):
        return self.warning(message, **kwargs)

    def error(self, message, **kwargs):
        return self.log(message, LoggingSeverity.ERROR, **kwargs)

    def fatal(self, message, **kwargs):
        return self.log(message, LoggingSeverity.FATAL, **kwargs)


from labkit.rclpy._public import present as _present  # noqa: E402
_present(globals())
