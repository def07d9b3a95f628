"""``rclpy.time``, ``rclpy.duration`` and ``rclpy.clock``: simulated ROS time.

Arithmetic, comparisons, bounds and error types follow rclpy's (Duration and Time
are unhashable there too, since they define ``__eq__`` without ``__hash__``).
A ROS clock's time jumps (its /clock override set, ROS time switched on or
off) call the jump callbacks registered on it under rcl's thresholds, as
rcl_set_ros_time_override and rcl_enable_ros_time_override do."""

from __future__ import annotations

import math
from collections.abc import Callable
from enum import IntEnum
from typing import TYPE_CHECKING

from turtletui.compat.exceptions import NotInitializedException
from turtletui.compat.identity import as_rclpy

if TYPE_CHECKING:
    from turtletui.compat.context import Context

_NS = 1_000_000_000
_INT64 = 2**63


class ClockType(IntEnum):
    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3

    # rclpy's is a pybind11 enum: it prints as ClockType.ROS_TIME, not as its number.
    def __str__(self) -> str:
        return f"ClockType.{self.name}"

    def __format__(self, spec: str) -> str:
        return format(str(self), spec)


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
        if self._nanoseconds == _INT64 - 1:
            return "Infinite"
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
                return Infinite
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


Infinite = Duration(nanoseconds=_INT64 - 1)
"""``rclpy.duration.Infinite``: rmw's RMW_DURATION_INFINITE, the longest Duration."""


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


class ClockChange(IntEnum):
    """What a time jump did to a clock's source, as ``rclpy.clock.ClockChange`` (rcl's values)."""

    ROS_TIME_NO_CHANGE = 1
    ROS_TIME_ACTIVATED = 2
    ROS_TIME_DEACTIVATED = 3
    SYSTEM_TIME_NO_CHANGE = 4


class JumpThreshold:
    """When a jump callback runs: a forward jump of at least ``min_forward``, a
    backward one of at least ``-min_backward``, or ROS time switched on or off."""

    def __init__(
        self, *, min_forward: Duration | None, min_backward: Duration | None, on_clock_change: bool = True
    ) -> None:
        if min_forward is not None and min_forward.nanoseconds <= 0:
            raise ValueError("min_forward must be a positive non-zero duration")
        if min_backward is not None and min_backward.nanoseconds >= 0:
            raise ValueError("min_backward must be a negative non-zero duration")
        if min_forward is None and min_backward is None and not on_clock_change:
            raise ValueError("At least one jump threshold must be enabled")
        self.min_forward = min_forward
        self.min_backward = min_backward
        self.on_clock_change = on_clock_change


class TimeJump:
    """A jump of a clock: ``clock_change`` and ``delta`` (a Duration)."""

    def __init__(self, clock_change: ClockChange, delta: Duration) -> None:
        if not isinstance(clock_change, ClockChange):
            raise TypeError("clock_change must be an instance of rclpy.clock.ClockChange")
        self._clock_change = clock_change
        self._delta = delta

    @property
    def clock_change(self) -> ClockChange:
        return self._clock_change

    @property
    def delta(self) -> Duration:
        return self._delta


class JumpHandle:
    """A jump callback registered on a clock; ``unregister()`` removes it."""

    def __init__(
        self,
        *,
        clock: Clock,
        threshold: JumpThreshold,
        pre_callback: Callable[[], None] | None,
        post_callback: Callable[[TimeJump], None] | None,
    ) -> None:
        if pre_callback is None and post_callback is None:
            raise ValueError("One of pre_callback or post_callback must be callable")
        if pre_callback is not None and not callable(pre_callback):
            raise ValueError("pre_callback must be callable if given")
        if post_callback is not None and not callable(post_callback):
            raise ValueError("post_callback must be callable if given")
        self._clock: Clock | None = clock
        self._pre_callback = pre_callback
        self._post_callback = post_callback
        self._on_clock_change = threshold.on_clock_change
        self._min_forward = 0 if threshold.min_forward is None else threshold.min_forward.nanoseconds
        self._min_backward = 0 if threshold.min_backward is None else threshold.min_backward.nanoseconds
        clock._jump_handles = [*clock._jump_handles, self]

    def _exceeded(self, jump: TimeJump) -> bool:
        """rcl_clock_call_callbacks' test."""
        delta = jump.delta.nanoseconds
        return (
            (self._on_clock_change and jump.clock_change in _SOURCE_CHANGES)
            or (self._min_backward < 0 and delta <= self._min_backward)
            or (self._min_forward > 0 and delta >= self._min_forward)
        )

    def _call(self, jump: TimeJump, before: bool) -> None:
        if before:
            if self._pre_callback is not None:
                self._pre_callback()
        elif self._post_callback is not None:
            self._post_callback(jump)

    def unregister(self) -> None:
        """Remove the callback from the clock."""
        if self._clock is not None:
            self._clock._jump_handles = [h for h in self._clock._jump_handles if h is not self]
            self._clock = None

    def __enter__(self) -> JumpHandle:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.unregister()


