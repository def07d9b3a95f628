"""``rclpy.time``, ``rclpy.duration`` and ``rclpy.clock``: simulated ROS time.

Arithmetic, comparisons, bounds and error types follow rclpy's (Duration and Time
are unhashable there too, since they define ``__eq__`` without ``__hash__``)."""

from __future__ import annotations

import math
from enum import IntEnum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from turtletui.compat.context import Context

_NS = 1_000_000_000
_INT64 = 2**63


class ClockType(IntEnum):
    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3


class Duration:
    """A span of time in nanoseconds, as ``rclpy.duration.Duration``."""

    __slots__ = ("_nanoseconds",)

    def __init__(self, *, seconds: int | float = 0, nanoseconds: int | float = 0) -> None:
        total = int(seconds * _NS) + int(nanoseconds)
        if total >= _INT64 or total < -_INT64:
            raise OverflowError("Total nanoseconds value is too large to store in C duration.")
        self._nanoseconds = total

    @property
    def nanoseconds(self) -> int:
        return self._nanoseconds

    def __repr__(self) -> str:
        return f"Duration(nanoseconds={self._nanoseconds})"

    def __str__(self) -> str:
        return f"{self._nanoseconds} nanoseconds"

    def __add__(self, other: Duration) -> Duration:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._nanoseconds + other._nanoseconds)
        return NotImplemented

    def __sub__(self, other: Duration) -> Duration:
        if isinstance(other, Duration):
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        return NotImplemented

    def __mul__(self, other: int | float) -> Duration:
        if isinstance(other, int):
            return Duration(nanoseconds=self._nanoseconds * other)
        if isinstance(other, float):
            if math.isnan(other):
                raise ValueError("Can't multiply duration with nan")
            if math.isinf(other):
                # rclpy returns its Infinite duration (RMW_DURATION_INFINITE) for +inf.
                if other < 0:
                    raise ValueError("Can't multiply duration with -inf")
                return Duration(nanoseconds=_INT64 - 1)
            return Duration(nanoseconds=int(self._nanoseconds * other))
        return NotImplemented

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds == other._nanoseconds
        return NotImplemented

    def __ne__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds != other._nanoseconds
        return NotImplemented

    def __lt__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds < other._nanoseconds
        return NotImplemented

    def __le__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds <= other._nanoseconds
        return NotImplemented

    def __gt__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds > other._nanoseconds
        return NotImplemented

    def __ge__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds >= other._nanoseconds
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]  # as rclpy's

    def to_msg(self):
        from turtletui.interfaces.builtin_interfaces import Duration as DurationMsg

        sec, nanosec = divmod(self._nanoseconds, _NS)
        return DurationMsg(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg) -> Duration:
        from turtletui.interfaces.builtin_interfaces import Duration as DurationMsg

        if not isinstance(msg, DurationMsg):
            raise TypeError("Must pass a builtin_interfaces.msg.Duration object")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)


