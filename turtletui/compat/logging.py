"""``rclpy.logging``: loggers with ROS's severities and logging filters.

Levels are kept by logger name (a child inherits its parent's), as rcutils does; the
filters (``throttle_duration_sec``, ``skip_first``, ``once``) keep their state per call
site and are checked like rclpy's RcutilsLogger: the same call site may not change its
severity, logger name, filters or filter parameters between calls.
"""

from __future__ import annotations

import sys
import warnings
from collections.abc import Callable
from enum import IntEnum
from typing import Any

from turtletui.compat import context as _context
from turtletui.compat.dispatch import current_call, in_callback
from turtletui.compat.identity import as_rclpy
from turtletui.graph import core
from turtletui.graph.logs import parse_level

__all__ = [
    "LoggingSeverity",
    "RcutilsLogger",
    "get_logger",
    "get_logger_effective_level",
    "get_logger_level",
    "get_logging_severity_from_string",
    "set_logger_level",
]

_NS = 1_000_000_000


class LoggingSeverity(IntEnum):
    UNSET = 0
    DEBUG = 10
    INFO = 20
    WARN = 30
    ERROR = 40
    FATAL = 50


FILTERS: dict[str, dict[str, bool]] = {
    "throttle": {"throttle_duration_sec": True, "throttle_time_source_type": False},
    "skip_first": {"skip_first": True},
    "once": {"once": True},
}
"""rclpy's logging filters, in the order it applies them: parameter -> required."""

LOG_KEYWORDS = tuple(param for params in FILTERS.values() for param in params)
"""Keyword arguments ``logger.log()`` accepts besides ``name``."""

SEVERITY_METHOD_KEYWORDS = ("name", *LOG_KEYWORDS)
"""Keyword arguments ``logger.info()`` (debug, warning, ...) accept."""

_LEVELS: dict[str, int] = {}
"""Levels set by name (``set_logger_level``, ``logger.set_level``), by logger name."""

_DEFAULT_LEVEL = LoggingSeverity.INFO


def _effective_level(name: str) -> LoggingSeverity:
    while name:
        level = _LEVELS.get(name)
        if level:
            return LoggingSeverity(level)
        name = name.rpartition(".")[0]
    return LoggingSeverity(_LEVELS.get("") or _DEFAULT_LEVEL)


def _severity_method(name: str, severity: LoggingSeverity, doc: str | None = None) -> Callable[..., bool]:
    """``logger.info`` (debug, warning...) at ``severity``. A call with no
    filters, the common case on the per-tick hot path of many controllers,
    has only the level to check (no call-site state to keep) and is handled
    here in one call; filters go through RcutilsLogger.log."""
    level = int(severity)

    def method(self: RcutilsLogger, message: str, **kwargs: Any) -> bool:
        if kwargs:
            return self.log(message, severity, **kwargs)
        if level < (_effective_level(self.name) if _LEVELS else _DEFAULT_LEVEL):
            return False
        text = message if message.__class__ is str else _text(message)
        host = _context._current_host or _context.current_host()
        host.graph.log(self.name, level, text, _call_site, in_callback=in_callback(), call=current_call(host))
        return True

    method.__name__ = name
    method.__qualname__ = f"RcutilsLogger.{name}"
    method.__doc__ = doc
    return method


