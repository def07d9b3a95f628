"""``rclpy.action.ActionServer``: goals from the graph, run in the node's executor.

As in rclpy 9: a goal request runs the goal callback (accept or reject), an
accepted goal's handle goes to the handle-accepted callback (by default
``goal_handle.execute()``), and ``execute()`` queues the execute callback as
a task of the executor. The goal's result is sent when that callback
returns. Goal, cancel and execute callbacks may be ``async def``. The goal
state machine is rcl_action's: an invalid transition raises RCLError.
"""

from __future__ import annotations

import inspect
import sys
import traceback
from collections.abc import Callable
from enum import Enum
from pathlib import Path
from typing import Any

from turtletui.compat.action import GoalStatus, goal_uuid
from turtletui.compat.callback_groups import ReentrantCallbackGroup
from turtletui.compat.destroyable import Destroyable
from turtletui.compat.dispatch import dispatcher, start_task
from turtletui.compat.executors import await_or_execute
from turtletui.compat.identity import as_rclpy
from turtletui.compat.qos import (
    QoSProfile,
    qos_profile_action_status_default,
    qos_profile_services_default,
)
from turtletui.compat.rcl_error import RCLError
from turtletui.graph import core
from turtletui.interfaces import copier, interface_name


class GoalResponse(Enum):
    """What a goal callback answers."""

    REJECT = 1
    ACCEPT = 2


class CancelResponse(Enum):
    """What a cancel callback answers."""

    REJECT = 1
    ACCEPT = 2


class GoalEvent(Enum):
    """The events of rcl_action's goal state machine."""

    EXECUTE = 0
    CANCEL_GOAL = 1
    SUCCEED = 2
    ABORT = 3
    CANCELED = 4


_S = GoalStatus
_TRANSITIONS = {
    GoalEvent.EXECUTE: ((_S.STATUS_ACCEPTED,), _S.STATUS_EXECUTING),
    GoalEvent.CANCEL_GOAL: ((_S.STATUS_ACCEPTED, _S.STATUS_EXECUTING), _S.STATUS_CANCELING),
    GoalEvent.SUCCEED: ((_S.STATUS_EXECUTING, _S.STATUS_CANCELING), _S.STATUS_SUCCEEDED),
    GoalEvent.ABORT: ((_S.STATUS_EXECUTING, _S.STATUS_CANCELING), _S.STATUS_ABORTED),
    GoalEvent.CANCELED: ((_S.STATUS_CANCELING,), _S.STATUS_CANCELED),
}
"""event: (the states it may happen in, the state it leads to), as rcl_action's goal_state_machine.c."""
_STATE_NAMES = {
    _S.STATUS_ACCEPTED: "ACCEPTED",
    _S.STATUS_EXECUTING: "EXECUTING",
    _S.STATUS_CANCELING: "CANCELING",
    _S.STATUS_SUCCEEDED: "SUCCEEDED",
    _S.STATUS_CANCELED: "CANCELED",
    _S.STATUS_ABORTED: "ABORTED",
}
_GRAPH_STATUS = {
    _S.STATUS_ACCEPTED: "accepted",
    _S.STATUS_EXECUTING: "executing",
    _S.STATUS_CANCELING: "canceling",
    _S.STATUS_SUCCEEDED: "succeeded",
    _S.STATUS_CANCELED: "canceled",
    _S.STATUS_ABORTED: "aborted",
}
_ACTIVE = (_S.STATUS_ACCEPTED, _S.STATUS_EXECUTING, _S.STATUS_CANCELING)