class Time:
    """A point in time in nanoseconds, as ``rclpy.time.Time``."""

    __slots__ = ("_nanoseconds", "_clock_type")

    def __init__(
        self,
        *,
        seconds: int | float = 0,
        nanoseconds: int | float = 0,
        clock_type: ClockType = ClockType.SYSTEM_TIME,
    ) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        if seconds < 0:
            raise ValueError("Seconds value must not be negative")
        if nanoseconds < 0:
            raise ValueError("Nanoseconds value must not be negative")
        total = int(seconds * _NS) + int(nanoseconds)
        if total >= _INT64:
            raise OverflowError("Total nanoseconds value is too large to store in C time point.")
        self._nanoseconds = total
        self._clock_type = clock_type

    @property
    def nanoseconds(self) -> int:
        return self._nanoseconds

    @property
    def clock_type(self) -> ClockType:
        return self._clock_type

    def seconds_nanoseconds(self) -> tuple[int, int]:
        return divmod(self._nanoseconds, _NS)

    def __repr__(self) -> str:
        return f"Time(nanoseconds={self._nanoseconds}, clock_type={self._clock_type.name})"

    def __add__(self, other: Duration) -> Time:
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._nanoseconds + other.nanoseconds, clock_type=self._clock_type)
            except OverflowError as e:
                raise OverflowError("Addition leads to overflow in C storage.") from e
        return NotImplemented

    def __radd__(self, other: Duration) -> Time:
        return self.__add__(other)

    def __sub__(self, other: Time | Duration) -> Time | Duration:
        if isinstance(other, Time):
            if other._clock_type != self._clock_type:
                raise TypeError("Can't subtract times with different clock types")
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        if isinstance(other, Duration):
            try:
                return Time(nanoseconds=self._nanoseconds - other.nanoseconds, clock_type=self._clock_type)
            except ValueError as e:
                raise ValueError("Subtraction leads to negative time.") from e
        return NotImplemented

    def _other_ns(self, other: Time) -> int:
        if other._clock_type != self._clock_type:
            raise TypeError("Can't compare times with different clock types")
        return other._nanoseconds

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Time):
            return self._nanoseconds == self._other_ns(other)
        return NotImplemented

    def __ne__(self, other: object) -> bool:
        if isinstance(other, Time):
            return self._nanoseconds != self._other_ns(other)
        return NotImplemented

    def __lt__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._nanoseconds < self._other_ns(other)
        return NotImplemented

    def __le__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._nanoseconds <= self._other_ns(other)
        return NotImplemented

    def __gt__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._nanoseconds > self._other_ns(other)
        return NotImplemented

    def __ge__(self, other: Time) -> bool:
        if isinstance(other, Time):
            return self._nanoseconds >= self._other_ns(other)
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]  # as rclpy's

    def to_msg(self):
        from turtletui.interfaces.builtin_interfaces import Time as TimeMsg

        sec, nanosec = self.seconds_nanoseconds()
        return TimeMsg(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        from turtletui.interfaces.builtin_interfaces import Time as TimeMsg

        if not isinstance(msg, TimeMsg):
            raise TypeError("Must pass a builtin_interfaces.msg.Time object")
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)


class Clock:
    """A clock reading simulated time: it advances only as the simulation does.

    Whatever its type (ROS, system or steady time), it reads the run's simulated clock:
    a controller sees one consistent time. ``Clock(clock_type=ClockType.ROS_TIME)`` is a
    ROSClock, as in rclpy."""

    _context: Context | None = None
    _ros_time_active = False
    """Whether now() reads ``_ros_time_ns`` (a ROSClock of a node with use_sim_time)."""
    _ros_time_ns = 0

    def __new__(cls, *, clock_type: ClockType = ClockType.SYSTEM_TIME) -> Clock:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        self = super().__new__(ROSClock if clock_type is ClockType.ROS_TIME else cls)
        self._clock_type = clock_type
        return self

    @property
    def clock_type(self) -> ClockType:
        return self._clock_type

    def __repr__(self) -> str:
        return f"Clock(clock_type={self._clock_type.name})"

    def _ctx(self, context: Context | None = None) -> Context:
        from turtletui.compat.context import get_default_context

        return context or self._context or get_default_context()

    def now(self) -> Time:
        if self._ros_time_active:
            return Time(nanoseconds=self._ros_time_ns, clock_type=self._clock_type)
        return Time(nanoseconds=self._ctx().host.graph.stamp_ns, clock_type=self._clock_type)

    def sleep_for(self, rel_time: Duration, context: Context | None = None) -> bool:
        return self.sleep_until(self.now() + rel_time, context)

    def sleep_until(self, until: Time, context: Context | None = None) -> bool:
        if not isinstance(until, Time):
            raise TypeError("Time must be specified as rclpy.time.Time")
        host = self._ctx(context).host
        return host.sleep_until(until.nanoseconds - host.graph.epoch_ns)


class ROSClock(Clock):
    def __new__(cls) -> ROSClock:
        return super().__new__(Clock, clock_type=ClockType.ROS_TIME)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the clock reads /clock (its node's use_sim_time) instead of
        the run's own time (which is simulated either way)."""
        return self._ros_time_active

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        self._ros_time_active = bool(enabled)

    def set_ros_time_override(self, time: Time) -> None:
        """What the clock reads while ROS time is active (the last /clock message)."""
        if not isinstance(time, Time):
            raise TypeError("Time must be specified as rclpy.time.Time")
        self._ros_time_ns = time.nanoseconds


def clock_for(context: Context, clock_type: ClockType = ClockType.ROS_TIME) -> Clock:
    """A clock bound to ``context`` (what ``node.get_clock()`` returns)."""
    clock = Clock(clock_type=clock_type)
    clock._context = context
    return clock
