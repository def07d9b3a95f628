"""The sandboxed child's side of the protocol with the simulator.

:class:`ParentOutbox` is the child Graph's outbox (turtletui.graph.core.GraphOutbox):
everything the controller's nodes declare, publish, call and log is queued as
turtletui.runtime.protocol messages and goes to the parent in the next
:class:`~turtletui.runtime.protocol.Report`; the parent's
:class:`~turtletui.runtime.protocol.Tick` comes back through :meth:`ParentOutbox.apply`.
This module must not import numpy or Textual: start-up time counts.
"""

from __future__ import annotations

import itertools
from array import array
from collections.abc import Callable, Sequence
from typing import Any

from turtletui.compat.matching import match_mirror
from turtletui.graph.core import (
    ActionClientRecord,
    ActionServer,
    GoalHandle,
    Graph,
    MessageOrigin,
    NodeRecord,
    Publisher,
    Service,
    ServiceClient,
    StampedQueue,
    Subscription,
    Timer,
    Topic,
)
from turtletui.graph.logs import WARN, LogRecord
from turtletui.interfaces import get_interface, to_values, trusted_from_values
from turtletui.runtime import graph_mirror
from turtletui.runtime.budget import RateCap
from turtletui.runtime.protocol import (
    AcceptServedGoal,
    AnswerServedCancel,
    CallService,
    CancelAnswer,
    CancelGoal,
    Crash,
    DeclareActionClient,
    DeclareActionServer,
    DeclareClient,
    DeclareNode,
    DeclarePublisher,
    DeclareService,
    DeclareSubscription,
    DeclareTimer,
    Delivery,
    FinishServedGoal,
    GoalAccepted,
    GoalEvent,
    GoalFeedback,
    GoalRejected,
    GoalStatus,
    GraphChange,
    Log,
    Publish,
    RejectServedGoal,
    RemoveEndpoint,
    RemoveNode,
    RemoveRecord,
    Report,
    SendGoal,
    ServeCancel,
    ServedGoalEvent,
    ServedGoalFeedback,
    ServedGoalStatus,
    ServerEvent,
    ServiceResponse,
    SetParameter,
    StampedDelivery,
    Tick,
)

OWNER = "child"
"""Owner of the controller's ready callbacks in the child."""

_REMOVED_KINDS = {
    Service: "service",
    ServiceClient: "client",
    ActionClientRecord: "action_client",
    ActionServer: "action_server",
}


