"""The app's simulation clock: a thread that calls one function every 16 ms.

Ticks are due at fixed monotonic deadlines (start + k x period), so late
ticks are made up by the next ones coming a little early and the mean period
stays exact (an interval timer that re-arms after each call drifts, one that
skips late calls loses ticks). The thread is apart from the screen's event loop: painting the screen
or laying out a panel, which can take tens of milliseconds in Textual, does
not delay the simulation. Whatever the tick touches is shared with the screen,
so the tick runs holding ``lock``; the screen holds it only to read or change
the simulation, never while it paints. No Textual here.
"""

from __future__ import annotations

import sys
import threading
import time
from collections import deque
from collections.abc import Callable
from contextlib import AbstractContextManager

MAX_BEHIND = 0.25
"""Seconds a tick may fall behind its deadline before the schedule starts
afresh (a suspended laptop, a stopped process): no burst of catch-up ticks."""

CATCH_UP = 0.003
"""Seconds at most by which a tick comes early to make up for a late one:
after a tick 8 ms late the next gaps are 13, 13, 14 ms rather than one of
8 ms, so the mean stays exact and no gap strays far on either side."""

SWITCH_INTERVAL = 0.001
"""Seconds Python lets a thread run before another may take the interpreter
(5 ms by default): the tick thread waking up waits at most this long for the
screen's thread to let go."""


class Schedule:
    """When ticks are due: every ``period`` seconds from the start, late ticks
    made up at most CATCH_UP seconds early, afresh after MAX_BEHIND."""

    def __init__(self, period: float, start: float) -> None:
        self.period = period
        self.due = start + period
        """The next deadline on the fixed grid."""
        self.last: float | None = None
        """When the last tick ran."""

    def wake_at(self) -> float:
        """When the next tick should run."""
        if self.last is None:
            return self.due
        return max(self.due, self.last + self.period - CATCH_UP)

    def ticked(self, now: float) -> float | None:
        """Note a tick that ran at ``now``; the gap since the one before (None for the first)."""
        gap = None if self.last is None else now - self.last
        self.last = now
        self.due += self.period
        if now - self.due > MAX_BEHIND:
            self.due = now + self.period
        return gap


class Ticker:
    """Calls ``tick(now)`` every ``period`` seconds of ``clock`` in its own thread.

    ``gaps`` holds the wall seconds between the latest ticks (how steady the
    loop is). An exception in ``tick`` stops the ticker and is handed to
    ``on_error`` (from the ticker's thread).
    """

    def __init__(
        self,
        period: float,
        tick: Callable[[float], None],
        lock: AbstractContextManager,
        *,
        clock: Callable[[], float] = time.monotonic,
        on_error: Callable[[BaseException], None] | None = None,
        gaps: deque[float] | None = None,
    ) -> None:
        self.period = period
        self.gaps: deque[float] = gaps if gaps is not None else deque(maxlen=4096)
        self._tick = tick
        self._lock = lock
        self._clock = clock
        self._on_error = on_error
        self._stopping = threading.Event()
        self._thread: threading.Thread | None = None

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def start(self) -> None:
        if self._thread is not None:
            return
        if sys.getswitchinterval() > SWITCH_INTERVAL:
            sys.setswitchinterval(SWITCH_INTERVAL)
        self._thread = threading.Thread(target=self._run, name="turtletui-ticker", daemon=True)
        self._thread.start()

    def stop(self, timeout: float = 2.0) -> None:
        """Stop ticking; returns once the thread has ended (or ``timeout`` passed)."""
        self._stopping.set()
        thread = self._thread
        if thread is not None and thread is not threading.current_thread():
            thread.join(timeout)

    def _run(self) -> None:
        clock = self._clock
        schedule = Schedule(self.period, clock())
        try:
            while not self._stopping.wait(max(schedule.wake_at() - clock(), 0.0)):
                now = clock()
                with self._lock:
                    if self._stopping.is_set():
                        return
                    self._tick(now)
                gap = schedule.ticked(now)
                if gap is not None:
                    self.gaps.append(gap)
        except BaseException as err:  # noqa: BLE001 - handed to the app, which shows it
            if self._on_error is not None:
                self._on_error(err)
            else:
                raise
