"""``rclpy.action.ActionClient``: goals, feedback and results over the graph."""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import Any

from turtletui.compat.destroyable import Destroyable
from turtletui.compat.identity import as_rclpy
from turtletui.compat.node import wait_for_server
from turtletui.compat.qos import (
    QoSProfile,
    qos_profile_action_status_default,
    qos_profile_services_default,
)
from turtletui.compat.task import Future
from turtletui.graph.logs import WARN
from turtletui.interfaces import copier
from turtletui.interfaces.action_msgs import GoalStatus
from turtletui.messages import LOST_GOAL_ADVICE

_NS = 1_000_000_000


_STATUS = {
    "accepted": GoalStatus.STATUS_ACCEPTED,
    "executing": GoalStatus.STATUS_EXECUTING,
    "canceling": GoalStatus.STATUS_CANCELING,
    "succeeded": GoalStatus.STATUS_SUCCEEDED,
    "canceled": GoalStatus.STATUS_CANCELED,
    "aborted": GoalStatus.STATUS_ABORTED,
}
_UNDISCOVERED_ACTION = (
    "{node} sent a goal to {action} before it had discovered the action's server, so the goal was lost "
    "and will never be answered: ROS 2 nodes take a moment to discover each other, here and on a real "
    "robot. " + LOST_GOAL_ADVICE
)
_ERROR_UNKNOWN_GOAL_ID = 2
"""action_msgs/srv/CancelGoal's code for a goal the server does not know (a rejected one)."""


def goal_uuid(goal_id: int) -> Any:
    """The unique_identifier_msgs/UUID of the graph's goal ``goal_id``: the same
    on the client's and the server's side, and in every run."""
    from turtletui.interfaces.unique_identifier_msgs import UUID

    return UUID(uuid=list(random.Random(goal_id).randbytes(16)))


class ClientGoalHandle:
    """The client's view of one goal."""

    def __init__(self, client: ActionClient, record: Any) -> None:
        self._client = client
        self._record = record
        """The graph's handle of the goal (the child's stand-in when sandboxed)."""
        self._accepted = False
        self._status = GoalStatus.STATUS_UNKNOWN
        self._result_future = Future()

    def __eq__(self, other: object) -> bool:
        if isinstance(other, ClientGoalHandle):
            return self.goal_id == other.goal_id
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]  # as rclpy's: compared by goal id

    def __repr__(self) -> str:
        return f"ClientGoalHandle <id={self.goal_id.uuid}, accepted={self._accepted}, status={self._status}>"

    @property
    def accepted(self) -> bool:
        return self._accepted

    @property
    def status(self) -> int:
        """The goal's GoalStatus number, as the server last reported it."""
        return self._status

    @property
    def goal_id(self) -> Any:
        """The goal's unique_identifier_msgs/UUID."""
        return goal_uuid(self._record.goal_id if self._record is not None else 0)

    def get_result_async(self) -> Future:
        """A Future of the result response (``.status``, ``.result``)."""
        if not self._accepted:
            raise TypeError("Goal was not accepted")
        return self._result_future

    def get_result(self) -> Any:
        """Wait for the result response. Never inside a callback: ROS deadlocks."""
        future = self.get_result_async()
        self._client._host().spin_until(future.done, None)
        return future.result()

    def cancel_goal_async(self) -> Future:
        """Ask the server to cancel the goal; a Future of its CancelGoal response."""
        from turtletui.interfaces.action_msgs import CancelGoal, GoalInfo

        future = Future()
        host = self._client._host()
        goal_id = self.goal_id

        def answered(code: int, canceling: bool) -> None:
            canceled = [GoalInfo(goal_id=goal_id)] if canceling else []
            future.set_result(CancelGoal.Response(return_code=code, goals_canceling=canceled))

        if self._accepted:
            host.graph.cancel_goal(self._record, host.owner, host.wrap_callback(answered))
        else:
            future.set_result(CancelGoal.Response(return_code=_ERROR_UNKNOWN_GOAL_ID))
        return future

    def cancel_goal(self) -> Any:
        """Cancel and wait for the server's answer. Never inside a callback: ROS deadlocks."""
        future = self.cancel_goal_async()
        self._client._host().spin_until(future.done, None)
        return future.result()

    def _answered(self, record: Any) -> None:
        if record is not None:
            self._record = record
            self._accepted = True
            self._status = _STATUS.get(record.status, GoalStatus.STATUS_ACCEPTED)

    def _status_changed(self, status: str) -> None:
        self._status = _STATUS.get(status, self._status)

    def _finished(self, status: str, result: Any) -> None:
        self._status = _STATUS.get(status, GoalStatus.STATUS_UNKNOWN)
        response = self._client._action_type.Impl.GetResultService.Response(status=self._status, result=result)
        self._result_future.set_result(response)