class ParentOutbox:
    """Queues what the child graph's nodes do for the parent; applies the
    parent's answers. Install with :meth:`install`."""

    remote_owner = graph_mirror.MIRROR_OWNER

    def __init__(self, graph: Graph, *, log_budget: int = 1 << 62, log_rate: RateCap | None = None) -> None:
        self.graph = graph
        self.log_budget = log_budget
        """Log records still worth sending: the parent keeps only Limits.log_lines
        (and notices one more), so a log flood costs no more than that."""
        self.log_rate = log_rate
        """Log records sent per wall second (the app's Limits.log_lines_per_second)."""
        self.logs_dropped = 0
        """Log records not sent for being over the budget (the parent says how many)."""
        self.changes: list[GraphChange] = []
        self.logs: list[Log] = []
        self._logged_call = 0
        """The call number of the last Log sent (Log.call_step)."""
        self.publishes: list[Publish] = []
        self.calls: list[CallService] = []
        self.goals: list[SendGoal] = []
        self.cancels: list[CancelGoal] = []
        self.responses: list[ServiceResponse] = []
        self.served: list[ServedGoalEvent] = []
        self._ids = itertools.count(1)
        self.wire_ids: dict[Any, int] = {}
        """The controller's nodes, publishers and subscriptions -> their wire ids."""
        self.own: dict[int, Any] = {}
        """... and back."""
        self._calls: dict[int, Callable[[Any], None]] = {}
        self._goals: dict[int, tuple] = {}
        """The controller's goals for the parent's action servers, by wire id."""
        self._goal_wire_ids: dict[GoalHandle, int] = {}
        self._cancels: dict[int, list[Callable[[int, bool], None] | None]] = {}
        """Who waits for the parent's answer to a cancel request, by goal wire id."""
        self._served: dict[int, GoalHandle] = {}
        """Goals of the controller's own action servers, by the parent's goal id."""

    def install(self) -> None:
        self.graph.outbox = self

    def report(self, wake_ns: int | None, *, done: bool = False, crash: Crash | None = None) -> Report:
        """Everything queued since the last report (then nothing is)."""
        changes, logs, publishes = self.changes, self.logs, self.publishes
        calls, goals, cancels, responses, served = self.calls, self.goals, self.cancels, self.responses, self.served
        report = Report(
            changes,
            logs,
            publishes,
            calls,
            goals,
            cancels,
            responses,
            served,
            self.logs_dropped,
            None if wake_ns is None else int(wake_ns),
            done,
            crash,
        )
        # New lists for what went out: the report keeps the old ones.
        if changes:
            self.changes = []
        if logs:
            self.logs = []
        if publishes:
            self.publishes = []
        if calls or goals or cancels or responses or served:
            self.calls, self.goals, self.cancels, self.responses, self.served = [], [], [], [], []
        return report

    # -- GraphOutbox: what the controller's nodes do ------------------------------------------
    def _new_id(self, record: Any) -> int:
        wire_id = next(self._ids)
        self.wire_ids[record] = wire_id
        self.own[wire_id] = record
        return wire_id

    def declared(self, record: Any) -> None:
        change: GraphChange
        if isinstance(record, NodeRecord):
            change = DeclareNode(self._new_id(record), record.name, record.namespace)
        elif isinstance(record, Publisher):
            node = self.wire_ids[record.node]
            qos = graph_mirror.QosPolicies.of(record.qos)
            topic = record.topic
            change = DeclarePublisher(self._new_id(record), node, topic.name, topic.type_name, record.depth, qos)
        elif isinstance(record, Subscription):
            node = self.wire_ids[record.node]
            label = getattr(record.callback, "label", "")
            qos = graph_mirror.QosPolicies.of(record.qos)
            topic = record.topic
            change = DeclareSubscription(
                self._new_id(record),
                node,
                topic.name,
                topic.type_name,
                record.depth,
                label,
                qos,
                type(record.queue) is StampedQueue,
            )
        elif isinstance(record, Timer):
            # named in the parent's report of a controller too slow for its timer
            change = DeclareTimer(self.wire_ids[record.node], record.period_ns, getattr(record.callback, "label", ""))
        elif isinstance(record, Service):
            change = DeclareService(self.wire_ids[record.node], record.name, record.type_name)
        elif isinstance(record, ServiceClient):
            change = DeclareClient(self.wire_ids[record.node], record.name, record.type_name)
        elif isinstance(record, ActionClientRecord):
            change = DeclareActionClient(self.wire_ids[record.node], record.name, record.type_name)
        elif isinstance(record, ActionServer):
            change = DeclareActionServer(self.wire_ids[record.node], record.name, record.type_name)
        else:
            return
        self.changes.append(change)

    def removed(self, record: Any) -> None:
        change: GraphChange
        if isinstance(record, NodeRecord):
            # its wire id stays known: a destroyed node's records still name it
            wire_id = self.wire_ids[record]
            self.own.pop(wire_id, None)
            change = RemoveNode(wire_id)
        elif isinstance(record, (Publisher, Subscription)):
            wire_id = self.wire_ids.pop(record)
            self.own.pop(wire_id, None)
            change = RemoveEndpoint(wire_id)
        elif type(record) in _REMOVED_KINDS:
            # other nodes see it gone from the next exchange on
            change = RemoveRecord(_REMOVED_KINDS[type(record)], self.wire_ids[record.node], record.name)
        else:
            return
        self.changes.append(change)

    def parameter_set(self, node: NodeRecord, name: str, value: Any, remove: bool) -> None:
        self.changes.append(SetParameter(self.wire_ids[node], name, wire_parameter_value(value), remove))

    def published(self, topic: Topic, msg: Any, publisher: Publisher | None, young: bool) -> None:
        # Its values now: a message changed after publish() is not what was sent.
        self.publishes.append(Publish(topic.name, to_values(msg), self.wire_ids.get(publisher, 0), young))

    def call(self, service: Service, request: Any, on_response: Callable[[Any], None]) -> None:
        call_id = next(self._ids)
        self._calls[call_id] = on_response
        self.calls.append(CallService(call_id, service.name, to_values(request)))

    def send_goal(
        self,
        server: ActionServer,
        goal: Any,
        on_accepted: Callable[[GoalHandle | None], None],
        on_feedback: Callable[[Any], None],
        on_result: Callable[[str, Any], None],
        on_status: Callable[[str], None] | None,
    ) -> GoalHandle:
        wire_id = next(self._ids)
        # goal_id becomes the parent's once it accepted the goal
        handle = GoalHandle(server, wire_id, goal, on_feedback, on_result, status="pending")
        self._goals[wire_id] = (handle, on_accepted, on_feedback, on_result, on_status, server.action_type)
        self._goal_wire_ids[handle] = wire_id
        self.goals.append(SendGoal(wire_id, server.name, to_values(goal)))
        return handle

    def cancel_goal(self, handle: GoalHandle, on_answer: Callable[[int, bool], None] | None) -> None:
        wire_id = self._goal_wire_ids[handle]
        self._cancels.setdefault(wire_id, []).append(on_answer)
        self.cancels.append(CancelGoal(wire_id))

    def logged(self, record: LogRecord) -> None:
        if self.log_rate is not None and not self.log_rate.allow(1):
            return  # over the app's cap: its note says how many, once a second
        if self.log_budget > 0:
            self.log_budget -= 1
            call = record.call
            self.logs.append(Log(record.level, str(record.node), record.msg, record.in_callback, call - self._logged_call))
            self._logged_call = call
        else:
            self.logs_dropped += 1

    # -- what the parent sent -------------------------------------------------------------------
    def apply(self, tick: Tick) -> None:
        """Queue the callbacks for what ``tick`` brought (the time is the caller's)."""
        graph = self.graph
        ready = graph.ready
        if tick.graph is not None:  # first: what arrives with it may come from nodes it adds
            graph_mirror.apply(graph, tick.graph, self.own)
            match_mirror(graph, self.remote_owner)
            if graph.on_endpoints is not None:
                graph.on_endpoints()  # matched events of the child's endpoints
        if tick.stamped:
            self._deliver_stamped(tick.deliveries, tick.stamped)
        elif tick.deliveries:
            self._deliver(tick.deliveries)
        for call_id, type_name, values in tick.results:
            on_response = self._calls.pop(call_id, None)
            if on_response is not None:
                response = trusted_from_values(get_interface(type_name))(values)
                ready.append((OWNER, lambda cb=on_response, r=response: cb(r)))
        for event in tick.goal_events:
            self._goal_event(event)
        for event in tick.served:
            self._serve(event)
        for req_id, name, values in tick.requests:
            service = graph.services.get(name)
            if service is None:
                continue
            request = trusted_from_values(service.srv_type.Request)(values)

            def respond(response: Any, req_id: int = req_id) -> None:
                self.responses.append(ServiceResponse(req_id, to_values(response)))

            ready.append((OWNER, lambda s=service, q=request, r=respond: s.handler(q, r)))
        for node_id, name, value in tick.parameters:
            node = self.own.get(node_id)
            if isinstance(node, NodeRecord) and node.parameter_setter is not None:
                ready.append((OWNER, lambda n=node, k=name, v=value: self._set_parameter(n, k, v)))

    def _deliver(self, deliveries: Sequence[Delivery]) -> None:
        """Queue messages for the controller's subscriptions."""
        own = self.own
        ready = self.graph.ready
        for sub_id, values in deliveries:
            sub = own.get(sub_id)
            if sub is None:
                continue
            sub.queue.append(trusted_from_values(sub.topic.msg_type)(values))
            if not sub.pending:
                sub.pending = True
                ready.append(sub.ready_item)

    def _deliver_stamped(self, deliveries: Sequence[Delivery], stamped: Sequence[StampedDelivery]) -> None:
        """Queue both kinds of messages, in the order the parent had them."""
        own = self.own
        graph = self.graph
        ready = graph.ready
        done = 0
        for position, sub_id, values, source_ns, sequence, gid in stamped:
            if position > done:
                self._deliver(deliveries[done:position])
                done = position
            sub = own.get(sub_id)
            if sub is None or type(sub.queue) is not StampedQueue:
                continue
            msg = trusted_from_values(sub.topic.msg_type)(values)
            sub.queue.append_stamped(msg, MessageOrigin(source_ns, graph.now_ns, sequence, gid))
            if not sub.pending:
                sub.pending = True
                ready.append(sub.ready_item)
        self._deliver(deliveries[done:])

    def _goal_event(self, event: GoalEvent) -> None:
        """What happened to one of the controller's goals for the parent's servers."""
        ready = self.graph.ready
        kind = type(event)
        if kind is CancelAnswer:  # may come after the goal's result
            waiting = self._cancels.get(event.goal_id)
            on_answer = waiting.pop(0) if waiting else None
            if on_answer is not None:
                ready.append((OWNER, lambda cb=on_answer, e=event: cb(e.code, e.canceling)))
            return
        entry = self._goals.get(event.goal_id)
        if entry is None:
            return
        handle, on_accepted, on_feedback, on_result, on_status, action = entry
        if kind is GoalAccepted:
            handle.goal_id, handle.status = event.server_goal_id, event.status
            ready.append((OWNER, lambda cb=on_accepted, h=handle: cb(h)))
        elif kind is GoalRejected:
            self._goals.pop(event.goal_id, None)
            handle.status = "rejected"
            ready.append((OWNER, lambda cb=on_accepted: cb(None)))
        elif kind is GoalStatus:
            handle.status = event.status
            if on_status is not None:
                ready.append((OWNER, lambda cb=on_status, s=event.status: cb(s)))
        elif kind is GoalFeedback:
            feedback = trusted_from_values(action.Feedback)(event.values)
            ready.append((OWNER, lambda cb=on_feedback, f=feedback: cb(f)))
        else:
            self._goals.pop(event.goal_id, None)
            handle.status = event.status
            result = trusted_from_values(action.Result)(event.values)
            ready.append((OWNER, lambda cb=on_result, s=event.status, r=result: cb(s, r)))

    def _serve(self, event: ServerEvent) -> None:
        """A goal for one of the controller's action servers, or a request to cancel one."""
        goal_id = event.goal_id
        ready = self.graph.ready

        def send(served: ServedGoalEvent) -> None:
            self.served.append(served)  # the list of the next report (each report takes its own)

        if type(event) is ServeCancel:
            handle = self._served.get(goal_id)
            if handle is not None:
                answer = lambda code, canceling: send(AnswerServedCancel(goal_id, code, canceling))  # noqa: E731
                ready.append((OWNER, lambda: handle.request_cancel(answer)))
            return
        server = self.graph.action_servers.get(event.action)
        if server is None or server.owner == self.remote_owner:
            return  # destroyed meanwhile: never answered, as in ROS

        def finished(status: str, result: Any) -> None:
            self._served.pop(goal_id, None)
            send(FinishServedGoal(goal_id, status, to_values(result)))

        handle = GoalHandle(
            server,
            goal_id,
            trusted_from_values(server.action_type.Goal)(event.values),
            on_feedback=lambda feedback: send(ServedGoalFeedback(goal_id, to_values(feedback))),
            on_result=finished,
            status="pending",
            on_answer=lambda h: send(AcceptServedGoal(goal_id, h.status) if h is not None else RejectServedGoal(goal_id)),
            on_status=lambda status: send(ServedGoalStatus(goal_id, status)),
        )
        self._served[goal_id] = handle
        ready.append((OWNER, lambda: server.on_goal(handle)))

    def _set_parameter(self, node: NodeRecord, name: str, value: Any) -> None:
        """``ros2 param set`` from the app; the parent checked the name and type,
        the node's own on-set callbacks may still refuse."""
        reason = node.parameter_setter(name, value)
        if reason:
            self.graph.log(node.name, WARN, f"Setting parameter {name} failed: {reason}")


def wire_parameter_value(value: Any) -> Any:
    """A parameter's value as the wire carries it (a scalar or a list of
    scalars): rclpy's arrays may be tuples or ``array.array``, and a byte
    array is ``bytes`` or a list of one-byte ``bytes``; each byte goes as its int."""
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    if isinstance(value, (list, tuple, array)):
        return [_wire_byte(item) if isinstance(item, bytes) else item for item in value]
    return value


def _wire_byte(item: bytes) -> int | str:
    return item[0] if len(item) == 1 else repr(item)  # rclpy's byte arrays hold one-byte bytes