class RcutilsLogger:
    """A named logger; records go to the graph of the host running the code."""

    def __init__(self, name: str = "") -> None:
        self.name = name
        self.contexts: dict[tuple, dict[str, Any]] = {}

    def get_child(self, name: str) -> RcutilsLogger:
        if not name:
            raise ValueError("Child logger name must not be empty.")
        return RcutilsLogger(f"{self.name}.{name}" if self.name else name)

    def set_level(self, level: int | LoggingSeverity) -> None:
        set_logger_level(self.name, level)

    def get_effective_level(self) -> LoggingSeverity:
        return _effective_level(self.name)

    def is_enabled_for(self, severity: int | LoggingSeverity) -> bool:
        severity = LoggingSeverity(severity)
        if not _LEVELS:
            return severity >= _DEFAULT_LEVEL
        return severity >= _effective_level(self.name)

    def log(
        self, message: str, severity: int | LoggingSeverity, name: str | None = None, **kwargs: Any
    ) -> bool:
        """Log ``message`` at ``severity``; False if the level or a filter dropped it."""
        if not self.is_enabled_for(severity):
            return False
        severity = LoggingSeverity(severity)
        if name is None:
            name = self.name
        filters = _filters_from_kwargs(kwargs)
        caller = _caller()
        context = self.contexts.get(caller)
        if context is None:
            context = self.contexts[caller] = _new_context(name, severity, filters, kwargs)
        else:
            _check_unchanged(context, name, severity, filters, kwargs)
        for kind in filters:
            if not _SHOULD_LOG[kind](context):
                return False
        host = _context._current_host or _context.current_host()
        graph = host.graph
        graph.log(
            name,
            int(severity),
            _text(message),
            _origin(caller) if graph.hears_rosout() else None,
            in_callback=in_callback(),
            call=current_call(host),
        )
        return True

    debug = _severity_method("debug", LoggingSeverity.DEBUG)
    info = _severity_method("info", LoggingSeverity.INFO)
    warning = _severity_method("warning", LoggingSeverity.WARN)
    def warn(self, message: str, **kwargs: Any) -> bool:
        """Deprecated in rclpy in favour of ``warning``; still works, with rclpy's DeprecationWarning."""
        warnings.warn(_WARN_DEPRECATED, DeprecationWarning, stacklevel=2)
        return self.warning(message, **kwargs)

    error = _severity_method("error", LoggingSeverity.ERROR)
    fatal = _severity_method("fatal", LoggingSeverity.FATAL)


_WARN_DEPRECATED = "Deprecated in favor of :py:classmethod:RcutilsLogger.warning:."
"""What typing_extensions.deprecated says for rclpy's ``warn`` (shown once per call site)."""


def _text(message: Any) -> str:
    """What rclpy's C logging call makes of ``message``: a str, None ('(null)') or bytes."""
    if isinstance(message, str):
        return message
    if message is None:
        return "(null)"
    if isinstance(message, bytes):
        return message.decode("utf-8", errors="replace")
    raise TypeError(
        f"log message must be a str, got {type(message).__name__} {message!r}: "
        "ROS 2 loggers take one string, e.g. f'x = {x}'"
    )


def _caller() -> tuple:
    """The call site outside this module (file, line, instruction, function), as rclpy's CallerId."""
    frame = sys._getframe(1)
    while frame.f_code.co_filename == __file__ and frame.f_back is not None:
        frame = frame.f_back
    code = frame.f_code
    return (code.co_name, code.co_filename, frame.f_lineno, frame.f_lasti)


def _call_site() -> tuple[str, str, int]:
    """The call site of the logging call Graph.log is handling, as /rosout's
    Log has it (file, function, line): the graph asks only when a /rosout
    subscription will see the line, which saves a look-up on every other."""
    frame = sys._getframe(1)
    while frame.f_code.co_filename in _LOGGING_FILES and frame.f_back is not None:
        frame = frame.f_back
    code = frame.f_code
    return (code.co_filename, code.co_name, frame.f_lineno)


_LOGGING_FILES = frozenset({__file__, core.__file__})
"""Where a logging call passes through on its way to Graph.log."""


def _origin(caller: tuple) -> tuple[str, str, int]:
    """A call site as /rosout's Log has it: (file, function, line)."""
    function, file, line, _ = caller
    return (file, function, line)


def _filters_from_kwargs(kwargs: dict[str, Any]) -> list[str]:
    detected = [kind for kind, params in FILTERS.items() if any(kwargs.get(p) for p in params)]
    for kind in detected:
        for param, required in FILTERS[kind].items():
            if required and param not in kwargs:
                raise TypeError(
                    f'required parameter "{param}" not specified but is required for the logging '
                    f'filter "{kind}"'
                )
    for key in kwargs:
        if key not in LOG_KEYWORDS:
            raise TypeError(
                f'parameter "{key}" is not one of the recognized logging options "{list(LOG_KEYWORDS)}"'
            )
    return detected


