"""A sandboxed controller's nodes on the simulator's graph.

:class:`GraphProxy` applies the child's :class:`~turtletui.runtime.protocol.Report`
to the parent's Graph (nodes, endpoints, services, parameters, published
messages, calls, goals, logs), checking what each field means: the node it
names exists, the message is of its topic's type and every value in range.
It gathers what the graph sends the child's nodes (messages, service answers
and requests, goal events, parameters, a new mirror of the graph) for the
next :class:`~turtletui.runtime.protocol.Tick`.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from typing import Any

from turtletui.compat.graph_info import publisher_gid
from turtletui.compat.matching import warn_others
from turtletui.graph.core import GoalHandle, Graph, GraphError, MessageOrigin, NodeRecord, Publisher
from turtletui.graph.logs import ERROR
from turtletui.interfaces import build_from_values, from_values, get_interface, to_values
from turtletui.runtime import graph_mirror
from turtletui.runtime.budget import CALLS, WAKE, Pace, size_text
from turtletui.runtime.protocol import (
    AcceptServedGoal,
    AnswerServedCancel,
    CancelAnswer,
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
    GoalResult,
    GoalStatus,
    GraphChange,
    ParameterUpdate,
    ProtocolError,
    RejectServedGoal,
    RemoveEndpoint,
    RemoveNode,
    RemoveRecord,
    Report,
    ServeCancel,
    ServedGoalEvent,
    ServedGoalFeedback,
    ServedGoalStatus,
    ServeGoal,
    ServerEvent,
    ServiceRequest,
    ServiceResult,
    SetParameter,
    StampedDelivery,
    Tick,
)

_MAX_TIMERS_NAMED = 100
"""Timers kept for a report of a controller too slow for them."""


class GraphProxy:
    """The child's records on the parent's graph, owned by ``owner``; ``label``
    names the controller in notices; ``pace`` learns its callbacks' names."""

    def __init__(self, graph: Graph, owner: str, label: str, pace: Pace, *, log_lines: int, log_bytes: int) -> None:
        self.graph = graph
        self.owner = owner
        graph.self_delivering.add(owner)
        self.label = label
        self.pace = pace
        self.log_lines = log_lines
        self.log_bytes = log_bytes
        self.running = True
        """False once the child is gone: ``ros2 param set`` on its nodes is refused."""
        self.values: Callable[[Any], Any] = to_values
        """A delivered message's values for the child (a replay, whose Ticks
        nobody reads, may skip them)."""
        self.build: Callable[[Any, list], Any] = build_from_values
        """Builds a published message from the child's values, checking every one
        (a copy of the simulation in the child itself may trust its own)."""
        self._logs_kept = 0
        self._log_bytes_kept = 0
        self._logs_dropped_here = 0
        self._logs_dropped_there = 0
        self._request_ids = itertools.count(1)
        self._nodes: dict[int, NodeRecord] = {}
        self._endpoints: dict[int, Any] = {}
        self._removed: dict[int, Any] = {}
        """Endpoints the Report being applied destroyed: it may still carry their messages."""
        self._goals: dict[int, Any] = {}
        self._service_calls: dict[int, Callable[[list], None]] = {}
        self._call = 0
        """The call number of the child's last Log (the sum of their call_step)."""
        self._deliveries: list[Delivery] = []
        self._stamped: list[StampedDelivery] = []
        self._results: list[ServiceResult] = []
        self._goal_events: list[GoalEvent] = []
        self._requests: list[ServiceRequest] = []
        self._parameters: list[ParameterUpdate] = []
        self._served_out: list[ServerEvent] = []
        """Goals and cancel requests for the child's own action servers, to send."""
        self._served: dict[int, GoalHandle] = {}
        """Goals of the child's action servers not finished yet, by goal id."""
        self._cancel_decisions: dict[int, Callable[..., None]] = {}
        self._mirror: graph_mirror.GraphMirror | None = None
        """The graph as the child last heard of it."""
        self._mirrored_version = -1
        """The graph's version when the child was last sent the mirror (or
        when only the child's own doings changed it)."""

    @property
    def dropped_logs(self) -> int:
        """Log records over the budget: dropped here, or by the child (its count)."""
        return self._logs_dropped_here + self._logs_dropped_there

    # -- to the child -----------------------------------------------------------------------------
    def has_news(self) -> bool:
        """Whether the next Tick brings the child something (or the graph changed)."""
        return bool(
            self._deliveries or self._stamped or self._results or self._goal_events or self._requests or self._parameters
            or self._served_out
        ) or self.graph.version != self._mirrored_version

    def tick(self) -> tuple[Tick, Any]:
        """The next Tick, and what it is for (budget.Pace's cause: the
        subscription whose messages it delivers, a tuple of them, WAKE or CALLS)."""
        cause: Any = WAKE
        results, goal_events, requests, parameters = self._results, self._goal_events, self._requests, self._parameters
        served = self._served_out
        if results or goal_events or requests or parameters or served:
            self._results, self._goal_events, self._requests, self._parameters = [], [], [], []
            self._served_out = []
            cause = CALLS
        deliveries = self._deliveries
        if deliveries:
            self._deliveries = []
            cause = deliveries[0][0] if len(deliveries) == 1 else _subscriptions(deliveries)
        stamped = self._stamped
        if stamped:
            self._stamped = []
            cause = _subscriptions(deliveries, stamped)
        mirror = None
        graph = self.graph
        if graph.version != self._mirrored_version:
            self._mirrored_version = graph.version
            snapshot = graph_mirror.snapshot(graph, self.owner, self._own_ids())
            if snapshot != self._mirror:
                self._mirror = mirror = snapshot
        return Tick(graph.now_ns, deliveries, results, goal_events, requests, parameters, served, mirror, stamped), cause

    def _own_ids(self) -> dict[int, int]:
        """``id(record)`` to wire id, for the child's nodes and topic endpoints here."""
        ids = {id(node): wire_id for wire_id, node in self._nodes.items()}
        ids.update((id(endpoint), wire_id) for wire_id, endpoint in self._endpoints.items())
        return ids

    # -- from the child ---------------------------------------------------------------------------
    def apply(self, report: Report) -> None:
        """Apply what the child's nodes did. Raises GraphError, InterfaceError or
        ProtocolError for what the graph cannot accept."""
        graph = self.graph
        unchanged = graph.version == self._mirrored_version
        self._removed.clear()
        for change in report.changes:
            self._change(change)
        if unchanged:
            # The child knows what it did itself: no exchange just to tell it.
            self._mirrored_version = graph.version
        for log in report.logs:
            self._call += log.call_step
            self._log(log.level, log.node, log.text, log.in_callback, self._call)
        if report.logs_dropped > self._logs_dropped_there:
            self._logs_dropped_there = report.logs_dropped  # the child's own count: only ever shown
        owner = self.owner
        topics = graph.topics
        endpoints = self._endpoints
        removed = self._removed
        for name, values, publisher_id, young in report.publishes:
            publisher = endpoints.get(publisher_id) or removed.get(publisher_id)
            if isinstance(publisher, Publisher) and publisher.topic.name == name:
                # its topic, also when the publisher is destroyed in this Report
                # and its topic left the graph with it: the message was sent before
                topic = publisher.topic
            else:
                publisher = None
                topic = topics.get(name)
                if topic is None:
                    raise GraphError(f"published on undeclared topic {name}")
            graph.publish(topic, self.build(topic.msg_type, values), owner, publisher, young=young)
        for call_id, name, values in report.calls:
            service = graph.services.get(name)
            if service is None:
                continue
            request = from_values(service.srv_type.Request, values)
            response_type = f"{service.type_name}_Response"
            graph.call(
                name,
                request,
                lambda response, cid=call_id, rt=response_type: self._results.append(
                    ServiceResult(cid, rt, to_values(response))
                ),
                owner,
            )
        for goal_id, name, values in report.goals:
            server = graph.action_servers.get(name)
            if server is None:
                continue
            graph.send_goal(
                name,
                from_values(server.action_type.Goal, values),
                owner,
                lambda handle, gid=goal_id: self._goal_accepted(gid, handle),
                lambda feedback, gid=goal_id: self._goal_events.append(GoalFeedback(gid, to_values(feedback))),
                lambda status, result, gid=goal_id: self._goal_events.append(
                    GoalResult(gid, status, to_values(result))
                ),
                lambda status, gid=goal_id: self._goal_events.append(GoalStatus(gid, status)),
            )
        for (goal_id,) in report.cancels:
            handle = self._goals.get(goal_id)
            if handle is not None:
                graph.cancel_goal(
                    handle,
                    owner,
                    lambda code, canceling, gid=goal_id: self._goal_events.append(CancelAnswer(gid, code, canceling)),
                )
        for event in report.served:
            self._served_event(event)
        for request_id, values in report.responses:
            respond = self._service_calls.pop(request_id, None)
            if respond is not None:
                respond(values)

    def _log(self, level: int, node: str, text: str, in_callback: bool = True, call: int = 0) -> None:
        graph = self.graph
        text = text[:10_000]
        self._logs_kept += 1
        self._log_bytes_kept += len(text) + 1
        if self._logs_kept <= self.log_lines and self._log_bytes_kept <= self.log_bytes:
            graph.log(node[:200], level, text, in_callback=in_callback, call=call)
            return
        self._logs_dropped_here += 1
        if self._logs_dropped_here == 1:
            graph.log(
                "turtletui",
                ERROR,
                f"{self.label}: log over its budget of {self.log_lines:,} messages or "
                f"{size_text(self.log_bytes)} per run: the rest is dropped",
            )

    def _goal_accepted(self, goal_id: int, handle: GoalHandle | None) -> None:
        if handle is None:
            self._goal_events.append(GoalRejected(goal_id))
            return
        self._goals[goal_id] = handle
        self._goal_events.append(GoalAccepted(goal_id, handle.goal_id, handle.status))

    def _serve(self, handle: GoalHandle) -> None:
        """A goal for one of the child's action servers: sent with the next exchange."""
        goal_id = handle.goal_id
        self._served[goal_id] = handle

        def decide_cancel(decided: Callable[..., None]) -> None:
            self._cancel_decisions[goal_id] = decided
            self._served_out.append(ServeCancel(goal_id))

        handle.decide_cancel = decide_cancel
        self._served_out.append(ServeGoal(goal_id, handle.action.name, to_values(handle.goal)))

    def _served_event(self, event: ServedGoalEvent) -> None:
        """What the child's action server did with one of its goals."""
        goal_id = event.goal_id
        handle = self._served.get(goal_id)
        if handle is None:
            return  # finished already, or never sent
        kind = type(event)
        if kind is AcceptServedGoal:
            handle.accept(event.status)
        elif kind is RejectServedGoal:
            handle.reject()
            del self._served[goal_id]
        elif kind is ServedGoalStatus:
            handle.set_status(event.status)
        elif kind is ServedGoalFeedback:
            handle.publish_feedback(from_values(handle.action.action_type.Feedback, event.values))
        elif kind is FinishServedGoal:
            handle.finish(event.status, from_values(handle.action.action_type.Result, event.values))
            del self._served[goal_id]
        elif kind is AnswerServedCancel:
            decided = self._cancel_decisions.pop(goal_id, None)
            if decided is not None:
                decided(True) if event.canceling else decided(False, event.code)

    def _node(self, wire_id: int, change: GraphChange) -> NodeRecord:
        node = self._nodes.get(wire_id)
        if node is None:
            raise ProtocolError(f"{type(change).__name__}.node names no node of the controller: {wire_id}")
        return node

    def _change(self, change: GraphChange) -> None:
        graph = self.graph
        kind = type(change)
        if kind is DeclareNode:
            wire_id = change.wire_id
            node = graph.add_node(change.name, change.namespace, self.owner)
            node.parameter_setter = lambda key, value, node=node, wire_id=wire_id: self._set_parameter(
                node, wire_id, key, value
            )
            self._nodes[wire_id] = node
        elif kind is RemoveNode:
            node = self._nodes.pop(change.wire_id, None)
            if node is not None:
                graph.remove_node(node)
        elif kind is DeclarePublisher:
            node = self._node(change.node, change)
            publisher = graph.add_publisher(node, change.topic, get_interface(change.type_name), change.depth, qos=change.qos)
            self._endpoints[change.wire_id] = publisher
            warn_others(graph, publisher)
        elif kind is DeclareSubscription:
            node = self._node(change.node, change)
            wire_id = change.wire_id
            self.pace.subscriptions[wire_id] = (_label(change.label), change.topic[:200])

            def forward(msg: Any, wire_id: int = wire_id) -> None:
                self._deliveries.append(Delivery(wire_id, self.values(msg)))

            def forward_stamped(entry: tuple[Any, MessageOrigin], wire_id: int = wire_id) -> None:
                msg, origin = entry
                publisher = origin.publisher
                gid = publisher_gid(graph, publisher) if isinstance(publisher, Publisher) else publisher
                self._stamped.append(
                    StampedDelivery(
                        len(self._deliveries), wire_id, self.values(msg), origin.source_ns, origin.sequence, gid
                    )
                )

            subscription = graph.add_subscription(
                node,
                change.topic,
                get_interface(change.type_name),
                change.depth,
                forward_stamped if change.message_info else forward,
                qos=change.qos,
                stamped=change.message_info,
            )
            self._endpoints[wire_id] = subscription
            warn_others(graph, subscription)
        elif kind is RemoveEndpoint:
            endpoint = self._endpoints.pop(change.wire_id, None)
            if endpoint is not None:
                self._removed[change.wire_id] = endpoint
                graph.remove_endpoint(endpoint)
        elif kind is DeclareTimer:
            if len(self.pace.timers) < _MAX_TIMERS_NAMED:
                self.pace.timers.append((change.period_ns, _label(change.label)))
        elif kind is DeclareClient:
            graph.add_client(self._node(change.node, change), change.name, get_interface(change.type_name))
        elif kind is DeclareActionClient:
            graph.add_action_client(self._node(change.node, change), change.name, get_interface(change.type_name))
        elif kind is DeclareActionServer:
            graph.add_action_server(
                self._node(change.node, change), change.name, get_interface(change.type_name), self._serve, answers=True
            )
        elif kind is DeclareService:
            self._declare_service(change)
        elif kind is RemoveRecord:
            self._remove(change)
        elif kind is SetParameter:
            value = change.value
            if type(value) is list:
                value = list(value)  # a decoded Report may be reused (SandboxHost._decode): keep its own
            graph.set_parameter(self._node(change.node, change), change.name, value, remove=change.remove)

    def _declare_service(self, change: DeclareService) -> None:
        srv_type = get_interface(change.type_name)
        name = change.name

        def handler(request: Any, respond: Callable[[Any], None]) -> None:
            request_id = next(self._request_ids)
            self._service_calls[request_id] = lambda values: respond(from_values(srv_type.Response, values))
            self._requests.append(ServiceRequest(request_id, name, to_values(request)))

        self.graph.add_service(self._node(change.node, change), name, srv_type, handler)

    def _remove(self, removed: RemoveRecord) -> None:
        """The child destroyed a service, client, action client or action server."""
        graph = self.graph
        node = self._nodes.get(removed.node)
        if removed.kind == "service":
            service = graph.services.get(removed.name)
            if service is not None and service.node is node:
                graph.remove_service(service)
            return
        if removed.kind == "action_server":
            server = graph.action_servers.get(removed.name)
            if server is not None and server.node is node:
                graph.remove_action_server(server)
            return
        records = graph.clients if removed.kind == "client" else graph.action_clients
        record = next((r for r in records if r.node is node and r.name == removed.name), None)
        if record is None:
            return
        if removed.kind == "client":
            graph.remove_client(record)
        else:
            graph.remove_action_client(record)

    def _set_parameter(self, node: NodeRecord, wire_id: int, name: str, value: Any) -> str | None:
        """``ros2 param set`` on a sandboxed node: refused here if ROS would refuse
        the type, else sent with the next exchange (the node's own on-set
        callbacks may still refuse it, and its log then says why)."""
        if not self.running:
            return f"{node.fqn} is not running"
        from turtletui.compat.node import InvalidParameterTypeException
        from turtletui.compat.parameter import Parameter, type_matches

        if name in node.parameters:
            expected = Parameter.Type.from_parameter_value(node.parameters[name])
            if expected is not Parameter.Type.NOT_SET and not type_matches(expected, value):
                # what the node would answer (unless it declared dynamic typing)
                return str(InvalidParameterTypeException(Parameter(name, value=value), expected))
        self._parameters.append(ParameterUpdate(wire_id, name, value))
        return None


def _subscriptions(deliveries: Sequence[Delivery], stamped: Sequence[StampedDelivery] = ()) -> Any:
    """What an exchange delivered messages for: one subscription's wire id, or
    a tuple of several."""
    ids = sorted({delivery.subscription for delivery in (*deliveries, *stamped)})
    return ids[0] if len(ids) == 1 else tuple(ids)


def _label(label: str) -> str:
    """A callback's name as the child declared it (only ever shown, so only a
    short identifier is kept)."""
    return label if label.isidentifier() and len(label) <= 60 else ""
