"""tf2_ros's BufferClient: transforms looked up by a tf2 buffer server over
the ``tf2_msgs/action/LookupTransform`` action, as tf2_ros_py's does it.

Each lookup sends a goal and blocks until the server answers, for at most
the goal's ``timeout`` plus ``timeout_padding`` (2 s) of clock time. Like
any blocking call it needs something else to deliver the answer: a thread
spinning the node, or a MultiThreadedExecutor's other threads; inside a
callback of a single-threaded executor, or with nothing spinning, it waits
the whole time and raises TimeoutException, as tf2_ros does. The server's
errors come back as tf2's exceptions; a server that gave up waiting for a
transform answers with no error and an empty transform, which the client
returns (ros2/geometry2#500)."""

from __future__ import annotations

import warnings
from typing import Any

from turtletui.compat.action import ActionClient
from turtletui.compat.executors import threads_that_can_help, wait_inside_callback
from turtletui.compat.tf2.buffer_interface import BufferInterface
from turtletui.compat.tf2.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from turtletui.compat.time import Duration, Time
from turtletui.interfaces.builtin_interfaces import Time as TimeMsg
from turtletui.interfaces.geometry_msgs import TransformStamped
from turtletui.interfaces.tf2_msgs import LookupTransform, TF2Error

_ERRORS = {
    TF2Error.LOOKUP_ERROR: LookupException,
    TF2Error.CONNECTIVITY_ERROR: ConnectivityException,
    TF2Error.EXTRAPOLATION_ERROR: ExtrapolationException,
    TF2Error.INVALID_ARGUMENT_ERROR: InvalidArgumentException,
    TF2Error.TIMEOUT_ERROR: TimeoutException,
}


class BufferClient(BufferInterface):
    """Lookups answered by the buffer server whose action is ``ns``
    (``tf2_buffer_server`` for tf2_ros's buffer_server)."""

    def __init__(
        self,
        node: Any,
        ns: str,
        check_frequency: float = 10.0,
        timeout_padding: Duration = Duration(seconds=2.0),  # noqa: B008 - tf2_ros's default
    ) -> None:
        BufferInterface.__init__(self)
        self.node = node
        self.action_client = ActionClient(node, LookupTransform, action_name=ns)
        self.check_frequency = check_frequency
        self.timeout_padding = timeout_padding

    def lookup_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Duration = Duration()
    ) -> TransformStamped:
        """The transform from ``source_frame`` into ``target_frame`` at ``time``
        (an rclpy Time; ``Time()`` for the latest), as the server has it
        within ``timeout``; raises tf2's exceptions."""
        if isinstance(time, TimeMsg):
            source_time = Time.from_msg(time)
            warnings.warn(
                "Passing a builtin_interfaces.msg.Time argument is deprecated, and will be removed in the near "
                "future. Use rclpy.time.Time instead.",
                stacklevel=2,
            )
        elif isinstance(time, Time):
            source_time = time
        else:
            raise TypeError("Must pass a rclpy.time.Time object.")
        goal = LookupTransform.Goal(
            target_frame=target_frame,
            source_frame=source_frame,
            source_time=source_time.to_msg(),
            timeout=timeout.to_msg(),
            advanced=False,
        )
        return self._process_goal(goal)

    def lookup_transform_full(
        self, target_frame: str, target_time: Time, source_frame: str, source_time: Time,
        fixed_frame: str, timeout: Duration = Duration(),
    ) -> TransformStamped:
        """``source_frame`` at ``source_time`` into ``target_frame`` at
        ``target_time``, through ``fixed_frame``."""
        goal = LookupTransform.Goal(
            target_frame=target_frame,
            source_frame=source_frame,
            source_time=source_time.to_msg(),
            timeout=timeout.to_msg(),
            target_time=target_time.to_msg(),
            fixed_frame=fixed_frame,
            advanced=True,
        )
        return self._process_goal(goal)

    def can_transform(
        self, target_frame: str, source_frame: str, time: Any, timeout: Duration = Duration()
    ) -> bool:
        """Whether lookup_transform succeeds (it is made)."""
        try:
            self.lookup_transform(target_frame, source_frame, time, timeout)
            return True
        except TransformException:
            return False

    def can_transform_full(
        self, target_frame: str, target_time: Time, source_frame: str, source_time: Time,
        fixed_frame: str, timeout: Duration = Duration(),
    ) -> bool:
        """Whether lookup_transform_full succeeds (it is made)."""
        try:
            self.lookup_transform_full(target_frame, target_time, source_frame, source_time, fixed_frame, timeout)
            return True
        except TransformException:
            return False

    def destroy(self) -> None:
        """Take the action client off the graph."""
        self.action_client.destroy()

    # -- internals --------------------------------------------------------------
    def _process_goal(self, goal: Any) -> TransformStamped:
        if not self.action_client.server_is_ready():
            raise TimeoutException("The BufferServer is not ready.")
        sent = self.action_client.send_goal_async(goal)
        limit = Duration.from_msg(goal.timeout) + self.timeout_padding
        self._wait(sent.done, max(limit.nanoseconds, 0))
        if not sent.done():
            raise TimeoutException(
                "The LookupTransform goal sent to the BufferServer did not come back in the specified time. "
                "Something is likely wrong with the server."
            )
        handle = sent.result()
        if not handle.accepted:
            raise TimeoutException(
                "The LookupTransform goal sent to the BufferServer did not come back with accepted status. "
                "Something is likely wrong with the server."
            )
        result = handle.get_result_async()
        self._wait(result.done, None)
        if not result.done():
            raise TimeoutException("The run ended before the BufferServer answered.")
        return _transform_or_raise(result.result().result)

    def _wait(self, done: Any, timeout_ns: int | None) -> None:
        """Block, as tf2_ros does, until ``done()`` or the timeout: only other
        threads (a spinning thread, a MultiThreadedExecutor's) can deliver."""
        node = self.node
        host = node.context.host
        if host.callback_depth > 0 and threads_that_can_help(node):
            wait_inside_callback(node, done, timeout_ns)
        else:
            host.spin_until(done, timeout_ns, callbacks=False)


def _transform_or_raise(result: Any) -> TransformStamped:
    """The server's transform, or its error as tf2's exception."""
    if result is None or result.error is None:
        raise TransformException(
            "The BufferServer returned None for result or result.error!  Something is likely wrong with the server."
        )
    code = result.error.error
    if code != TF2Error.NO_ERROR:
        raise _ERRORS.get(code, TransformException)(result.error.error_string)
    return result.transform
