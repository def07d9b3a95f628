"""``rclpy.action.ActionClient``: goals, feedback and results over the graph."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from turtletui.compat.destroyable import Destroyable
from turtletui.compat.qos import (
    QoSProfile,
    qos_profile_action_status_default,
    qos_profile_services_default,
)
from turtletui.compat.task import Future

_NS = 1_000_000_000


class GoalStatus:
    """Numbers of action_msgs/msg/GoalStatus."""

    STATUS_UNKNOWN = 0
    STATUS_ACCEPTED = 1
    STATUS_EXECUTING = 2
    STATUS_CANCELING = 3
    STATUS_SUCCEEDED = 4
    STATUS_CANCELED = 5
    STATUS_ABORTED = 6


_STATUS = {"succeeded": 4, "canceled": 5, "aborted": 6}


class _FeedbackMessage:
    """What a feedback callback receives: ``msg.feedback`` is the Feedback."""

    __slots__ = ("goal_id", "feedback")

    def __init__(self, goal_id: int, feedback: Any) -> None:
        self.goal_id = goal_id
        self.feedback = feedback


class _GetResultResponse:
    """What ``get_result_async()`` completes with: ``.result`` and ``.status``."""

    __slots__ = ("status", "result")

    def __init__(self, status: int, result: Any) -> None:
        self.status = status
        self.result = result


class _CancelResponse:
    ERROR_NONE = 0
    ERROR_REJECTED = 1

    def __init__(self, accepted: bool) -> None:
        self.return_code = 0 if accepted else 1
        self.goals_canceling = []


class ClientGoalHandle:
    """The client's view of one goal."""

    def __init__(self, client: ActionClient, accepted: bool) -> None:
        self._client = client
        self._accepted = accepted
        self._status = GoalStatus.STATUS_ACCEPTED if accepted else GoalStatus.STATUS_UNKNOWN
        self._result_future = Future()
        self._server_handle: Any = None

    @property
    def accepted(self) -> bool:
        return self._accepted

    @property
    def status(self) -> int:
        return self._status

    @property
    def goal_id(self) -> Any:
        return self._server_handle.goal_id if self._server_handle else None

    def get_result_async(self) -> Future:
        return self._result_future

    def get_result(self) -> Any:
        self._client._host().spin_until(self._result_future.done, None)
        return self._result_future.result()

    def cancel_goal_async(self) -> Future:
        future = Future()
        host = self._client._host()
        if self._server_handle is not None and self._result_future.done() is False:
            self._status = GoalStatus.STATUS_CANCELING
            host.graph.cancel_goal(self._server_handle)
            future.set_result(_CancelResponse(True))
        else:
            future.set_result(_CancelResponse(False))
        return future

    def cancel_goal(self) -> Any:
        return self.cancel_goal_async().result()

    def _finished(self, status: str, result: Any) -> None:
        self._status = _STATUS.get(status, GoalStatus.STATUS_UNKNOWN)
        self._result_future.set_result(_GetResultResponse(self._status, result))


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
        delivery order matters in the simulation)."""
        if not all(hasattr(action_type, part) for part in ("Goal", "Result", "Feedback")):
            raise TypeError(
                f"ActionClient needs an action class such as turtlesim.action.RotateAbsolute, got {action_type!r}"
            )
        node._require_alive()
        self._node = node
        self._action_type = action_type
        self._action_name = node.resolve_topic_name(action_name)
        self._record = node._graph.add_action_client(node._record, self._action_name, action_type)
        node._entities.append(self)  # destroyed with the node

    def _host(self) -> Any:
        return self._node.context.host

    def server_is_ready(self) -> bool:
        self._require_alive()
        return self._node._graph.has_action_server(self._action_name)

    def wait_for_server(self, timeout_sec: float | None = None) -> bool:
        if self.server_is_ready():
            return True
        timeout = None if timeout_sec is None else int(timeout_sec * _NS)
        return self._host().spin_until(self.server_is_ready, timeout, callbacks=False)

    def send_goal_async(
        self, goal: Any, feedback_callback: Callable[[Any], None] | None = None, goal_uuid: Any = None
    ) -> Future:
        """Send ``goal``; the Future completes with a ClientGoalHandle."""
        self._require_alive()
        if type(goal) is not self._action_type.Goal:
            raise TypeError(f"send_goal_async() on {self._action_name} expects a Goal of {self._action_type}, got {goal!r}")
        future = Future()
        host = self._host()
        handle = ClientGoalHandle(self, accepted=True)

        def on_accepted(server_handle: Any) -> None:
            handle._server_handle = server_handle
            if handle._status == GoalStatus.STATUS_ACCEPTED:
                handle._status = GoalStatus.STATUS_EXECUTING
            future.set_result(handle)

        def on_feedback(feedback: Any) -> None:
            if feedback_callback is not None:
                feedback_callback(_FeedbackMessage(handle.goal_id, feedback))

        host.graph.send_goal(
            self._action_name,
            goal,
            host.owner,
            host.wrap_callback(on_accepted),
            host.wrap_callback(on_feedback),
            host.wrap_callback(handle._finished),
        )
        return future

    def send_goal(self, goal: Any, **kwargs: Any) -> Any:
        """Send ``goal`` and wait for its result; ``kwargs`` are send_goal_async's
        (``feedback_callback``, ``goal_uuid``). Never inside a callback: ROS deadlocks."""
        future = self.send_goal_async(goal, **kwargs)
        self._host().spin_until(future.done, None)
        handle = future.result()
        return handle.get_result() if handle else None

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
