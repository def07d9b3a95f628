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
from collections.abc import Callable
from typing import Any

from turtletui.graph.core import (
    ActionClientRecord,
    ActionServer,
    GoalHandle,
    Graph,
    NodeRecord,
    Publisher,
    Service,
    ServiceClient,
    Subscription,
    Timer,
    Topic,
)
from turtletui.graph.logs import WARN, LogRecord
from turtletui.interfaces import get_interface, to_values, trusted_from_values
from turtletui.runtime import graph_mirror
from turtletui.runtime.protocol import (
    CallService,
    CancelGoal,
    Crash,
    DeclareActionClient,
    DeclareClient,
    DeclareNode,
    DeclarePublisher,
    DeclareService,
    DeclareSubscription,
    DeclareTimer,
    GoalAccepted,
    GoalFeedback,
    GraphChange,
    Log,
    Publish,
    RemoveEndpoint,
    RemoveNode,
    RemoveRecord,
    Report,
    SendGoal,
    ServiceResponse,
    SetParameter,
    Tick,
)

OWNER = "child"
"""Owner of the controller's ready callbacks in the child."""

_REMOVED_KINDS = {Service: "service", ServiceClient: "client", ActionClientRecord: "action_client"}


class ParentOutbox:
    """Queues what the child graph's nodes do for the parent; applies the
    parent's answers. Install with :meth:`install`."""

    remote_owner = graph_mirror.MIRROR_OWNER

    def __init__(self, graph: Graph, *, log_budget: int = 1 << 62) -> None:
        self.graph = graph
        self.log_budget = log_budget
        """Log records still worth sending: the parent keeps only Limits.log_lines
        (and notices one more), so a log flood costs no more than that."""
        self.logs_dropped = 0
        """Log records not sent for being over the budget (the parent says how many)."""
        self.changes: list[GraphChange] = []
        self.logs: list[Log] = []
        self.publishes: list[Publish] = []
        self.calls: list[CallService] = []
        self.goals: list[SendGoal] = []
        self.cancels: list[CancelGoal] = []
        self.responses: list[ServiceResponse] = []
        self._ids = itertools.count(1)
        self.wire_ids: dict[Any, int] = {}
        """The controller's nodes, publishers and subscriptions -> their wire ids."""
        self.own: dict[int, Any] = {}
        """... and back."""
        self._calls: dict[int, Callable[[Any], None]] = {}
        self._goals: dict[int, tuple] = {}

    def install(self) -> None:
        self.graph.outbox = self

    def report(self, wake_ns: int | None, *, done: bool = False, crash: Crash | None = None) -> Report:
        """Everything queued since the last report (then nothing is)."""
        changes, logs, publishes = self.changes, self.logs, self.publishes
        calls, goals, cancels, responses = self.calls, self.goals, self.cancels, self.responses
        report = Report(
            changes,
            logs,
            publishes,
            calls,
            goals,
            cancels,
            responses,
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
        if calls or goals or cancels or responses:
            self.calls, self.goals, self.cancels, self.responses = [], [], [], []
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
                self._new_id(record), node, topic.name, topic.type_name, record.depth, label, qos
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
        else:
            return  # an action server: served in the child only
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
        if isinstance(value, (bytes, bytearray)):
            value = list(value)
        self.changes.append(SetParameter(self.wire_ids[node], name, value, remove))

    def published(self, topic: Topic, msg: Any) -> None:
        # Its values now: a message changed after publish() is not what was sent.
        self.publishes.append(Publish(topic.name, to_values(msg)))

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
    ) -> None:
        goal_id = next(self._ids)
        handle = GoalHandle(server, goal_id, goal, on_feedback, on_result)
        self._goals[goal_id] = (handle, on_accepted, on_feedback, on_result, server.action_type)
        self.goals.append(SendGoal(goal_id, server.name, to_values(goal)))

    def cancel_goal(self, handle: GoalHandle) -> None:
        self.cancels.append(CancelGoal(handle.goal_id))

    def logged(self, record: LogRecord) -> None:
        if self.log_budget > 0:
            self.log_budget -= 1
            self.logs.append(Log(record.level, str(record.node), record.msg))
        else:
            self.logs_dropped += 1

    # -- what the parent sent -------------------------------------------------------------------
    def apply(self, tick: Tick) -> None:
        """Queue the callbacks for what ``tick`` brought (the time is the caller's)."""
        graph = self.graph
        ready = graph.ready
        if tick.graph is not None:  # first: what arrives with it may come from nodes it adds
            graph_mirror.apply(graph, tick.graph, self.own)
        own = self.own
        for sub_id, values in tick.deliveries:
            sub = own.get(sub_id)
            if sub is None:
                continue
            sub.queue.append(trusted_from_values(sub.topic.msg_type)(values))
            if not sub.pending:
                sub.pending = True
                ready.append(sub.ready_item)
        for call_id, type_name, values in tick.results:
            on_response = self._calls.pop(call_id, None)
            if on_response is not None:
                response = trusted_from_values(get_interface(type_name))(values)
                ready.append((OWNER, lambda cb=on_response, r=response: cb(r)))
        for event in tick.goal_events:
            entry = self._goals.get(event.goal_id)
            if entry is None:
                continue
            handle, on_accepted, on_feedback, on_result, action = entry
            if isinstance(event, GoalAccepted):
                ready.append((OWNER, lambda cb=on_accepted, h=handle: cb(h)))
            elif isinstance(event, GoalFeedback):
                feedback = trusted_from_values(action.Feedback)(event.values)
                ready.append((OWNER, lambda cb=on_feedback, f=feedback: cb(f)))
            else:
                self._goals.pop(event.goal_id, None)
                handle.status = event.status
                result = trusted_from_values(action.Result)(event.values)
                ready.append((OWNER, lambda cb=on_result, s=event.status, r=result: cb(s, r)))
        for req_id, name, values in tick.requests:
            service = graph.services.get(name)
            if service is None:
                continue
            request = trusted_from_values(service.srv_type.Request)(values)

            def respond(response: Any, req_id: int = req_id) -> None:
                self.responses.append(ServiceResponse(req_id, to_values(response)))

            ready.append((OWNER, lambda s=service, q=request, r=respond: s.handler(q, r)))
        for node_id, name, value in tick.parameters:
            node = own.get(node_id)
            if isinstance(node, NodeRecord) and node.parameter_setter is not None:
                ready.append((OWNER, lambda n=node, k=name, v=value: self._set_parameter(n, k, v)))

    def _set_parameter(self, node: NodeRecord, name: str, value: Any) -> None:
        """``ros2 param set`` from the app; the parent checked the name and type,
        the node's own on-set callbacks may still refuse."""
        reason = node.parameter_setter(name, value)
        if reason:
            self.graph.log(node.name, WARN, f"Setting parameter {name} failed: {reason}")
