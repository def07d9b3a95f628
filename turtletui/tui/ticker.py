"""The app's simulation clock: a thread that calls one function every 16 ms.

Ticks are due at fixed monotonic deadlines (start + k x period), so a late
tick is followed by an early one and the mean period stays exact (an interval
timer that re-arms after each call drifts, one that skips late calls loses
ticks). The thread is apart from the screen's event loop: painting the screen
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
from typing import ContextManager

MAX_BEHIND = 0.25
"""Seconds a tick may fall behind its deadline before the schedule starts
afresh (a suspended laptop, a stopped process): no burst of catch-up ticks."""

SWITCH_INTERVAL = 0.001
"""Seconds Python lets a thread run before another may take the interpreter
(5 ms by default): the tick thread waking up waits at most this long for the
screen's thread to let go."""


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
        lock: ContextManager,
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
        period = self.period
        due = clock() + period
        last: float | None = None
        try:
            while not self._stopping.wait(max(due - clock(), 0.0)):
                now = clock()
                with self._lock:
                    if self._stopping.is_set():
                        return
                    self._tick(now)
                if last is not None:
                    self.gaps.append(now - last)
                last = now
                due += period
                if now - due > MAX_BEHIND:
                    due = now + period
        except BaseException as err:  # noqa: BLE001 - handed to the app, which shows it
            if self._on_error is not None:
                self._on_error(err)
            else:
                raise
