"""``rclpy.timer``: Timer and Rate, on the run's time or on a node's /clock.

A timer keeps rcl's bookkeeping on its clock (rcl/src/rcl/timer.c). While
that clock reads the run's time (every clock but a ROS clock whose node has
use_sim_time on), the graph's heap of timers fires it, so that it costs
nothing between calls. While it reads /clock, the graph's clock no longer
drives it: it fires when /clock jumps past its next call, once however far
the jump went, as rcl's jump callback and ``rcl_timer_call`` make it; a jump
back further than its last call restarts its period; ROS time switched on or
off carries the part of the period already gone over into the new time, as
rcl's "time credit" does. With nothing publishing /clock it never fires.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from turtletui.compat.destroyable import Destroyable
from turtletui.compat.executors import (
    busy_exclusive_group,
    nothing_spins,
    threads_that_can_help,
    wait_in_host,
)
from turtletui.compat.identity import as_rclpy
from turtletui.compat.time import (
    _SOURCE_CHANGES,
    Clock,
    ClockChange,
    ClockType,
    Duration,
    JumpHandle,
    JumpThreshold,
    ROSClock,
    Time,
    TimeJump,
)

if TYPE_CHECKING:
    from turtletui.compat.node import Node
    from turtletui.graph import core

_NS = 1_000_000_000
ZERO_PERIOD_NS = 1_000_000
"""How often a timer of period 0 fires here: rcl has it ready at every spin,
which under simulated time would be every nanosecond (a run that never
ends); once a simulated millisecond is as often as a busy executor spins."""


def scheduled_period(period_ns: int) -> int:
    """The period the graph fires a timer asked for ``period_ns`` with (0: ZERO_PERIOD_NS)."""
    return period_ns if period_ns > 0 else ZERO_PERIOD_NS
_TIMER_THRESHOLD = JumpThreshold(min_forward=Duration(nanoseconds=1), min_backward=Duration(nanoseconds=-1))
"""What rcl_timer_init registers on a ROS clock: every jump, and ROS time switched on or off."""


class TimerInfo:
    """When a timer's call was due and when it was made, as ``rclpy.timer.TimerInfo``: what a
    timer callback gets for a parameter annotated ``TimerInfo``."""

    def __init__(
        self, *, expected_call_time: int = 0, actual_call_time: int = 0, clock_type: ClockType = ClockType.SYSTEM_TIME
    ) -> None:
        if not isinstance(clock_type, ClockType):
            raise TypeError("Clock type must be a ClockType enum")
        if expected_call_time < 0 or actual_call_time < 0:
            raise ValueError("call time values must not be negative")
        self._expected_call_time = Time(nanoseconds=expected_call_time, clock_type=clock_type)
        self._actual_call_time = Time(nanoseconds=actual_call_time, clock_type=clock_type)

    @property
    def expected_call_time(self) -> Time:
        return self._expected_call_time

    @property
    def actual_call_time(self) -> Time:
        return self._actual_call_time


def timer_info_parameter(callback: Callable) -> str | None:
    """The first parameter of ``callback`` annotated ``TimerInfo`` (rclpy's executor passes it
    the call's TimerInfo by that name), or None."""
    try:
        parameters = inspect.signature(callback).parameters.values()
    except (TypeError, ValueError):
        return None
    return next((p.name for p in parameters if p.annotation is TimerInfo), None)


def with_timer_info(callback: Callable, parameter: str, timer: list[Timer]) -> Callable[[], Any]:
    """``callback`` called with the TimerInfo of each call of ``timer[0]`` as ``parameter``."""

    @functools.wraps(callback)
    def call() -> Any:
        return callback(**{parameter: timer[0]._info()})

    return call


class Timer(Destroyable):
    """Calls ``callback()`` every ``timer_period_ns`` of its clock's time."""

    def __init__(self, node: Node, record: core.Timer, clock: Clock, period_ns: int | None = None) -> None:
        self._node = node
        self._period_ns = record.period_ns if period_ns is None else period_ns
        """The period asked for: 0 stays 0 here, while the graph fires such a timer every ZERO_PERIOD_NS."""
        self._record = record
        self._graph = node._graph
        self._clock = clock
        self._callback: Any = None
        self.callback_group = None
        # rcl's state, in the clock's nanoseconds, while /clock drives the timer
        self._on_clock = False
        self._next_call = self._last_call = self._credit = 0
        self._pending = False
        """Whether a call is queued on the graph and not yet taken."""
        self._expected = 0
        """While /clock drives it, when the call being made was due."""
        self._jump_handle: _TimerJumps | None = None
        if isinstance(clock, ROSClock):
            self._jump_handle = _TimerJumps(self)
            if clock.ros_time_is_active:  # made on /clock time: rcl_timer_init's times
                now = clock.now().nanoseconds
                self._take_off_graph(now, now + record.period_ns)

    @property
    def clock(self) -> Clock:
        return self._clock

    @property
    def handle(self) -> TimerHandle:
        """The timer's rcl handle (rclpy's ``_rclpy.Timer``), as rclpy's Rate and examples use it."""
        return TimerHandle(self)

    @property
    def callback(self) -> Any:
        """The function the timer calls, as given to create_timer."""
        return self._callback

    @callback.setter
    def callback(self, callback: Any) -> None:
        """Call ``callback`` from the next call on, as rclpy's executor reads
        ``timer.callback`` at each (a TimerInfo parameter, too)."""
        self._callback = callback
        self._record.callback = self._node._timer_run(callback, self.callback_group, [self], [self._record])

    @property
    def timer_period_ns(self) -> int:
        self._require_alive()
        return self._period_ns

    @timer_period_ns.setter
    def timer_period_ns(self, value: int) -> None:
        """A new period, as rcl_timer_exchange_period: the next call stays when it was due,
        the calls after it follow the new period."""
        self._require_alive()
        period_ns = int(value)
        self._period_ns = period_ns
        self._record.period_ns = scheduled_period(period_ns)

    def cancel(self) -> None:
        self._require_alive()
        self._graph.cancel_timer(self._record)

    def is_canceled(self) -> bool:
        self._require_alive()
        return self._record.canceled

    def reset(self) -> None:
        self._require_alive()
        if self._on_clock:
            self._record.canceled = False
            self._next_call = self._now() + self._record.period_ns
        else:
            self._graph.reset_timer(self._record)

    def is_ready(self) -> bool:
        self._require_alive()
        # a period of 0 is always ready in rcl
        return not self._record.canceled and (self._period_ns == 0 or self._next_call_ns() <= self._now())

    def time_since_last_call(self) -> int:
        self._require_alive()
        return self._now() - self._last_call_ns()

    def time_until_next_call(self) -> int | None:
        self._require_alive()
        if self._record.canceled:
            return None
        return self._next_call_ns() - self._now()

    def destroy(self) -> None:
        self._node._release_entity(self, self._node._graph.cancel_timer)

    def _info(self) -> TimerInfo:
        """The TimerInfo of the call being made (rcl_timer_call_with_info): when it was due
        (a period before the next call), and now."""
        expected = self._expected if self._on_clock else self._next_call_ns() - self._record.period_ns
        return TimerInfo(
            expected_call_time=max(expected, 0), actual_call_time=self._now(), clock_type=self._clock.clock_type
        )

    # -- rcl's bookkeeping ---------------------------------------------------------------------
    def _now(self) -> int:
        return self._clock.now().nanoseconds

    def _next_call_ns(self) -> int:
        if self._on_clock:
            return self._next_call
        return self._graph.epoch_ns + self._record.next_due

    def _last_call_ns(self) -> int:
        if self._on_clock:
            return self._last_call
        return self._next_call_ns() - self._record.period_ns

    def _take_off_graph(self, last_call: int, next_call: int) -> None:
        self._on_clock = True
        self._last_call, self._next_call = last_call, next_call
        self._graph.park_timer(self._record)

    def _put_on_graph(self) -> None:
        self._on_clock = False
        self._graph.schedule_timer(self._record, max(self._next_call - self._graph.epoch_ns, self._graph.now_ns))

    def _alive(self) -> bool:
        if self._destroyed or not self._record.node.alive:
            if self._jump_handle is not None:
                self._jump_handle.unregister()
                self._jump_handle = None
            return False
        return True

    def _before_jump(self, jump: TimeJump) -> None:
        """rcl's pre-jump: on a change of time source, the part of the period
        still to go is kept as credit (the clock still reads the old source)."""
        if not self._alive() or jump.clock_change not in _SOURCE_CHANGES:
            return
        now = self._now()
        if now != 0:
            self._credit = self._next_call_ns() - now
        if jump.clock_change is ClockChange.ROS_TIME_ACTIVATED:
            self._take_off_graph(self._last_call_ns(), self._next_call_ns())

    def _after_jump(self, jump: TimeJump) -> None:
        """rcl's post-jump (``_rcl_timer_time_jump``)."""
        if not self._alive():
            return
        period = self._record.period_ns
        now = self._now()
        if jump.clock_change in _SOURCE_CHANGES:
            credit, self._credit = self._credit, 0
            if now != 0 and credit:
                self._next_call = now - credit + period
                self._last_call = now - credit
            elif now == 0:
                self._credit = credit  # rcl leaves it for a later change of source
            if jump.clock_change is ClockChange.ROS_TIME_DEACTIVATED:
                self._put_on_graph()
                return
        elif now < self._last_call and self._next_call > now:
            # back further than the last call: the next one a period from now
            self._next_call, self._last_call = now + period, now
        if self._next_call <= now:
            self._queue_call()

    def _queue_call(self) -> None:
        if not self._pending and not self._record.canceled:
            self._pending = True
            self._graph.ready.append((self._record.owner, self._take))

    def _take(self) -> None:
        """What the executor does with a ready timer: ``rcl_timer_call``, then the callback."""
        self._pending = False
        if not self._on_clock or self._record.canceled or not self._alive():
            return
        now = self._now()
        if self._next_call > now:
            return
        period = self._record.period_ns
        self._last_call = now
        self._expected = self._next_call
        next_call = self._next_call + period
        if next_call <= now:  # missed calls are skipped, not made up
            next_call += (1 + (now - next_call) // period) * period
        self._next_call = next_call
        self._record.callback()


class TimerHandle:
    """What ``timer.handle`` is in rclpy (``_rclpy.Timer``): the rcl timer's calls,
    refused with InvalidHandle once the timer is destroyed; ``with handle:`` too."""

    def __init__(self, timer: Timer) -> None:
        self._timer = timer

    @property
    def pointer(self) -> int:
        """A number naming the rcl timer (its address in rclpy)."""
        self._timer._require_alive()
        return id(self._timer)

    def __enter__(self) -> TimerHandle:
        self._timer._require_alive()
        return self

    def __exit__(self, *exc_info: object) -> None:
        pass

    def is_timer_ready(self) -> bool:
        return self._timer.is_ready()

    def is_timer_canceled(self) -> bool:
        return self._timer.is_canceled()

    def cancel_timer(self) -> None:
        self._timer.cancel()

    def reset_timer(self) -> None:
        self._timer.reset()

    def get_timer_period(self) -> int:
        return self._timer.timer_period_ns

    def change_timer_period(self, period_ns: int) -> None:
        self._timer.timer_period_ns = period_ns

    def time_since_last_call(self) -> int:
        return self._timer.time_since_last_call()

    def time_until_next_call(self) -> int | None:
        return self._timer.time_until_next_call()

    def destroy_when_not_in_use(self) -> None:
        self._timer.destroy()


class _TimerJumps(JumpHandle):
    """The jump callback rcl_timer_init registers on a ROS clock for its timer."""

    def __init__(self, timer: Timer) -> None:
        super().__init__(clock=timer.clock, threshold=_TIMER_THRESHOLD, pre_callback=None, post_callback=timer._after_jump)
        self._timer = timer

    def _call(self, jump: TimeJump, before: bool) -> None:
        if before:
            self._timer._before_jump(jump)
        else:
            self._timer._after_jump(jump)


class Rate:
    """``node.create_rate(hz)``: as rclpy's, a timer of the node's clock in a
    reentrant group of its own; ``sleep()`` returns when the timer fires, at
    once if it fired since the last sleep. The timer needs an executor
    spinning the node (and, on /clock time, something publishing /clock)."""

    def __init__(self, node: Node, frequency: float, clock: Clock | None = None) -> None:
        # rclpy's checks and texts: `frequency <= 0` (a str or None raises its TypeError),
        # then create_timer's conversion of the period (nan refused, inf a period of 0)
        if frequency <= 0:
            raise ValueError("frequency must be > 0")
        self._node = node
        self._fired = False
        self._destroyed = False
        self._timer = node.create_timer(1.0 / frequency, self._tick, node._rate_group, clock)

    def _tick(self) -> None:
        self._fired = True

    def sleep(self) -> None:
        """Wait for the rate's timer to fire."""
        if self._destroyed:
            raise RuntimeError("Rate cannot sleep because it has been destroyed")
        node = self._node
        host = node.context.host
        hang = self._why_sleep_hangs(host)
        if hang:
            raise RuntimeError(
                f"Rate.sleep() {hang}: in ROS 2 it would wait for ever. Spin the node in a thread "
                "(threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()) and keep the loop "
                "in main, or drive the loop from a timer (create_timer) instead."
            )
        if not self._fired:
            wait_in_host(host, lambda: self._fired or self._destroyed, None)
        self._fired = False

    def _why_sleep_hangs(self, host: Any) -> str:
        node = self._node
        clock_sub = node._time_source._clock_sub if self._timer._on_clock else None
        if host.callback_depth:
            if not threads_that_can_help(node):
                return "inside a callback of a single-threaded executor: the rate's timer cannot fire while it waits"
            if clock_sub is not None and busy_exclusive_group(node.default_callback_group):
                return (
                    "inside a callback of the node's default callback group on /clock time (use_sim_time): "
                    "the node's /clock subscription is in that group too, so its clock cannot move while it waits"
                )
            return ""
        if nothing_spins(node):
            return "with nothing spinning the node: the rate's timer never fires"
        return ""

    def destroy(self) -> None:
        """Stop the rate: a sleep after it raises. As rclpy's, the rate's timer
        stays the node's until ``node.destroy_rate(rate)`` destroys it."""
        self._destroyed = True

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.timer", Timer, Rate, TimerInfo)
TimerHandle.__name__ = TimerHandle.__qualname__ = "Timer"
TimerHandle.__module__ = "rclpy._rclpy_pybind11"  # as rclpy's prints