class ServerGoalHandle:
    """The server's handle of one accepted goal (made by the ActionServer only)."""

    def __init__(self, action_server: ActionServer, record: core.GoalHandle, goal_request: Any) -> None:
        self._action_server = action_server
        self._record = record
        self._goal_request = goal_request
        self._goal_id = goal_uuid(record.goal_id)
        self._status = _S.STATUS_ACCEPTED
        self._destroyed = False

    def __eq__(self, other: object) -> bool:
        if isinstance(other, ServerGoalHandle):
            return self.goal_id == other.goal_id
        return NotImplemented

    def __ne__(self, other: object) -> bool:
        equal = self.__eq__(other)
        return equal if equal is NotImplemented else not equal

    __hash__ = None  # type: ignore[assignment]  # as rclpy's: compared by goal id

    @property
    def request(self) -> Any:
        """The goal message the client sent."""
        return self._goal_request

    @property
    def goal_id(self) -> Any:
        """The goal's unique_identifier_msgs/UUID."""
        return self._goal_id

    @property
    def is_active(self) -> bool:
        return not self._destroyed and self._status in _ACTIVE

    @property
    def is_cancel_requested(self) -> bool:
        return self.status == _S.STATUS_CANCELING

    @property
    def status(self) -> int:
        """A GoalStatus number (STATUS_UNKNOWN once destroyed)."""
        return _S.STATUS_UNKNOWN if self._destroyed else self._status

    def _update_state(self, event: GoalEvent) -> None:
        if self._destroyed:
            return
        allowed, new = _TRANSITIONS[event]
        if self._status not in allowed:
            raise RCLError(
                "Failed to update goal state: goal_handle attempted invalid transition from state "
                f"{_STATE_NAMES[self._status]} with event {event.name}"
            )
        self._status = new
        if new in (_S.STATUS_EXECUTING, _S.STATUS_CANCELING):
            self._record.set_status(_GRAPH_STATUS[new])  # the result goes when execute returns

    def execute(self, execute_callback: Callable[[ServerGoalHandle], Any] | None = None) -> None:
        """Run ``execute_callback`` (the server's by default) for this goal, as a task of the executor."""
        # A goal canceled before it executes stays CANCELING: its callback still runs.
        if not self.is_cancel_requested:
            self._update_state(GoalEvent.EXECUTE)
        self._action_server._notify_execute(self, execute_callback)

    def publish_feedback(self, feedback: Any) -> None:
        """Send ``feedback`` (an ``action_type.Feedback``) to the client."""
        if not isinstance(feedback, self._action_server.action_type.Feedback):
            raise TypeError(
                f"publish_feedback() on {self._action_server._name} expects a "
                f"{interface_name(self._action_server.action_type)}.Feedback, got {feedback!r}"
            )
        if not self._destroyed:
            # sent as it is now, as rclpy serialises it: the callback may change it next
            self._record.publish_feedback(copier(type(feedback))(feedback))

    def succeed(self) -> None:
        self._update_state(GoalEvent.SUCCEED)

    def abort(self) -> None:
        self._update_state(GoalEvent.ABORT)

    def canceled(self) -> None:
        self._update_state(GoalEvent.CANCELED)

    def destroy(self) -> None:
        self._destroyed = True


def default_handle_accepted_callback(goal_handle: ServerGoalHandle) -> None:
    """Execute the goal."""
    goal_handle.execute()


def default_goal_callback(goal_request: Any) -> GoalResponse:
    """Accept all goals."""
    return GoalResponse.ACCEPT


def default_cancel_callback(cancel_request: Any) -> CancelResponse:
    """No cancellations."""
    return CancelResponse.REJECT


