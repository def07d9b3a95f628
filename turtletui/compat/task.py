"""``rclpy.task.Future``: the result of an asynchronous call."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class Future:
    """Represents the outcome of a task (a service call, an action goal...)."""

    def __init__(self, *, executor: Any = None) -> None:
        self._state = "PENDING"
        self._result: Any = None
        self._exception: BaseException | None = None
        self._callbacks: list[Callable[[Future], None]] = []

    def __await__(self):
        while not self.done():
            yield
        return self.result()

    def cancel(self) -> None:
        if not self.done():
            self._state = "CANCELLED"
            self._run_callbacks()

    def cancelled(self) -> bool:
        return self._state == "CANCELLED"

    def done(self) -> bool:
        return self._state != "PENDING"

    def result(self) -> Any:
        """The result, or None if not done yet; raises the task's exception."""
        if self._exception is not None:
            raise self._exception
        return self._result

    def exception(self) -> BaseException | None:
        return self._exception

    def set_result(self, result: Any) -> None:
        self._state = "FINISHED"
        self._result = result
        self._run_callbacks()

    def set_exception(self, exception: BaseException) -> None:
        self._state = "FINISHED"
        self._exception = exception
        self._run_callbacks()

    def add_done_callback(self, callback: Callable[[Future], None]) -> None:
        """Call ``callback(future)`` when done (at once if it already is)."""
        if self.done():
            callback(self)
        else:
            self._callbacks.append(callback)

    def _run_callbacks(self) -> None:
        callbacks, self._callbacks = self._callbacks, []
        for callback in callbacks:
            callback(self)
