"""tf2_ros's Buffer: BufferCore plus waiting for transforms, blocking or as futures.

A blocking wait (a ``timeout`` other than zero) lasts in simulated time and,
as in tf2_ros, spins nothing itself: new transforms reach the buffer only if
something else runs the TransformListener's callbacks meanwhile (a
MultiThreadedExecutor's other threads, the listener's ``spin_thread``).
Inside a callback of a single-threaded executor the wait therefore runs to
its timeout and the lookup then fails, as it does on a real system."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from turtletui.compat.executors import threads_that_can_help, wait_inside_callback
from turtletui.compat.task import Future
from turtletui.compat.tf2.buffer_core import BufferCore
from turtletui.compat.tf2.buffer_interface import BufferInterface
from turtletui.compat.time import Clock, Duration
from turtletui.interfaces.geometry_msgs import TransformStamped
from turtletui.interfaces.tf2_msgs import FrameGraph


class Buffer(BufferCore, BufferInterface):
    """Transforms of the last ``cache_time`` (10 s by default); with ``node``,
    also the ``tf2_frames`` service that answers with all_frames_as_yaml()."""

    def __init__(self, cache_time: Duration | None = None, node: Any = None) -> None:
        BufferCore.__init__(self, cache_time)
        BufferInterface.__init__(self)
        self._new_data_callbacks: list[Callable[[], None]] = []
        self._callbacks_to_remove: list[Callable[[], None]] = []
        self._callbacks_lock = threading.RLock()
        self._node = node
        if node is not None:
            self.srv = node.create_service(FrameGraph, "tf2_frames", self._get_frames)
            self.clock = node.get_clock()
        else:
            self.clock = Clock()

    def _get_frames(self, request: Any, response: Any) -> Any:
        return FrameGraph.Response(frame_yaml=self.all_frames_as_yaml())

    def set_transform(self, transform: TransformStamped, authority: str) -> None:
        super().set_transform(transform, authority)
        self._call_new_data_callbacks()

    def set_transform_static(self, transform: TransformStamped, authority: str) -> None:
        super().set_transform_static(transform, authority)
        self._call_new_data_callbacks()

    def _call_new_data_callbacks(self) -> None:
        with self._callbacks_lock:
            for callback in list(self._new_data_callbacks):
                callback()
            for callback in self._callbacks_to_remove:
                if callback in self._new_data_callbacks:
                    self._new_data_callbacks.remove(callback)
            self._callbacks_to_remove.clear()

    def _remove_callback(self, callback: Callable[[], None]) -> None:
        with self._callbacks_lock:
            self._callbacks_to_remove.append(callback)

    # -- blocking -----------------------------------------------------------

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Duration = Duration()
    ) -> TransformStamped:
        """The transform from ``source_frame`` into ``target_frame`` at ``time``
        (``Time()``: the latest), waiting up to ``timeout`` for it; raises
        LookupException, ConnectivityException or ExtrapolationException."""
        self.can_transform(target_frame, source_frame, time, timeout)
        return self.lookup_transform_core(target_frame, source_frame, time)

    def lookup_transform_full(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any,
        fixed_frame: str, timeout: Duration = Duration(),
    ) -> TransformStamped:
        """``source_frame`` at ``source_time`` into ``target_frame`` at ``target_time``, through
        ``fixed_frame`` (the frame that stays put between the two times)."""
        self.can_transform_full(target_frame, target_time, source_frame, source_time, fixed_frame, timeout)
        return self.lookup_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame)

    def can_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Duration = Duration(),
        return_debug_tuple: bool = False,
    ) -> Any:
        """Whether the transform is available, waiting up to ``timeout`` for it;
        ``(bool, why not)`` with ``return_debug_tuple``."""
        def ready() -> bool:
            return self.can_transform_core(target_frame, source_frame, time)[0]

        self._wait(ready, timeout)
        result = self.can_transform_core(target_frame, source_frame, time)
        return result if return_debug_tuple else result[0]

    def can_transform_full(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any,
        fixed_frame: str, timeout: Duration = Duration(), return_debug_tuple: bool = False,
    ) -> Any:
        """can_transform for lookup_transform_full."""
        def ready() -> bool:
            return self.can_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame)[0]

        self._wait(ready, timeout)
        result = self.can_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame)
        return result if return_debug_tuple else result[0]

    def _wait(self, ready: Callable[[], bool], timeout: Duration) -> None:
        if not hasattr(timeout, "nanoseconds"):
            raise TypeError(
                f"timeout must be an rclpy.duration.Duration, got {timeout!r} "
                "(e.g. timeout=rclpy.duration.Duration(seconds=1.0))"
            )
        timeout_ns = timeout.nanoseconds
        if timeout_ns <= 0 or ready():
            return
        node = self._node
        if node is not None and threads_that_can_help(node):
            wait_inside_callback(node, ready, timeout_ns)
            return
        from turtletui.compat.context import get_default_context

        context = node.context if node is not None else get_default_context()
        if context.ok():
            context.host.spin_until(ready, timeout_ns, callbacks=False)

    # -- futures ------------------------------------------------------------

    def wait_for_transform_async(self, target_frame: str, source_frame: str, time: Any) -> Future:
        """A future that gets the transform once it is available."""
        return self._when_available(
            lambda: self.can_transform_core(target_frame, source_frame, time)[0],
            lambda: self.lookup_transform(target_frame, source_frame, time),
        )

    def wait_for_transform_full_async(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> Future:
        """wait_for_transform_async for lookup_transform_full."""
        return self._when_available(
            lambda: self.can_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame)[0],
            lambda: self.lookup_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame),
        )

    async def lookup_transform_async(self, target_frame: str, source_frame: str, time: Any) -> TransformStamped:
        """lookup_transform as a coroutine: awaits the transform, never fails for want of it."""
        await self.wait_for_transform_async(target_frame, source_frame, time)
        return self.lookup_transform_core(target_frame, source_frame, time)

    async def lookup_transform_full_async(
        self, target_frame: str, target_time: Any, source_frame: str, source_time: Any, fixed_frame: str
    ) -> TransformStamped:
        """lookup_transform_full as a coroutine."""
        await self.wait_for_transform_full_async(target_frame, target_time, source_frame, source_time, fixed_frame)
        return self.lookup_transform_full_core(target_frame, target_time, source_frame, source_time, fixed_frame)

    def _when_available(self, possible: Callable[[], bool], lookup: Callable[[], TransformStamped]) -> Future:
        future = Future()
        if possible():
            future.set_result(lookup())
            return future

        def on_new_data() -> None:
            try:
                if possible():
                    future.set_result(lookup())
            except BaseException as err:  # noqa: BLE001 - the future carries it, as tf2_ros's
                future.set_exception(err)

        self._new_data_callbacks.append(on_new_data)
        future.add_done_callback(lambda _: self._remove_callback(on_new_data))
        return future