class ActionServer(Destroyable):
    """Serves an action to the graph's clients, as ``rclpy.action.ActionServer``."""

    def __init__(
        self,
        node: Any,
        action_type: Any,
        action_name: str,
        execute_callback: Callable[[ServerGoalHandle], Any],
        *,
        callback_group: Any = None,
        goal_callback: Callable[[Any], Any] = default_goal_callback,
        handle_accepted_callback: Callable[[ServerGoalHandle], Any] = default_handle_accepted_callback,
        cancel_callback: Callable[[Any], Any] = default_cancel_callback,
        goal_service_qos_profile: QoSProfile = qos_profile_services_default,
        result_service_qos_profile: QoSProfile = qos_profile_services_default,
        cancel_service_qos_profile: QoSProfile = qos_profile_services_default,
        feedback_pub_qos_profile: QoSProfile = QoSProfile(depth=10),  # noqa: B008 - as rclpy's
        status_pub_qos_profile: QoSProfile = qos_profile_action_status_default,
        result_timeout: int = 10,
    ) -> None:
        """The QoS profiles and ``result_timeout`` are accepted and ignored (results
        reach their client when the goal ends); graph queries report the
        server's hidden endpoints with rclpy's default profiles."""
        if not all(hasattr(action_type, part) for part in ("Goal", "Result", "Feedback")):
            raise TypeError(
                f"ActionServer needs an action class such as turtlesim.action.RotateAbsolute, got {action_type!r}"
            )
        node._require_alive()
        self.register_handle_accepted_callback(handle_accepted_callback)
        self.register_goal_callback(goal_callback)
        self.register_cancel_callback(cancel_callback)
        self.register_execute_callback(execute_callback)
        self._node = node
        self._action_type = action_type
        self._name = node._resolve(action_name)
        self._group = node._group(callback_group)
        self._logger = node.get_logger().get_child("action_server")
        host = node.context.host
        self._goal_handles: dict[int, ServerGoalHandle] = {}
        self._decide_cancel = dispatcher(host, self._group, self._execute_cancel_request, node=node)
        self._record = node._graph.add_action_server(
            node._record,
            self._name,
            action_type,
            dispatcher(host, self._group, self._execute_goal_request, node=node),
            answers=True,
        )
        node._entities.append(self)  # destroyed with the node

    @property
    def action_type(self) -> Any:
        return self._action_type

    # -- what rclpy lets one replace ------------------------------------------------
    def register_handle_accepted_callback(self, handle_accepted_callback: Callable | None) -> None:
        self._handle_accepted_callback = handle_accepted_callback or default_handle_accepted_callback

    def register_goal_callback(self, goal_callback: Callable | None) -> None:
        self._goal_callback = goal_callback or default_goal_callback

    def register_cancel_callback(self, cancel_callback: Callable | None) -> None:
        self._cancel_callback = cancel_callback or default_cancel_callback

    def register_execute_callback(self, execute_callback: Callable) -> None:
        if not callable(execute_callback):
            raise TypeError("Failed to register goal execution callback: not callable")
        self._execute_callback = execute_callback

    # -- the protocol ------------------------------------------------------------------
    async def _execute_goal_request(self, record: core.GoalHandle) -> None:
        response = await await_or_execute(self._goal_callback, record.goal)
        if not isinstance(response, GoalResponse):
            self._logger.warning("Goal request callback did not return a GoalResponse type. Rejecting goal.")
        if response is not GoalResponse.ACCEPT or self._destroyed:
            record.reject()
            return
        goal_handle = ServerGoalHandle(self, record, record.goal)
        self._goal_handles[record.goal_id] = goal_handle
        record.decide_cancel = lambda decided: self._decide_cancel(goal_handle, decided)
        accepted = self._handle_accepted_callback
        if inspect.iscoroutinefunction(accepted):
            self._answer(record, goal_handle)
            await accepted(goal_handle)
            return
        try:
            # The answer goes after what the callback queued (the execute task):
            # rclpy's executor runs its tasks before it takes the client's reply.
            accepted(goal_handle)
        finally:
            self._answer(record, goal_handle)

    @staticmethod
    def _answer(record: core.GoalHandle, goal_handle: ServerGoalHandle) -> None:
        executing = goal_handle._status == _S.STATUS_EXECUTING
        record.accept("executing" if executing else "accepted")

    def _notify_execute(self, goal_handle: ServerGoalHandle, execute_callback: Callable | None) -> None:
        callback = execute_callback or self._execute_callback
        host = self._node.context.host
        # As rclpy's executor.create_task: a task outside any callback group, which
        # the executor runs before the callbacks ready meanwhile (other goal requests)
        start_task(host, ReentrantCallbackGroup(), self._execute_goal, (callback, goal_handle), now=False, first=True)

    async def _execute_goal(self, execute_callback: Callable, goal_handle: ServerGoalHandle) -> None:
        try:
            result = await await_or_execute(execute_callback, goal_handle)
        except Exception as ex:  # noqa: BLE001 - as rclpy: logged, and the goal aborted
            result = self._action_type.Result()
            self._logger.error(f"Error raised in execute callback: {ex}")
            _print_user_traceback(ex)
        if goal_handle.is_active:
            self._logger.warning(f"Goal state not set, assuming aborted. Goal ID: {goal_handle.goal_id.uuid}")
            goal_handle.abort()
        if not isinstance(result, self._action_type.Result):
            raise TypeError(
                f"the execute callback of action {self._name} must return a "
                f"{interface_name(self._action_type)}.Result, got {result!r}"
            )
        goal_handle._record.finish(_GRAPH_STATUS.get(goal_handle._status, "aborted"), copier(type(result))(result))

    async def _execute_cancel_request(
        self, goal_handle: ServerGoalHandle, decided: Callable[..., None]
    ) -> None:
        response = await await_or_execute(self._cancel_callback, goal_handle)
        accepted = response == CancelResponse.ACCEPT
        if accepted:
            try:
                goal_handle._update_state(GoalEvent.CANCEL_GOAL)
            except RCLError:
                accepted = False  # it ended meanwhile
        # rclpy answers a refused request with ERROR_NONE and no goal canceling
        decided(accepted, core.CANCEL_ACCEPTED)

    def destroy(self) -> None:
        """Take the server off the graph; its goals' handles are destroyed."""
        if self._destroyed:
            return
        self._destroyed = True
        for goal_handle in self._goal_handles.values():
            goal_handle.destroy()
        self._node._graph.remove_action_server(self._record)
        if self in self._node._entities:
            self._node._entities.remove(self)


_COMPAT_ROOT = str(Path(__file__).resolve().parents[1])


def _print_user_traceback(exc: BaseException) -> None:
    """What rclpy's ``traceback.print_exc()`` shows, without turtletui's own frames."""
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if not f.filename.startswith(_COMPAT_ROOT)]
    lines = ["Traceback (most recent call last):\n", *traceback.format_list(frames)]
    lines += traceback.format_exception_only(type(exc), exc)
    sys.stderr.write("".join(lines))

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.action.server", ActionServer, ServerGoalHandle, GoalResponse, CancelResponse)
