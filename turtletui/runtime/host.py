"""What every controller host shares (in-process and sandboxed child)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from turtletui.compat.dispatch import callback_label


class _ThreadDepth(threading.local):
    n = 0


class Depth:
    """A plain depth counter, for a host whose callbacks run on one thread
    (slots: bumped twice for every delivery)."""

    __slots__ = ("n",)

    def __init__(self) -> None:
        self.n = 0


class CallbackTracking:
    """Counts how deep the calling thread is inside controller callbacks, so
    a call that would deadlock ROS (spinning inside a callback) can say so
    instead."""

    _depth: Any = _ThreadDepth()
    """How deep each thread is inside controller callbacks (a thread that spins
    in a callback deadlocks in ROS; another thread spinning meanwhile does not).
    A host whose callbacks all run on one thread may keep a plain counter."""

    @property
    def callback_depth(self) -> int:
        return self._depth.n

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
