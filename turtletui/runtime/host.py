"""What every controller host shares (in-process and sandboxed child)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from turtletui.compat.dispatch import callback_label


class RunEnded(KeyboardInterrupt):
    """Raised in a controller that still waits once its run is over, as Ctrl-C
    stops a node in ROS: in a callback (whose loop of sleeps would otherwise
    never end, each returning at once), or in its main thread after
    POST_RUN_WAITS such waits (a loop in main() without ``rclpy.ok()``).
    The hosts take it for the run's end, not a crash; ``except
    KeyboardInterrupt`` catches it as it would Ctrl-C. Threads the controller
    started are left alone, as Ctrl-C leaves them."""


POST_RUN_WAITS = 1000
"""Waits the controller's main thread may make once the run is over (its way
out: a node destroyed, a last sleep) before it is stopped."""


class _ThreadDepth(threading.local):
    n = 0
    call = 0


class Depth:
    """A plain depth counter, for a host whose callbacks run on one thread
    (slots: bumped twice for every delivery), and the number of the call
    running (turtletui.compat.dispatch numbers them: LogRecord.call)."""

    __slots__ = ("n", "call")

    def __init__(self) -> None:
        self.n = 0
        self.call = 0


class CallbackTracking:
    """Counts how deep the calling thread is inside controller callbacks, so
    a call that would deadlock ROS (spinning inside a callback) can say so
    instead."""

    _depth: Any = _ThreadDepth()
    """How deep each thread is inside controller callbacks (a thread that spins
    in a callback deadlocks in ROS; another thread spinning meanwhile does not).
    A host whose callbacks all run on one thread may keep a plain counter."""

    controller_thread: int = 0
    """The thread the controller's main() runs on (threading.get_ident())."""
    _waits_after_end = 0

    @property
    def callback_depth(self) -> int:
        return self._depth.n

    def waited_after_end(self) -> bool:
        """What a wait that returned because the run is over returns (False),
        unless the waiter is stopped (:class:`RunEnded`)."""
        if self.callback_depth:
            raise RunEnded("the run ended")
        if threading.get_ident() == self.controller_thread:
            self._waits_after_end += 1
            if self._waits_after_end > POST_RUN_WAITS:
                raise RunEnded("the run ended")
        return False

    @property
    def callback_counter(self) -> Any:
        """What counts the depth: ``callback_counter.n`` is the calling thread's.
        turtletui.compat.dispatch bumps it inline, as ``wrap_callback`` does."""
        return self._depth

    def wrap_callback(self, callback: Callable) -> Callable:
        """``callback`` as the graph should call it: counted while it runs.
        Its ``label`` names it in reports (``pose_callback``)."""
        depth = self._depth

        def run(*args: Any) -> Any:
            depth.n += 1
            try:
                return callback(*args)
            finally:
                depth.n -= 1

        run.label = callback_label(callback)  # type: ignore[attr-defined]
        return run
