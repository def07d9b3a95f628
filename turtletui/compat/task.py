"""``rclpy.task.Future``: the result of an asynchronous call."""

from __future__ import annotations

import inspect
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
        # Yields itself: the Task awaiting it resumes when it is done.
        while self._state == "PENDING":
            yield self
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


class Task(Future):
    """A coroutine (an ``async def`` callback) run by an executor: it runs
    until it awaits a Future that is not done, and goes on, in its callback
    group, once that Future is done. The Task is done when the coroutine
    returns (or raises)."""

    def __init__(self, handler: Any, args: tuple = (), kwargs: dict | None = None, *, executor: Any = None) -> None:
        super().__init__(executor=executor)
        self._handler = handler
        self._args = args
        self._kwargs = kwargs or {}
        self._resume: Callable[[], None] | None = None
        """How to run the next step later (queue it with the executor)."""

    def executing(self) -> bool:
        return False

    def __call__(self) -> None:
        """Run the task's next step; an exception from the handler is set on
        the task and raised, as rclpy's executor raises it from spin."""
        if self._state != "PENDING":
            return
        handler = self._handler
        if not inspect.iscoroutine(handler):
            try:
                result = handler(*self._args, **self._kwargs)
            except Exception as exc:
                self.set_exception(exc)
                raise
            if not inspect.iscoroutine(result):
                self.set_result(result)
                return
            self._handler = handler = result
        try:
            awaited = handler.send(None)
        except StopIteration as stop:
            self.set_result(stop.value)
            return
        except Exception as exc:
            self.set_exception(exc)
            raise
        if isinstance(awaited, Future) and self._resume is not None:
            awaited.add_done_callback(lambda _future: self._resume())
        elif self._resume is not None:
            self._resume()
