"""``rclpy.time``, ``rclpy.duration`` and ``rclpy.clock``: simulated ROS time."""

from __future__ import annotations

from enum import IntEnum
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from turtletui.compat.context import Context

_NS = 1_000_000_000


class ClockType(IntEnum):
    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3


class Duration:
    """A span of time in nanoseconds, as ``rclpy.duration.Duration``."""

    __slots__ = ("_nanoseconds",)

    def __init__(self, *, seconds: float = 0, nanoseconds: int = 0) -> None:
        self._nanoseconds = int(seconds * _NS) + int(nanoseconds)

    @property
    def nanoseconds(self) -> int:
        return self._nanoseconds

    def __repr__(self) -> str:
        return f"Duration(nanoseconds={self._nanoseconds})"

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Duration):
            return self._nanoseconds == other._nanoseconds
        return NotImplemented

    def __lt__(self, other: Duration) -> bool:
        return self._nanoseconds < other._nanoseconds

    def __le__(self, other: Duration) -> bool:
        return self._nanoseconds <= other._nanoseconds

    def __gt__(self, other: Duration) -> bool:
        return self._nanoseconds > other._nanoseconds

    def __ge__(self, other: Duration) -> bool:
        return self._nanoseconds >= other._nanoseconds

    def __hash__(self) -> int:
        return hash(self._nanoseconds)

    def __add__(self, other: Duration) -> Duration:
        if not isinstance(other, Duration):
            return NotImplemented
        return Duration(nanoseconds=self._nanoseconds + other._nanoseconds)

    def __sub__(self, other: Duration) -> Duration:
        if not isinstance(other, Duration):
            return NotImplemented
        return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)

    def __mul__(self, factor: float) -> Duration:
        return Duration(nanoseconds=int(self._nanoseconds * factor))

    def to_msg(self):
        from turtletui.interfaces.builtin_interfaces import Duration as DurationMsg

        sec, nanosec = divmod(self._nanoseconds, _NS)
        return DurationMsg(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg) -> Duration:
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec)


class Time:
    """A point in time in nanoseconds, as ``rclpy.time.Time``."""

    __slots__ = ("_nanoseconds", "_clock_type")

    def __init__(
        self, *, seconds: float = 0, nanoseconds: int = 0, clock_type: ClockType = ClockType.SYSTEM_TIME
    ) -> None:
        total = int(seconds * _NS) + int(nanoseconds)
        if total < 0:
            raise ValueError("Time cannot be negative")
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
        if not isinstance(other, Duration):
            return NotImplemented
        return Time(nanoseconds=self._nanoseconds + other.nanoseconds, clock_type=self._clock_type)

    __radd__ = __add__

    def __sub__(self, other: Time | Duration) -> Time | Duration:
        if isinstance(other, Time):
            if other._clock_type != self._clock_type:
                raise TypeError("Can't subtract times with different clock types")
            return Duration(nanoseconds=self._nanoseconds - other._nanoseconds)
        if isinstance(other, Duration):
            return Time(nanoseconds=self._nanoseconds - other.nanoseconds, clock_type=self._clock_type)
        return NotImplemented

    def _key(self, other: Time) -> int:
        if other._clock_type != self._clock_type:
            raise TypeError("Can't compare times with different clock types")
        return other._nanoseconds

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        return self._nanoseconds == self._key(other)

    def __lt__(self, other: Time) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        return self._nanoseconds < self._key(other)

    def __le__(self, other: Time) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        return self._nanoseconds <= self._key(other)

    def __gt__(self, other: Time) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        return self._nanoseconds > self._key(other)

    def __ge__(self, other: Time) -> bool:
        if not isinstance(other, Time):
            return NotImplemented
        return self._nanoseconds >= self._key(other)

    def __hash__(self) -> int:
        return hash((self._nanoseconds, self._clock_type))

    def to_msg(self):
        from turtletui.interfaces.builtin_interfaces import Time as TimeMsg

        sec, nanosec = divmod(self._nanoseconds, _NS)
        return TimeMsg(sec=sec, nanosec=nanosec)

    @classmethod
    def from_msg(cls, msg, clock_type: ClockType = ClockType.ROS_TIME) -> Time:
        return cls(seconds=msg.sec, nanoseconds=msg.nanosec, clock_type=clock_type)


class Clock:
    """A node's clock: simulated ROS time, advancing only as the simulation does."""

    def __init__(self, *, clock_type: ClockType = ClockType.ROS_TIME, context: Context | None = None) -> None:
        self._clock_type = clock_type
        self._context = context

    @property
    def clock_type(self) -> ClockType:
        return self._clock_type

    def now(self) -> Time:
        from turtletui.compat.context import get_default_context

        context = self._context or get_default_context()
        return Time(nanoseconds=context.host.graph.stamp_ns, clock_type=self._clock_type)

    def sleep_for(self, rel_time: Duration | float, context: Context | None = None) -> bool:
        ns = rel_time.nanoseconds if isinstance(rel_time, Duration) else int(rel_time * _NS)
        return self.sleep_until(Time(nanoseconds=self.now().nanoseconds + ns, clock_type=self._clock_type))

    def sleep_until(self, until: Time, context: Context | None = None) -> bool:
        from turtletui.compat.context import get_default_context

        ctx = context or self._context or get_default_context()
        return ctx.host.sleep_until(until.nanoseconds - ctx.host.graph.epoch_ns)


class ROSClock(Clock):
    def __init__(self) -> None:
        super().__init__(clock_type=ClockType.ROS_TIME)

    @property
    def ros_time_is_active(self) -> bool:
        return True