_SOURCE_CHANGES = (ClockChange.ROS_TIME_ACTIVATED, ClockChange.ROS_TIME_DEACTIVATED)


class Clock:
    """A clock reading simulated time: it advances only as the simulation does.

    Whatever its type (ROS, system or steady time), it reads the run's simulated clock:
    a controller sees one consistent time. ``Clock(clock_type=ClockType.ROS_TIME)`` is a
    ROSClock, as in rclpy."""

    _context: Context | None = None
    _ros_time_active = False
    """Whether now() reads ``_ros_time_ns`` (a ROSClock of a node with use_sim_time)."""
    _ros_time_ns = 0
    _jump_handles: list[JumpHandle] = []  # noqa: RUF012  (replaced, never mutated: per clock once one registers)

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

    def create_jump_callback(
        self,
        threshold: JumpThreshold,
        *,
        pre_callback: Callable[[], None] | None = None,
        post_callback: Callable[[TimeJump], None] | None = None,
    ) -> JumpHandle:
        """Call ``pre_callback()`` before and ``post_callback(TimeJump)`` after
        each jump of this clock that exceeds ``threshold``."""
        return JumpHandle(clock=self, threshold=threshold, pre_callback=pre_callback, post_callback=post_callback)

    def _jump(self, jump: TimeJump, before: bool) -> None:
        """Run the jump callbacks ``jump`` exceeds, in the order they were
        registered (one that raises stops the rest, as in rclpy)."""
        for handle in self._jump_handles:
            if handle._exceeded(jump):
                handle._call(jump, before)

    def sleep_for(self, rel_time: Duration, context: Context | None = None) -> bool:
        return self.sleep_until(self.now() + rel_time, context)

    def sleep_until(self, until: Time, context: Context | None = None) -> bool:
        """Wait until the clock reads ``until``. A ROS clock reading /clock waits
        for /clock to get there (another thread must spin its node); ROS time
        switched on or off ends the wait early (False), as in rclpy."""
        if not isinstance(until, Time):
            raise TypeError("Time must be specified as rclpy.time.Time")
        ctx = self._ctx(context)
        if not ctx.ok():
            raise NotInitializedException()  # rclpy checks the context before anything else
        if until.clock_type != self._clock_type:
            raise ValueError("until's clock type does not match this clock's type")
        from turtletui.compat.executors import wait_in_host

        host = ctx.host
        if not self._ros_time_active:
            return host.sleep_until(until.nanoseconds - host.graph.epoch_ns)
        changed = False

        def on_jump(jump: TimeJump) -> None:
            nonlocal changed
            changed = changed or jump.clock_change in _SOURCE_CHANGES

        threshold = JumpThreshold(min_forward=Duration(nanoseconds=1), min_backward=None)
        with self.create_jump_callback(threshold, post_callback=on_jump):
            wait_in_host(host, lambda: changed or self.now() >= until, None)
        return not changed and self.now() >= until


class ROSClock(Clock):
    def __new__(cls) -> ROSClock:
        return super().__new__(Clock, clock_type=ClockType.ROS_TIME)

    @property
    def ros_time_is_active(self) -> bool:
        """Whether the clock reads /clock (its node's use_sim_time) instead of
        the run's own time (which is simulated either way)."""
        return self._ros_time_active

    def _set_ros_time_is_active(self, enabled: bool) -> None:
        enabled = bool(enabled)
        if enabled == self._ros_time_active:
            return
        change = ClockChange.ROS_TIME_ACTIVATED if enabled else ClockChange.ROS_TIME_DEACTIVATED
        jump = TimeJump(change, Duration())
        self._jump(jump, before=True)
        self._ros_time_active = enabled
        self._jump(jump, before=False)

    def set_ros_time_override(self, time: Time) -> None:
        """What the clock reads while ROS time is active (the last /clock message)."""
        if not isinstance(time, Time):
            raise TypeError(f"Time must be specified as rclpy.time.Time. Received type: {type(time)}")
        if not self._ros_time_active:
            self._ros_time_ns = time.nanoseconds
            return
        jump = TimeJump(ClockChange.ROS_TIME_NO_CHANGE, Duration(nanoseconds=time.nanoseconds - self._ros_time_ns))
        self._jump(jump, before=True)
        self._ros_time_ns = time.nanoseconds
        self._jump(jump, before=False)


def clock_for(context: Context, clock_type: ClockType = ClockType.ROS_TIME) -> Clock:
    """A clock bound to ``context`` (what ``node.get_clock()`` returns)."""
    clock = Clock(clock_type=clock_type)
    clock._context = context
    return clock

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.clock", Clock, ROSClock, JumpThreshold, TimeJump, JumpHandle)
as_rclpy("rclpy._rclpy_pybind11", ClockType, ClockChange)
as_rclpy("rclpy.duration", Duration)
as_rclpy("rclpy.time", Time)