class ActionClient(Destroyable):
    """Sends goals to an action server, as ``rclpy.action.ActionClient``."""

    def __init__(
        self,
        node: Any,
        action_type: Any,
        action_name: str,
        *,
        callback_group: Any = None,
        goal_service_qos_profile: QoSProfile = qos_profile_services_default,
        result_service_qos_profile: QoSProfile = qos_profile_services_default,
        cancel_service_qos_profile: QoSProfile = qos_profile_services_default,
        feedback_sub_qos_profile: QoSProfile = QoSProfile(depth=10),  # noqa: B008 - as rclpy's
        status_sub_qos_profile: QoSProfile = qos_profile_action_status_default,
    ) -> None:
        """The callback group and QoS profiles are accepted and ignored (as for topics, only
        delivery order matters in the simulation); graph queries report the
        client's hidden endpoints with rclpy's default profiles."""
        if not all(hasattr(action_type, part) for part in ("Goal", "Result", "Feedback")):
            raise TypeError(
                f"ActionClient needs an action class such as turtlesim.action.RotateAbsolute, got {action_type!r}"
            )
        node._require_alive()
        self._node = node
        self._action_type = action_type
        self._action_name = node._resolve(action_name)
        self._record = node._graph.add_action_client(node._record, self._action_name, action_type)
        self._told_undiscovered = False
        node._entities.append(self)  # destroyed with the node

    def _host(self) -> Any:
        return self._node.context.host

    def server_is_ready(self) -> bool:
        """Whether the action's server exists and this client has discovered it."""
        self._require_alive()
        return self._node._graph.action_matched(self._record)

    def wait_for_server(self, timeout_sec: float | None = None) -> bool:
        """Wait (in simulated time) until the server exists and this client has
        discovered it; False on timeout."""
        graph = self._node._graph
        return wait_for_server(
            self._host(), self._record, lambda: graph.action_servers.get(self._action_name),
            self.server_is_ready, timeout_sec,
        )

    def send_goal_async(
        self, goal: Any, feedback_callback: Callable[[Any], None] | None = None, goal_uuid: Any = None
    ) -> Future:
        """Send ``goal``; the Future completes with a ClientGoalHandle (``accepted``
        False if the server rejected it). ``goal_uuid`` is accepted and ignored:
        the graph numbers goals, so that runs repeat."""
        self._require_alive()
        if type(goal) is not self._action_type.Goal:
            raise TypeError(f"send_goal_async() on {self._action_name} expects a Goal of {self._action_type}, got {goal!r}")
        future = Future()
        host = self._host()
        graph = host.graph
        if self._action_name in graph.action_servers and not graph.action_matched(self._record):
            self._tell_goal_lost()  # and never answered, as in ROS 2
            return future
        handle = ClientGoalHandle(self, None)
        feedback_type = self._action_type.Impl.FeedbackMessage

        def on_answer(record: Any) -> None:
            handle._answered(record)
            future.set_result(handle)

        def on_feedback(feedback: Any) -> None:
            if feedback_callback is not None:
                feedback_callback(feedback_type(goal_id=handle.goal_id, feedback=feedback))

        handle._record = host.graph.send_goal(
            self._action_name,
            copier(type(goal))(goal),  # as sent: the caller may change its goal next
            host.owner,
            host.wrap_callback(on_answer),
            host.wrap_callback(on_feedback),
            host.wrap_callback(handle._finished),
            host.wrap_callback(handle._status_changed),
        )
        return future

    def _tell_goal_lost(self) -> None:
        if not self._told_undiscovered:
            self._told_undiscovered = True
            node = self._node.get_fully_qualified_name()
            self._node._graph.log("turtletui", WARN, _UNDISCOVERED_ACTION.format(node=node, action=self._action_name))

    def send_goal(self, goal: Any, **kwargs: Any) -> Any:
        """Send ``goal`` and wait for its result; ``kwargs`` are send_goal_async's
        (``feedback_callback``, ``goal_uuid``). None if the server rejected it.
        Never inside a callback: ROS deadlocks."""
        future = self.send_goal_async(goal, **kwargs)
        self._host().spin_until(future.done, None)
        handle = future.result()
        return handle.get_result() if handle is not None and handle.accepted else None

    def destroy(self) -> None:
        """Take the client off the graph; using it afterwards raises InvalidHandle."""
        if self._destroyed:
            return
        self._destroyed = True
        self._node._graph.remove_action_client(self._record)
        if self in self._node._entities:
            self._node._entities.remove(self)


def get_action_names_and_types(node: Any) -> list[tuple[str, list[str]]]:
    """Every action with a server or a client in the graph, with its type."""
    node._require_alive()
    return node._graph.action_names_and_types()


def get_action_server_names_and_types_by_node(
    node: Any, remote_node_name: str, remote_node_namespace: str
) -> list[tuple[str, list[str]]]:
    """The actions the node ``remote_node_namespace/remote_node_name`` serves."""
    return node._names_and_types_by_node(remote_node_name, remote_node_namespace, "action_servers", "action server")


def get_action_client_names_and_types_by_node(
    node: Any, remote_node_name: str, remote_node_namespace: str
) -> list[tuple[str, list[str]]]:
    """The actions the node ``remote_node_namespace/remote_node_name`` is a client of."""
    return node._names_and_types_by_node(remote_node_name, remote_node_namespace, "action_clients", "action client")

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.action.client", ActionClient, ClientGoalHandle)
