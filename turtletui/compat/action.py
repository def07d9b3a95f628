"""``rclpy.action.ActionClient``: goals, feedback and results over the graph."""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import Any

from turtletui.compat.destroyable import Destroyable
from turtletui.compat.dispatch import dispatcher
from turtletui.compat.executors import answers_can_run
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
from turtletui.messages import LOST_GOAL_ADVICE, RESPONSE_WAITS_ADVICE

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
_RESPONSE_WAITS = (
    "{node}: spin_until_future_complete() inside a callback waited its whole timeout for an answer of action "
    "{action}, which is handled in the callback's own mutually exclusive group (the node's default, if you gave "
    "none) only after the callback returns; meanwhile the node handled nothing else. " + RESPONSE_WAITS_ADVICE
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
        self._result_requests: list[Future] = []
        """The futures of get_result_async calls made before the result came."""
        self._result: Any = None
        """The GetResult response, once the server sent it."""

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
        """A Future of the result response (``.status``, ``.result``): as in rclpy, a
        request of its own, whose done callbacks run as tasks of the executor that
        takes the response, after the client's own (removing the pending request)."""
        if not self._accepted:
            raise TypeError("Goal was not accepted")
        future = self._client._pending(self._client._pending_result_requests, Future())
        if self._result is not None:  # answered later, as the server answers the request
            client, result = self._client, self._result
            host = client._host()
            answer = client._dispatch(lambda: client._answer(client._pending_result_requests, future, result))
            host.graph.ready.append((host.owner, answer))
        else:
            self._result_requests.append(future)
        return future

    def get_result(self) -> Any:
        """Wait for the result response. Never inside a callback: ROS deadlocks."""
        future = self.get_result_async()
        self._client._host().spin_until(future.done, None)
        return future.result()

    def cancel_goal_async(self) -> Future:
        """Ask the server to cancel the goal; a Future of its CancelGoal response."""
        from turtletui.interfaces.action_msgs import CancelGoal, GoalInfo

        client = self._client
        pending = client._pending_cancel_requests
        future = client._pending(pending, Future())
        host = client._host()
        goal_id = self.goal_id

        def answered(code: int, canceling: bool) -> None:
            self._status_changed(self._record.status)
            canceled = [GoalInfo(goal_id=goal_id)] if canceling else []
            client._answer(pending, future, CancelGoal.Response(return_code=code, goals_canceling=canceled))

        if self._accepted:
            host.graph.cancel_goal(self._record, host.owner, client._dispatch(answered))
        else:
            client._answer(pending, future, CancelGoal.Response(return_code=_ERROR_UNKNOWN_GOAL_ID))
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
        self._result = self._client._action_type.Impl.GetResultService.Response(status=self._status, result=result)
        requests, self._result_requests = self._result_requests, []
        for future in requests:
            self._client._answer(self._client._pending_result_requests, future, self._result)


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
        """The QoS profiles are accepted and ignored (as for topics, only delivery order
        matters in the simulation); graph queries report the
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
        self._callback_group = node.default_callback_group if callback_group is None else callback_group
        self._told_undiscovered = False
        self._told_response_waits = False
        # rclpy's: the futures of requests sent and not yet answered, by sequence number
        self._sequence = 0
        self._pending_goal_requests: dict[int, Future] = {}
        self._pending_cancel_requests: dict[int, Future] = {}
        self._pending_result_requests: dict[int, Future] = {}
        node._entities.append(self)  # destroyed with the node

    def _dispatch(self, callback: Callable) -> Callable:
        """``callback`` as the graph should call it: a callback of the client's node in its
        group, parked while an executor without the node spins, as rclpy's executors take
        the client's responses and feedback only when they wait on its node."""
        return dispatcher(self._host(), self._callback_group, callback, node=self._node)

    def _pending(self, requests: dict[int, Future], future: Future) -> Future:
        """``future`` as the pending request of a new sequence number: as rclpy's, it leaves
        ``requests`` in a done callback of its own, which runs before the program's."""
        future._client = self  # what a wait for it inside a callback asks (Executor._spins_again)
        self._sequence += 1
        requests[self._sequence] = future
        future.add_done_callback(lambda done: self._remove_pending_request(done, requests))
        return future

    def _answer(self, requests: dict[int, Future], future: Future, response: Any) -> None:
        """The response of ``future``'s request taken, as rclpy's executor takes it: dropped
        if the request is no longer pending, else the future's done callbacks become tasks."""
        if future not in requests.values():
            return
        future._set_executor(self._node.executor)
        future.set_result(response)

    def _response_can_run(self) -> bool:
        """Whether, while the calling thread runs a callback, the answers to this
        client's requests (and its goals, if this controller serves the action)
        could be handled: neither waits for a mutually exclusive group busy with
        that callback."""
        server = self._node._graph.action_servers.get(self._action_name)
        return answers_can_run(self._callback_group, None if server is None else server.on_goal)

    def _tell_response_waits(self) -> None:
        """Say, once, that a wait inside a callback ran out its timeout because
        the answer could not be handled before the callback returned."""
        if not self._told_response_waits:
            self._told_response_waits = True
            node = self._node.get_fully_qualified_name()
            self._node._graph.log("turtletui", WARN, _RESPONSE_WAITS.format(node=node, action=self._action_name))

    def _remove_pending_request(self, future: Future, requests: dict[int, Future]) -> None:
        for sequence, pending in list(requests.items()):
            if pending is future:
                del requests[sequence]
                return

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
        future = self._pending(self._pending_goal_requests, Future())
        host = self._host()
        graph = host.graph
        if self._action_name in graph.action_servers and not graph.action_matched(self._record):
            self._tell_goal_lost()  # and never answered, as in ROS 2
            return future
        handle = ClientGoalHandle(self, None)
        feedback_type = self._action_type.Impl.FeedbackMessage

        def on_answer(record: Any) -> None:
            handle._answered(record)
            self._answer(self._pending_goal_requests, future, handle)

        def on_feedback(feedback: Any) -> None:
            handle._status_changed(handle._record.status)
            if feedback_callback is not None:
                feedback_callback(feedback_type(goal_id=handle.goal_id, feedback=feedback))

        handle._record = host.graph.send_goal(
            self._action_name,
            copier(type(goal))(goal),  # as sent: the caller may change its goal next
            host.owner,
            self._dispatch(on_answer),
            self._dispatch(on_feedback),
            self._dispatch(handle._finished),
            # no status of its own: as rclpy's client takes the latest status message with
            # whatever else it takes, each response and feedback brings the goal's status
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