def _filter_params(filters: list[str], kwargs: dict[str, Any]) -> dict[str, Any]:
    return {param: kwargs.get(param) for kind in filters for param in FILTERS[kind]}


def _new_context(name: str, severity: LoggingSeverity, filters: list[str], kwargs: dict[str, Any]) -> dict:
    context: dict[str, Any] = {"name": name, "severity": severity, "filters": filters}
    context["params"] = _filter_params(filters, kwargs)
    if "throttle" in filters:
        clock = kwargs.get("throttle_time_source_type")
        if clock is not None:
            from turtletui.compat.time import Clock

            if not isinstance(clock, Clock):
                raise ValueError(f'Received throttle_time_source_type of "{clock}" is not a clock instance')
        context["throttle_last_logged"] = 0
    context["has_been_logged_once"] = False
    context["first_has_been_skipped"] = False
    return context


def _check_unchanged(
    context: dict, name: str, severity: LoggingSeverity, filters: list[str], kwargs: dict[str, Any]
) -> None:
    if severity != context["severity"]:
        raise ValueError("Logger severity cannot be changed between calls.")
    if name != context["name"]:
        raise ValueError("Logger name cannot be changed between calls.")
    if filters != context["filters"]:
        raise ValueError("Requested logging filters cannot be changed between calls.")
    if _filter_params(filters, kwargs) != context["params"]:
        raise ValueError("Logging filter parameters cannot be changed between calls.")


def _throttle(context: dict) -> bool:
    clock = context["params"].get("throttle_time_source_type")
    now = clock.now().nanoseconds if clock is not None else (_context._current_host or _context.current_host()).graph.stamp_ns
    if now >= context["throttle_last_logged"] + context["params"]["throttle_duration_sec"] * _NS:
        context["throttle_last_logged"] = now
        return True
    return False


def _skip_first(context: dict) -> bool:
    if not context["first_has_been_skipped"]:
        context["first_has_been_skipped"] = True
        return False
    return True


def _once(context: dict) -> bool:
    if not context["has_been_logged_once"]:
        context["has_been_logged_once"] = True
        return True
    return False


_SHOULD_LOG = {"throttle": _throttle, "skip_first": _skip_first, "once": _once}

def get_logger(name: str) -> RcutilsLogger:
    """A logger called ``name`` (``rclpy.logging.get_logger``); a new object each call, as in
    rclpy (levels belong to the name, filter state to the object)."""
    if not name:
        raise ValueError("Logger name must not be empty.")
    return RcutilsLogger(name)


def set_logger_level(name: str, level: int | LoggingSeverity, detailed_error: bool = False) -> None:
    level = LoggingSeverity(level)
    if level is LoggingSeverity.UNSET:
        _LEVELS.pop(name, None)
    else:
        _LEVELS[name] = int(level)


def get_logger_effective_level(name: str) -> LoggingSeverity:
    return _effective_level(name)


def get_logger_level(name: str) -> LoggingSeverity:
    return LoggingSeverity(_LEVELS.get(name, LoggingSeverity.UNSET))


def get_logging_severity_from_string(log_severity: str) -> LoggingSeverity:
    return LoggingSeverity(parse_level(log_severity))


def apply_log_level(spec: str | None, by_logger: dict[str, str] | None = None) -> None:
    """Apply ``--log-level LEVEL`` (every logger's default) and ``--log-level NAME:=LEVEL``."""
    global _DEFAULT_LEVEL
    if spec:
        _DEFAULT_LEVEL = LoggingSeverity(parse_level(spec))
    for name, level in (by_logger or {}).items():
        set_logger_level(name, parse_level(level))


def reset_levels() -> None:
    global _DEFAULT_LEVEL
    _LEVELS.clear()
    _DEFAULT_LEVEL = LoggingSeverity.INFO

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.impl.logging_severity", LoggingSeverity)
as_rclpy("rclpy.impl.rcutils_logger", RcutilsLogger)
