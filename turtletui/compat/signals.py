"""``rclpy.signals``: which signal handlers rclpy would have installed.

rclpy installs handlers for SIGINT and SIGTERM at ``rclpy.init()`` (unless
``signal_handler_options=SignalHandlerOptions.NO``, the pattern of a node that
publishes a last stop command on Ctrl-C itself) and removes them at
``rclpy.shutdown()``. turtletui ends a run itself (Ctrl-C included), so no
handler is installed: only which ones rclpy would have is kept, as
``get_current_signal_handlers_options()`` reports it.
"""

from __future__ import annotations

from enum import IntEnum


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


def install_signal_handlers(options: SignalHandlerOptions = SignalHandlerOptions.ALL) -> None:
    """Record ``options`` as the handlers installed (rclpy.init does this)."""
    global _current
    _current = SignalHandlerOptions(options)


def get_current_signal_handlers_options() -> SignalHandlerOptions:
    """The signal handlers rclpy would have installed now."""
    return _current


def uninstall_signal_handlers() -> None:
    """Record that no handler is installed (rclpy.shutdown does this)."""
    global _current
    _current = SignalHandlerOptions.NO
