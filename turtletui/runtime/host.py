"""What every controller host shares (in-process and sandboxed child)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class CallbackTracking:
    """Counts how deep the host is inside controller callbacks, so a call that
    would deadlock ROS (spinning inside a callback) can say so instead."""

    callback_depth = 0

    def wrap_callback(self, callback: Callable) -> Callable:
        """``callback`` as the graph should call it: counted while it runs."""
        host = self

        def run(*args: Any) -> Any:
            host.callback_depth += 1
            try:
                return callback(*args)
            finally:
                host.callback_depth -= 1

        return run
