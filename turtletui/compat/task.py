"""``rclpy.task.Future``: the result of an asynchronous call."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class Future:
    """Represents the outcome of a task (a service call, an action goal...).

    As in rclpy, a cancelled future is ``cancelled()`` but not ``done()``."""

    def __init__(self, *, executor: Any = None) -> None:
        self._state = "PENDING"
        self._result: Any = None
        self._exception: BaseException | None = None
        self._callbacks: list[Callable[[Future], None]] = []

    def __await__(self):
        while self._state == "PENDING":
            yield
        return self.result()

    def cancel(self) -> None:
        """Request cancellation if the future is still pending."""
        if self._state == "PENDING":
            self._state = "CANCELLED"
            self._run_callbacks()

    def cancelled(self) -> bool:
        return self._state == "CANCELLED"

    def done(self) -> bool:
        """True once a result or an exception was set."""
        return self._state == "FINISHED"

    def result(self) -> Any:
        """The result, or None if not done yet; raises the task's exception."""
        if self._exception is not None:
            raise self._exception
        return self._result

    def exception(self) -> BaseException | None:
        return self._exception

    def set_result(self, result: Any) -> None:
        self._result = result
        self._state = "FINISHED"
        self._run_callbacks()

    def set_exception(self, exception: BaseException) -> None:
        self._exception = exception
        self._state = "FINISHED"
        self._run_callbacks()

    def add_done_callback(self, callback: Callable[[Future], None]) -> None:
        """Call ``callback(future)`` when done (at once if it already is, or was cancelled)."""
        if self._state != "PENDING":
            callback(self)
        else:
            self._callbacks.append(callback)

    def remove_done_callback(self, callback: Callable[[Future], None]) -> bool:
        """Remove a callback added earlier; False if it is not (or no longer) waiting."""
        try:
            self._callbacks.remove(callback)
        except ValueError:
            return False
        return True

    def _run_callbacks(self) -> None:
        callbacks, self._callbacks = self._callbacks, []
        for callback in callbacks:
            callback(self)
