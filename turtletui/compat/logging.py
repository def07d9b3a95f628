"""``rclpy.logging``: node loggers with ROS's severities, throttling and ``once``."""

from __future__ import annotations

import sys
from enum import IntEnum
from typing import Any

from turtletui.graph.logs import parse_level

_NS = 1_000_000_000


class LoggingSeverity(IntEnum):
    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


_LEVELS: dict[str, int] = {}
"""Levels set by name (``set_logger_level``, ``--log-level``), by logger name."""

_DEFAULT_LEVEL = LoggingSeverity.INFO


class RcutilsLogger:
    """A named logger; records go to the graph of the host running the code."""

    def __init__(self, name: str = "") -> None:
        self.name = name
        self._level: int | None = None
        self._call_state: dict[tuple[str, int], list[Any]] = {}

    def get_child(self, name: str) -> RcutilsLogger:
        if not name:
            raise ValueError("Child logger name must not be empty.")
        return RcutilsLogger(f"{self.name}.{name}" if self.name else name)

    def set_level(self, level: int | LoggingSeverity) -> bool:
        self._level = int(level)
        return True

    def get_effective_level(self) -> LoggingSeverity:
        if self._level:
            return LoggingSeverity(self._level)
        name = self.name
        while name:
            if name in _LEVELS:
                return LoggingSeverity(_LEVELS[name])
            name = name.rpartition(".")[0]
        return LoggingSeverity(_LEVELS.get("", _DEFAULT_LEVEL))

    def is_enabled_for(self, severity: int | LoggingSeverity) -> bool:
        return int(severity) >= self.get_effective_level()

    def log(self, message: str, severity: int | LoggingSeverity, **kwargs: Any) -> bool:
        """Log ``message`` at ``severity``; returns whether it was logged."""
        return self._log(message, int(severity), kwargs)

    def debug(self, message: str, **kwargs: Any) -> bool:
        return self._log(message, 10, kwargs)

    def info(self, message: str, **kwargs: Any) -> bool:
        return self._log(message, 20, kwargs)

    def warning(self, message: str, **kwargs: Any) -> bool:
        return self._log(message, 30, kwargs)

    warn = warning

    def error(self, message: str, **kwargs: Any) -> bool:
        return self._log(message, 40, kwargs)

    def fatal(self, message: str, **kwargs: Any) -> bool:
        return self._log(message, 50, kwargs)

    def _log(self, message: str, severity: int, kwargs: dict[str, Any]) -> bool:
        if not isinstance(message, str):
            raise TypeError(
                f"log message must be a str, got {type(message).__name__} {message!r}: "
                "ROS 2 loggers take one string, e.g. f'x = {x}'"
            )
        if self._level is None and not _LEVELS:
            if severity < _DEFAULT_LEVEL:
                return False
        elif severity < self.get_effective_level():
            return False
        graph = (_current_host or _bind_current_host())().graph
        if kwargs:
            unknown = set(kwargs) - {
                "throttle_duration_sec",
                "throttle_time_source_type",
                "skip_first",
                "once",
            }
            if unknown:
                raise TypeError(f"unsupported logging keyword argument(s): {', '.join(sorted(unknown))}")
            frame = sys._getframe(2)
            key = (frame.f_code.co_filename, frame.f_lineno)
            state = self._call_state.setdefault(key, [0, None])
            state[0] += 1
            if kwargs.get("once") and state[0] > 1:
                return False
            if kwargs.get("skip_first") and state[0] == 1:
                return False
            period = kwargs.get("throttle_duration_sec")
            if period:
                now = graph.now_ns
                if state[1] is not None and now - state[1] < period * _NS:
                    return False
                state[1] = now
        graph.log(self.name, severity, message)
        return True


_current_host = None


def _bind_current_host():
    # Imported on first use: turtletui.compat.context may import this module.
    global _current_host
    from turtletui.compat.context import current_host

    _current_host = current_host
    return current_host


_loggers: dict[str, RcutilsLogger] = {}


def get_logger(name: str) -> RcutilsLogger:
    """The logger called ``name`` (``rclpy.logging.get_logger``)."""
    logger = _loggers.get(name)
    if logger is None:
        logger = _loggers[name] = RcutilsLogger(name)
    return logger


def set_logger_level(name: str, level: int | LoggingSeverity, detailed_error: bool = False) -> None:
    _LEVELS[name] = int(level)


def get_logger_effective_level(name: str) -> LoggingSeverity:
    return get_logger(name).get_effective_level()


def apply_log_level(spec: str | None) -> None:
    """Apply ``--log-level LEVEL`` or ``--log-level name:=LEVEL``."""
    global _DEFAULT_LEVEL
    if not spec:
        return
    _DEFAULT_LEVEL = LoggingSeverity(parse_level(spec))


def reset_levels() -> None:
    global _DEFAULT_LEVEL
    _LEVELS.clear()
    _loggers.clear()
    _DEFAULT_LEVEL = LoggingSeverity.INFO
