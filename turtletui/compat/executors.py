"""``rclpy.executors``. Every executor runs callbacks one at a time in arrival
order on the host's simulated clock, which keeps runs deterministic."""

from __future__ import annotations

from typing import Any

from turtletui.compat.context import Context, get_default_context
from turtletui.compat.task import Future

_NS = 1_000_000_000


class ExternalShutdownException(Exception):
    """Raised by rclpy when the context is shut down while spinning."""


class ShutdownException(Exception):
    pass


class TimeoutException(Exception):
    pass


def _timeout_ns(timeout_sec: float | None) -> int | None:
    if timeout_sec is None or timeout_sec < 0:
        return None
    return int(timeout_sec * _NS)


class Executor:
    """Runs the callbacks of the nodes added to it."""

    def __init__(self, *, context: Context | None = None) -> None:
        self._context = context or get_default_context()
        self._nodes: list[Any] = []

    @property
    def context(self) -> Context:
        return self._context

    def add_node(self, node: Any) -> bool:
        if node in self._nodes:
            return False
        self._nodes.append(node)
        node.executor = self
        return True

    def remove_node(self, node: Any) -> None:
        if node in self._nodes:
            self._nodes.remove(node)

    def get_nodes(self) -> list[Any]:
        return list(self._nodes)

    def shutdown(self, timeout_sec: float | None = None) -> bool:
        self._nodes.clear()
        return True

    def __enter__(self) -> Executor:
        return self

    def __exit__(self, exc_type: Any, exc_val: Any, exc_tb: Any) -> None:
        self.shutdown()

    def _guard(self, what: str) -> Any:
        host = self._context.host
        if host.callback_depth:
            raise RuntimeError(
                f"{what} was called inside a callback: in ROS 2 this deadlocks, because the "
                "executor is busy running your callback and cannot deliver anything else. "
                "Use call_async() with add_done_callback(), or do the waiting in main()."
            )
        return host

    def spin(self) -> None:
        host = self._guard("spin()")
        context = self._context
        if context.ok():
            host.spin(lambda: not context.ok())

    def spin_once(self, timeout_sec: float | None = None) -> None:
        host = self._guard("spin_once()")
        if self._context.ok():
            host.spin_once(_timeout_ns(timeout_sec))

    def spin_until_future_complete(self, future: Future, timeout_sec: float | None = None) -> None:
        host = self._guard("spin_until_future_complete()")
        if not self._context.ok():
            return
        # As rclpy: a cancelled future is not done(), but ends the wait too.
        host.spin_until(lambda: future.done() or future.cancelled(), _timeout_ns(timeout_sec))

    def spin_once_until_future_complete(self, future: Future, timeout_sec: float | None = None) -> None:
        self.spin_once(timeout_sec)


class SingleThreadedExecutor(Executor):
    pass


class MultiThreadedExecutor(Executor):
    def __init__(self, num_threads: int | None = None, *, context: Context | None = None) -> None:
        super().__init__(context=context)
        self._num_threads = num_threads or 2

    def shutdown(self, timeout_sec: float | None = None, *, wait_for_threads: bool = True) -> bool:
        """``wait_for_threads`` is accepted and ignored: callbacks run on one thread here."""
        return super().shutdown(timeout_sec)


class EventsExecutor(SingleThreadedExecutor):
    pass


_global_executor: Executor | None = None


def get_global_executor() -> Executor:
    global _global_executor
    if _global_executor is None or _global_executor.context is not get_default_context():
        _global_executor = SingleThreadedExecutor()
    return _global_executor
