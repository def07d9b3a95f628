"""What every controller host shares (in-process and sandboxed child)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

_depth = threading.local()
"""How deep each thread is inside controller callbacks (a thread that spins
in a callback deadlocks in ROS; another thread spinning meanwhile does not)."""


class CallbackTracking:
    """Counts how deep the calling thread is inside controller callbacks, so
    a call that would deadlock ROS (spinning inside a callback) can say so
    instead."""

    @property
    def callback_depth(self) -> int:
        return getattr(_depth, "n", 0)

    def wrap_callback(self, callback: Callable) -> Callable:
        """``callback`` as the graph should call it: counted while it runs.
        Its ``label`` names it in reports (``pose_callback``)."""

        def run(*args: Any) -> Any:
            _depth.n = getattr(_depth, "n", 0) + 1
            try:
                return callback(*args)
            finally:
                _depth.n -= 1

        run.label = callback_label(callback)  # type: ignore[attr-defined]
        return run


def callback_label(callback: Callable) -> str:
    """A short name for a callback: the function's or method's name, or ""
    for a lambda or another callable object."""
    name = getattr(callback, "__name__", "")
    return name if isinstance(name, str) and name.isidentifier() else ""
