"""``rclpy.signals``: which signal handlers rclpy would have installed.

rclpy installs handlers for SIGINT and SIGTERM at ``rclpy.init()`` (unless
``signal_handler_options=SignalHandlerOptions.NO``, the pattern of a node that
publishes a last stop command on Ctrl-C itself) and removes them at
``rclpy.shutdown()``. Its SIGINT handler shuts every context down (rcl's
part: ``rclpy.ok()`` is False, a publish fails) and then calls the handler it
replaced, which raises KeyboardInterrupt: so does turtletui's, on the thread
that may set one. SIGTERM is left to turtletui, which ends a run itself.
"""

from __future__ import annotations

import signal
import threading
from enum import IntEnum
from typing import Any


class SignalHandlerOptions(IntEnum):
    """Which signals rclpy handles (rclpy's pybind11 enum, in its order)."""

    ALL = 3
    NO = 0
    SIGINT = 1
    SIGTERM = 2

    # rclpy's is a pybind11 enum: it prints as SignalHandlerOptions.NO, not as its number.
    def __str__(self) -> str:
        return f"SignalHandlerOptions.{self.name}"

    def __format__(self, spec: str) -> str:
        return format(str(self), spec)


_current = SignalHandlerOptions.NO
_replaced: list[Any] = []
"""The SIGINT handler rclpy's replaced, while it is installed."""


def _on_sigint(signum: int, frame: Any) -> None:
    from turtletui.compat.context import interrupt_contexts

    interrupt_contexts()
    previous = _replaced[0] if _replaced else signal.default_int_handler
    if callable(previous):
        previous(signum, frame)
    elif previous != signal.SIG_IGN:
        raise KeyboardInterrupt


def install_signal_handlers(options: SignalHandlerOptions = SignalHandlerOptions.ALL) -> None:
    """Install rclpy's handlers for ``options`` (rclpy.init does this): SIGINT's shuts the contexts down."""
    global _current
    _current = SignalHandlerOptions(options)
    wanted = _current in (SignalHandlerOptions.ALL, SignalHandlerOptions.SIGINT)
    if wanted and threading.current_thread() is threading.main_thread():
        if signal.getsignal(signal.SIGINT) is not _on_sigint:  # a host may have put its own back since
            _replaced[:] = [signal.signal(signal.SIGINT, _on_sigint)]
    elif not wanted:
        _restore()


def _restore() -> None:
    if _replaced and threading.current_thread() is threading.main_thread():
        previous = _replaced.pop()
        if signal.getsignal(signal.SIGINT) is _on_sigint:
            signal.signal(signal.SIGINT, previous)


def get_current_signal_handlers_options() -> SignalHandlerOptions:
    """The signal handlers rclpy would have installed now."""
    return _current


def uninstall_signal_handlers() -> None:
    """Remove rclpy's handlers (rclpy.shutdown does this)."""
    global _current
    _current = SignalHandlerOptions.NO
    _restore()
