"""``rclpy.task.Future``: the result of an asynchronous call."""

from __future__ import annotations

import inspect
import threading
import warnings
from collections.abc import Callable
from typing import Any

from turtletui.compat.identity import as_rclpy

_awaiting = threading.local()
"""The Future a coroutine step stopped at, per thread: rclpy's ``__await__`` yields None,
so the Task learns what its coroutine waits for here rather than from the yielded value."""


class Future:
    """Represents the outcome of a task (a service call, an action goal...).

    As in rclpy, a cancelled future is ``cancelled()`` but not ``done()``, and
    its done callbacks run as tasks of its executor (the one that made it, or
    that took a service's response for it), on a later spin, or at once when it
    has none."""

    __module__ = "rclpy.task"  # as it prints in rclpy

    def __init__(self, *, executor: Any = None) -> None:
        self._state = "PENDING"
        self._result: Any = None
        self._exception: BaseException | None = None
        self._callbacks: list[Callable[[Future], None]] = []
        self._hooks: list[Callable[[Future], None]] = []
        """turtletui's own callbacks (a task resuming, a group released): run at once."""
        self._executor = executor
        self._client: Any = None
        """For a service call's future, the rclpy Client that made it
        (Executor.spin_until_future_complete asks it whether its response
        could be handled while a callback waits)."""

    def __await__(self):
        # Yields None, as rclpy's does (a coroutine driven by hand sees it); the
        # Task awaiting it finds it in _awaiting and resumes when it is done.
        while self._state == "PENDING":
            _awaiting.future = self
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
        """Call ``callback(future)`` when done; if it already is (or was cancelled), as a task
        of the future's executor, or at once without one."""
        if self._state == "PENDING":
            self._callbacks.append(callback)
        elif self._executor is not None:
            self._executor.create_task(callback, self)
        else:
            callback(self)

    def _add_done_hook(self, hook: Callable[[Future], None]) -> None:
        """Call ``hook(future)`` as soon as it is done (at once if it is)."""
        if self._state == "PENDING":
            self._hooks.append(hook)
        else:
            hook(self)

    def _set_executor(self, executor: Any) -> None:
        self._executor = executor

    def remove_done_callback(self, callback: Callable[[Future], None]) -> bool:
        """Remove a callback added earlier; False if it is not (or no longer) waiting."""
        try:
            self._callbacks.remove(callback)
        except ValueError:
            return False
        return True

    def _run_callbacks(self) -> None:
        hooks, self._hooks = self._hooks, []
        for hook in hooks:
            hook(self)
        callbacks, self._callbacks = self._callbacks, []
        if self._executor is not None:
            for callback in callbacks:
                self._executor.create_task(callback, self)
            return
        for callback in callbacks:
            try:
                callback(self)
            except Exception as err:  # noqa: BLE001 - rclpy warns and runs the other callbacks
                warnings.warn(f"Unhandled exception in done callback: {err}", stacklevel=2)


class Task(Future):
    """A coroutine (an ``async def`` callback) run by an executor: it runs
    until it awaits a Future that is not done, and goes on, in its callback
    group, once that Future is done. The Task is done when the coroutine
    returns (or raises)."""

    _raises = True
    """Whether calling the task raises its handler's error after keeping it: turtletui's
    executors run a task to raise it from spin; one a program runs itself (a handler of
    Executor.wait_for_ready_callbacks) only keeps it, as rclpy's Task does."""

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
                if self._raises:
                    raise
                return
            if not inspect.iscoroutine(result):
                self.set_result(result)
                return
            self._handler = handler = result
        _awaiting.future = None
        try:
            handler.send(None)
        except StopIteration as stop:
            self.set_result(stop.value)
            return
        except Exception as exc:
            self.set_exception(exc)
            if self._raises:
                raise
            return
        finally:
            awaited, _awaiting.future = _awaiting.future, None
        if isinstance(awaited, Future) and self._resume is not None:
            awaited._add_done_hook(lambda _future: self._resume())
        elif self._resume is not None:
            self._resume()


as_rclpy("rclpy.task", Task)  # as rclpy's prints (Future names itself in its body)
