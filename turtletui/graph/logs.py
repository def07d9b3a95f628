"""Log records as ROS 2 writes them to the console."""

from __future__ import annotations

from typing import Any, NamedTuple

DEBUG, INFO, WARN, ERROR, FATAL = 10, 20, 30, 40, 50
LEVEL_NAMES = {DEBUG: "DEBUG", INFO: "INFO", WARN: "WARN", ERROR: "ERROR", FATAL: "FATAL"}
LEVELS_BY_NAME = {name: level for level, name in LEVEL_NAMES.items()}
LEVELS_BY_NAME["WARNING"] = WARN
OUTPUT_SUFFIX = ":stdout"
"""Ends the node name of a record that holds a line a sandboxed controller printed (not logged)."""
ERROR_SUFFIX = ":stderr"
"""Ends the node name of a record that holds a line a sandboxed controller wrote
to stderr (print(..., file=sys.stderr), a warning, a thread's traceback)."""
PRINTED_SUFFIXES = (OUTPUT_SUFFIX, ERROR_SUFFIX)
"""A record whose node name ends with one of these was printed, not logged (``str.endswith``)."""


class LogRecord(NamedTuple):
    """One log line: ``stamp_ns`` is ROS time, ``t`` simulated seconds since start.

    A tuple of plain values: immutable, cheap to make, and ignored by the
    garbage collector however many a long run keeps.
    """

    stamp_ns: int
    t: float
    level: int
    node: str
    msg: str
    in_callback: bool = True
    """Whether a callback the executor ran logged it (a timer's, a subscription's...),
    not code outside spin such as a loop in main() that sleeps between lines."""
    call: int = 0
    """Which callback call logged it, 0 outside any: the lines of one call (a
    timer callback that loops and sleeps instead of returning) share it."""

    @property
    def level_name(self) -> str:
        return LEVEL_NAMES.get(self.level, str(self.level))

    def format(self) -> str:
        """``[INFO] [1700000000.123456789] [turtle_controller]: message``, as rcutils does."""
        sec, nsec = divmod(self.stamp_ns, 1_000_000_000)
        return f"[{self.level_name}] [{sec}.{nsec:09d}] [{self.node}]: {self.msg}"


def parse_level(value: str | int) -> int:
    """A level from its name (any case, WARNING allowed) or number; ValueError otherwise."""
    if isinstance(value, int):
        return value
    try:
        return LEVELS_BY_NAME[value.upper()]
    except KeyError:
        names = ", ".join(n.lower() for n in LEVEL_NAMES.values())
        raise ValueError(f"unknown log level {value!r}: use one of {names}") from None


def to_log_message(record: LogRecord, origin: tuple[str, str, int] | None = None) -> Any:
    """The record as the rcl_interfaces/msg/Log a node publishes on /rosout;
    ``origin`` is where it was logged: (file, function, line)."""
    from turtletui.interfaces.builtin_interfaces import Time
    from turtletui.interfaces.rcl_interfaces import Log

    sec, nanosec = divmod(record.stamp_ns, 1_000_000_000)
    file, function, line = origin or ("", "", 0)
    return Log(
        stamp=Time(sec=sec, nanosec=nanosec), level=max(0, min(record.level, 255)), name=record.node,
        msg=record.msg, file=file, function=function, line=line,
    )
