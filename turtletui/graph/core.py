"""A small deterministic ROS-like middleware: nodes, topics, services, actions, timers.

Time is simulated and kept in integer nanoseconds. ``Graph.advance()`` jumps to
the next due timer (turtlesim's 16 ms update timer is one of them), fires it,
and runs every callback that became ready until the graph is quiet. Callbacks
run in the order they became ready, so a run is the same every time.

Endpoints carry an ``owner``: the controller host they belong to. Hosts that
live in another process (the sandbox) register ``Remote`` endpoints whose
callbacks forward to the child instead of running here.
"""

from __future__ import annotations

import heapq
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Literal, NamedTuple, Protocol

from turtletui.errors import TurtletuiError
from turtletui.graph.action_endpoints import (
    ActionServiceEndpoint,
    ActionTopicEndpoint,
    service_endpoints,
    topic_endpoints,
)
from turtletui.graph.logs import INFO, WARN, LogRecord, to_log_message
from turtletui.graph.qos import incompatible_policy, is_transient_local, rclcpp_incompatible_qos

NS_PER_S = 1_000_000_000
LOCKSTEP_EPOCH_NS = 1_700_000_000 * NS_PER_S
"""ROS time at simulated t = 0 in lockstep runs: fixed, so logs repeat bit for bit."""
DISCOVERY_NS = 50_000_000
"""How long the processes of a run take to discover each other's new
publishers, subscriptions, services and clients (Graph.discovery_ns): Fast
DDS on one machine took 22 ms to 1.8 s to match a new publisher (Kilted,
rclpy 9.1, a quiet to a busy 2-core VM)."""

_RATE_WINDOW = 64
ROSOUT = "/rosout"
ROSOUT_ECHO_NS = 1_000_000
"""How long a line logged in a /rosout callback takes to reach /rosout's
subscriptions (about a round trip through rcl's logging and DDS on one
machine); every other line reaches them at once."""

_new_tuple = tuple.__new__
"""Makes a NamedTuple from a tuple without the Python-level ``__new__`` it adds
(a log record is made for every line a controller logs)."""

EndpointKind = Literal["publishers", "subscriptions", "services", "clients", "action_servers", "action_clients"]
"""What ``Graph.names_and_types_by_node`` lists."""


def _grouped(found: set[tuple[str, str]]) -> list[tuple[str, list[str]]]:
    """(name, type) pairs as rcl's names-and-types lists give them: sorted by
    name, each name once with its types (a topic may carry several)."""
    grouped: dict[str, list[str]] = {}
    for name, type_name in sorted(found):
        grouped.setdefault(name, []).append(type_name)
    return list(grouped.items())


class GraphError(TurtletuiError):
    """A request the middleware refuses (a service provided twice, an undeclared topic...)."""


class TopicTypeConflict(GraphError):
    """An endpoint of one process asked for a topic that process already uses
    with another type: a DDS participant refuses that, as Fast DDS does (rcl
    then raises RCLError). Other processes may use the name with any type."""

    def __init__(self, name: str, type_name: str, used: str) -> None:
        super().__init__(f"topic {name} is used here with type {used}, not {type_name}")
        self.name = name
        self.type_name = type_name
        """The type asked for."""
        self.used = used
        """The type this process already uses on the name."""


@dataclass(eq=False)
class NodeRecord:
    """A node in the graph, as ``ros2 node list`` sees it."""

    name: str
    namespace: str
    owner: str
    parameters: dict[str, Any] = field(default_factory=dict)
    alive: bool = True
    parameter_setter: Callable[[str, Any], str | None] | None = field(default=None, repr=False)
    """How ``ros2 param set`` reaches the node: ``setter(name, value)`` returns
    why it refused, or None; None when nothing outside the node can set them."""
    rclcpp: bool = False
    """A C++ node of the simulator's (turtlesim, teleop_turtle, rosbag2's):
    rclcpp warns in its log of its endpoints' QoS mismatches (a controller's
    nodes warn in rclpy's words themselves)."""

    @property
    def fqn(self) -> str:
        ns = self.namespace.rstrip("/")
        return f"{ns}/{self.name}"


class MessageOrigin(NamedTuple):
    """Where and when a queued message comes from, for a callback that takes
    rclpy's MessageInfo (see StampedQueue)."""

    source_ns: int
    """When it was published, in simulated ns since start."""
    received_ns: int
    """When it reached the subscription, in simulated ns since start."""
    sequence: int | None
    """Its publisher's count of messages it had published, this one included
    (None when no publisher record sent it: a bridged message)."""
    publisher: Publisher | bytes | None
    """The publisher's record, or its GID when it lives in another process."""


class StampedQueue(deque):
    """The queue of a subscription whose callback takes message info: each
    message waits as ``(msg, MessageOrigin)``. Its ``append`` stamps what
    Graph.publish hands it with the publish under way (Graph.sending), so
    that the publish loop does nothing more for other subscriptions."""

    def __init__(self, graph: Graph, depth: int) -> None:
        super().__init__(maxlen=max(depth, 1))
        self.graph = graph

    def append(self, msg: Any) -> None:
        graph = self.graph
        publisher = graph.sending
        now = graph.now_ns
        sequence = None if publisher is None else publisher.sequence
        deque.append(self, (msg, MessageOrigin(now, now, sequence, publisher)))

    def append_stamped(self, msg: Any, origin: MessageOrigin) -> None:
        """Queue ``msg`` from an earlier publish or another process."""
        deque.append(self, (msg, origin))


@dataclass(eq=False)
class Subscription:
    node: NodeRecord
    topic: Topic
    depth: int
    callback: Callable[[Any], None]
    owner: str
    qos: Any = None
    """The QoS the creator asked for, as it gave it (the graph keeps only ``depth``)."""
    copy: Callable[[Any], Any] | None = None
    """Makes the subscription's own copy of each message it queues, as a middleware
    that deserialises per subscription would, or takes only what its callback
    reads of it (turtlesim's velocity commands); None to queue the published object."""
    created_ns: int = 0
    """When it was made, in simulated ns (for discovery: Graph.discovery_ns)."""
    queue: deque = field(init=False)
    pending: bool = False
    ready_item: tuple = field(init=False, repr=False)
    """The ready-queue entry that delivers this subscription's queue (made once)."""

    def __post_init__(self) -> None:
        self.queue = deque(maxlen=max(self.depth, 1))
        self.ready_item = (self.owner, self.deliver)

    def deliver(self) -> None:
        """Hand the queued messages to the callback, oldest first."""
        self.pending = False
        queue = self.queue
        callback = self.callback
        popleft = queue.popleft
        while queue:
            callback(popleft())


@dataclass(eq=False)
class Publisher:
    node: NodeRecord
    topic: Topic
    depth: int
    owner: str
    qos: Any = None
    """The QoS the creator asked for, as it gave it."""
    created_ns: int = 0
    """When it was made, in simulated ns (for discovery: Graph.discovery_ns)."""
    muted: set = field(default_factory=set, repr=False)
    """The subscriptions it never reaches: their QoS is incompatible with its own."""
    sequence: int = 0
    """How many messages it has published: the last one's publication sequence
    number (rmw's MessageInfo counts each publisher's from 1)."""
    gid: bytes | None = field(default=None, repr=False)
    """Its GID once something asked for it (turtletui.compat.graph_info): a
    DDS GUID stays what it was when first seen."""
    kept: deque | None = field(init=False, repr=False)
    """A transient-local publisher's last ``depth`` messages, as (when published,
    message, its sequence number), for the transient-local subscriptions that
    join later; None for a volatile one."""

    def __post_init__(self) -> None:
        self.kept = deque(maxlen=max(self.depth, 1)) if is_transient_local(self.qos) else None


class Topic:
    """A named channel with one message type, its endpoints and a measured rate.

    Processes may use one name with several types, as in ROS 2: each type is a
    channel of its own (Graph.topics holds the first, Graph.retyped the
    others), and endpoints of different types never match."""

    __slots__ = (
        "name",
        "msg_type",
        "type_name",
        "publishers",
        "subscriptions",
        "count",
        "_stamps",
        "publishers_made",
    )

    def __init__(self, name: str, msg_type: type, type_name: str) -> None:
        self.name = name
        self.msg_type = msg_type
        self.type_name = type_name
        self.publishers: list[Publisher] = []
        self.subscriptions: list[Subscription] = []
        self.count = 0
        self._stamps: deque[int] = deque(maxlen=_RATE_WINDOW)
        self.publishers_made: dict[str, int] = {}
        """Owner -> publishers it created here, counting those since destroyed:
        its keys are every owner that ever had a publisher here."""

    def rate(self, now_ns: int) -> float:
        """Messages per simulated second over the last 64 messages (0 if idle for 2 s)."""
        stamps = self._stamps
        if len(stamps) < 2 or now_ns - stamps[-1] > 2 * NS_PER_S:
            return 0.0
        span = stamps[-1] - stamps[0]
        return (len(stamps) - 1) * NS_PER_S / span if span else 0.0


@dataclass(eq=False)
class Timer:
    node: NodeRecord
    period_ns: int
    callback: Callable[[], None]
    owner: str
    next_due: int | None
    """When it fires next, in simulated ns; None while it is off the simulated clock (Graph.park_timer)."""
    canceled: bool = False
    seq: int = 0
    queued: bool = False
    """Whether a call is in the ready queue, not yet taken: a timer due again
    meanwhile is not queued twice (rcl's timer is ready or not, and its call
    skips the periods it missed), so a callback that waited a second for an
    executor runs once, not once per period."""
    ready_item: tuple = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.ready_item = (self.owner, self.take)

    def take(self) -> None:
        """What the ready queue runs: the call taken (the timer may be queued again), then the callback."""
        self.queued = False
        self.callback()

    def reset(self, now_ns: int) -> None:
        self.canceled = False
        self.next_due = now_ns + self.period_ns


@dataclass(eq=False)
class Service:
    """A service server. ``handler(request, respond)`` calls ``respond(response)``,
    now or later (a sandboxed server answers in a later exchange)."""

    node: NodeRecord
    name: str
    srv_type: type
    type_name: str
    handler: Callable[[Any, Callable[[Any], None]], None]
    owner: str
    created_ns: int = 0
    """When it was made, in simulated ns (for discovery: Graph.discovery_ns)."""


@dataclass(eq=False)
class ServiceClient:
    node: NodeRecord
    name: str
    srv_type: type
    type_name: str
    owner: str
    created_ns: int = 0
    """When it was made, in simulated ns (for discovery: Graph.discovery_ns)."""


CANCEL_ACCEPTED, CANCEL_REJECTED, CANCEL_TERMINATED = 0, 1, 3
"""action_msgs/srv/CancelGoal return codes (ERROR_NONE, ERROR_REJECTED, ERROR_GOAL_TERMINATED)."""

_ACTIVE_GOAL = frozenset({"accepted", "executing", "canceling"})


def _ignore(*_: Any) -> None:
    """A goal callback nobody asked for."""


@dataclass(eq=False)
class GoalHandle:
    """The server side of one action goal.

    A server that answers goals itself (``ActionServer.answers``) finds its
    goals "pending" and calls ``accept()`` or ``reject()``, now or later; the
    others' goals start "executing". Every change reaches the client through
    the callbacks the graph gave the handle.
    """

    action: ActionServer
    goal_id: int
    goal: Any
    on_feedback: Callable[[Any], None]
    on_result: Callable[[str, Any], None]
    status: str = "executing"
    """pending, rejected, accepted, executing, canceling, succeeded, aborted or canceled."""
    cancel_requested: bool = False
    on_cancel: Callable[[], None] | None = None
    """What a cancel request does on a server that always accepts them."""
    decide_cancel: Callable[[Callable[..., None]], None] | None = None
    """How a server that may refuse decides: ``decide_cancel(decided)`` calls
    ``decided(accepted, refusal=CANCEL_REJECTED)``, now or later; ``refusal`` is
    the code a refused request gets. With neither, cancel requests are refused."""
    on_answer: Callable[[GoalHandle | None], None] = _ignore
    on_status: Callable[[str], None] = _ignore

    @property
    def active(self) -> bool:
        return self.status in _ACTIVE_GOAL

    def accept(self, status: str = "executing") -> None:
        """Accept a pending goal, as "accepted" or already "executing"."""
        if self.status == "pending" and status in ("accepted", "executing"):
            self.status = status
            self.on_answer(self)

    def reject(self) -> None:
        if self.status == "pending":
            self.status = "rejected"
            self.on_answer(None)

    def set_status(self, status: str) -> None:
        """Move an active goal to "executing" (from accepted) or "canceling"."""
        allowed = {"executing": ("accepted",), "canceling": ("accepted", "executing")}.get(status, ())
        if self.status in allowed:
            self.status = status
            self.on_status(status)

    def publish_feedback(self, feedback: Any) -> None:
        if self.active:
            self.on_feedback(feedback)

    def finish(self, status: str, result: Any) -> None:
        """End the goal as succeeded, aborted or canceled, sending its result."""
        if self.active:
            self.status = status
            self.on_result(status, result)

    def request_cancel(self, answer: Callable[[int, bool], None]) -> None:
        """A client asks to cancel the goal: ``answer(code, canceling)`` (a
        CancelGoal return code, and whether the goal is now canceling) runs
        once the server has decided."""
        if not self.active:
            answer(CANCEL_TERMINATED, False)
            return

        def decided(accepted: bool, refusal: int = CANCEL_REJECTED) -> None:
            if accepted and self.active:
                self.cancel_requested = True
                self.set_status("canceling")
                answer(CANCEL_ACCEPTED, True)
            else:
                answer(refusal, False)

        if self.decide_cancel is not None:
            self.decide_cancel(decided)
        elif self.on_cancel is not None:
            first = not self.cancel_requested
            decided(True)
            if first:
                self.on_cancel()
        else:
            answer(CANCEL_REJECTED, False)


@dataclass(eq=False)
class ActionServer:
    """``on_goal(handle)`` accepts a goal and later finishes it through the handle."""

    node: NodeRecord
    name: str
    action_type: type
    type_name: str
    on_goal: Callable[[GoalHandle], None]
    owner: str
    answers: bool = False
    """Whether the server accepts or rejects each goal itself (GoalHandle.accept);
    else every goal is accepted as soon as ``on_goal`` returns."""
    created_ns: int = 0
    """When it was made, in simulated ns (for discovery: Graph.discovery_ns)."""


@dataclass(eq=False)
class ActionClientRecord:
    node: NodeRecord
    name: str
    action_type: type
    type_name: str
    owner: str
    created_ns: int = 0
    """When it was made, in simulated ns (for discovery: Graph.discovery_ns)."""


class GraphOutbox(Protocol):
    """Told what a Graph's own nodes do when the graph is one part of a larger
    one (a sandboxed controller's: turtletui.runtime.outbox sends it all to the
    simulator). Records owned by ``remote_owner`` stand for the other part's:
    the outbox, not this graph, delivers what is published, called or sent to
    them."""

    remote_owner: str

    def declared(self, record: Any) -> None:
        """A node, publisher, subscription, timer, service, client, action server
        or action client was added."""

    def removed(self, record: Any) -> None:
        """A node was destroyed, or a publisher, subscription, service, client,
        action server or action client taken off the graph."""

    def parameter_set(self, node: NodeRecord, name: str, value: Any, remove: bool) -> None:
        """A node's parameter was set (or undeclared: ``remove``)."""

    def published(self, topic: Topic, msg: Any, publisher: Publisher | None, young: bool) -> None:
        """``msg`` was published (and delivered to this graph's subscriptions)
        by ``publisher``, which the other part has discovered unless
        ``young`` (then only kept: it is transient local). ``msg`` may be the
        publisher's own, which it may change once publish() returns: take
        what is sent of it now."""

    def call(self, service: Service, request: Any, on_response: Callable[[Any], None]) -> None:
        """A remote ``service`` is called; ``on_response`` is for its answer."""

    def send_goal(
        self,
        server: ActionServer,
        goal: Any,
        on_accepted: Callable[[GoalHandle | None], None],
        on_feedback: Callable[[Any], None],
        on_result: Callable[[str, Any], None],
        on_status: Callable[[str], None] | None,
    ) -> GoalHandle:
        """A goal is sent to a remote action ``server``: its handle here."""

    def cancel_goal(self, handle: GoalHandle, on_answer: Callable[[int, bool], None] | None) -> None:
        """Cancelling a goal of a remote action server is asked for."""

    def logged(self, record: LogRecord) -> None:
        """A log record was made."""


class Graph:
    """Nodes, topics, services, actions and timers sharing one simulated clock."""

    def __init__(
        self,
        *,
        epoch_ns: int = LOCKSTEP_EPOCH_NS,
        type_name: Callable[[type], str],
        type_description_names: tuple[tuple[str, str], ...] | None = (),
    ) -> None:
        self.now_ns = 0
        """Simulated nanoseconds since start."""
        self.epoch_ns = epoch_ns
        self.nodes: list[NodeRecord] = []
        self.topics: dict[str, Topic] = {}
        """Every topic by name: the channel of the type that came first (the one
        a name's tools show: echo, hz, the topic monitor, a recording)."""
        self.retyped: dict[str, list[Topic]] = {}
        """The channels of further types on names of ``topics``: endpoints of
        other processes that used the name with another type (see Topic)."""
        self.services: dict[str, Service] = {}
        self.clients: list[ServiceClient] = []
        self.action_servers: dict[str, ActionServer] = {}
        self.action_clients: list[ActionClientRecord] = []
        self.log_sinks: list[Callable[[LogRecord], None]] = []
        self.taps: list[Callable[[str, Any], None]] = []
        """Observers of everything: ``tap(kind, payload)`` with kind "topic"
        (topic, msg), "service" (name, request, response), "goal" (action name,
        goal) or "log" (record); a tap ignores kinds it does not know. Like
        another process, a tap does not see what a publisher no one has
        discovered yet sends (see ``discovery_ns``)."""
        self.record_everything = False
        """Whether a tap wants messages nobody subscribes to (turtlesim then
        publishes its colour sensor anyway): set while a run is recorded."""
        self.ready: deque[tuple[str, Callable[[], None]]] = deque()
        """Callbacks to run, each with the owner it runs for, in arrival order."""
        self.discovery_ns = 0
        """How long processes take to discover each other's new publishers and
        subscriptions, as DDS discovery does: a publisher and a subscription of
        different owners (processes) match ``discovery_ns`` after the younger
        of the two was made, and what is published before that is not
        delivered to it. Within one process they match at once (one DDS
        participant). 0: always at once; a run uses DISCOVERY_NS."""
        self._type_name = type_name
        self.type_description_names = type_description_names
        """How the distro names types in type descriptions (type_descriptions.Names:
        turtlesim's as turtlesim_msgs from Kilted on); None where nodes serve no
        ``~/get_type_description`` (Humble)."""
        self._timers: list[tuple[int, int, Timer]] = []
        self._seq = 0
        self._goal_ids = 0
        self.version = 0
        """Bumped by every change of who is on the graph (nodes, endpoints,
        services, clients, actions): a sandbox sends its child a new mirror
        of the graph when it moved."""
        self.outbox: GraphOutbox | None = None
        """Told what this graph's nodes do, when the graph is one part of a
        larger one (see GraphOutbox); None for a whole graph."""
        self.on_node: Callable[[NodeRecord], None] | None = None
        """Told of every node made (the simulation looks at a controller's
        endpoints a second after its nodes appear)."""
        self.on_endpoints: Callable[[], None] | None = None
        """Told after every publisher or subscription made or removed (the
        rclpy layer's matched events, turtletui.compat.matched_events)."""
        self.on_mismatch: Callable[[Publisher, Subscription, str], None] | None = None
        """Told of every publisher and subscription that match but for their
        QoS (with the policy's name), as DDS tells both sides: the rclpy layer
        warns its own endpoints of them (a C++ node's warn here, in _match)."""
        self.self_delivering: set[str] = set()
        """Owners whose endpoints live in another process that delivers between
        them itself (a sandboxed controller's): this graph gives them nothing
        of their own."""
        self._in_rosout_callback = 0
        """How many /rosout subscriptions are handing out messages right now."""
        self._rosout_later: list[tuple[LogRecord, tuple[str, str, int] | None]] = []
        """Lines logged in a /rosout callback, delivered ROSOUT_ECHO_NS later (see ``_to_rosout``)."""
        self.sending: Publisher | None = None
        """The publisher of the message ``publish`` is handing out (or last
        handed out), for the StampedQueue of a callback that takes message info."""

    def type_name_of(self, cls: type) -> str:
        """The full name of an interface class as this graph's distro has it
        (``turtlesim_msgs/msg/Pose`` from Kilted on)."""
        return self._type_name(cls)

    # -- time ---------------------------------------------------------------
    @property
    def t(self) -> float:
        """Simulated seconds since start."""
        return self.now_ns / NS_PER_S

    @property
    def stamp_ns(self) -> int:
        """ROS time now: the epoch plus simulated time."""
        return self.epoch_ns + self.now_ns

    def next_due(self) -> int | None:
        """When the next live timer fires, in simulated ns; None if there is none."""
        timers = self._timers
        while timers and (timers[0][2].canceled or timers[0][0] != timers[0][2].next_due):
            heapq.heappop(timers)
        return timers[0][0] if timers else None

    def advance(self, until_ns: int | None = None) -> bool:
        """Jump to the next due timer (not past ``until_ns``) and fire every timer
        due then. Returns False, leaving time at ``until_ns``, when none is due."""
        timers = self._timers
        while timers:
            due, seq, timer = timers[0]
            if timer.canceled or due != timer.next_due:
                heapq.heappop(timers)
                continue
            break
        else:
            if until_ns is not None and until_ns > self.now_ns:
                self.now_ns = until_ns
            return False
        if until_ns is not None and due > until_ns:
            if until_ns > self.now_ns:
                self.now_ns = until_ns
            return False
        now = self.now_ns
        if due > now:
            self.now_ns = now = due
        # The head is live and due: fire it, then any other timer due now.
        heapreplace = heapq.heapreplace
        ready = self.ready
        timer.next_due = next_due = due + timer.period_ns
        heapreplace(timers, (next_due, seq, timer))  # pop and push in one
        if not timer.queued:
            timer.queued = True
            ready.append(timer.ready_item)
        while timers[0][0] <= now:
            due, seq, timer = timers[0]
            if timer.canceled or due != timer.next_due:
                heapq.heappop(timers)
                if not timers:
                    break
                continue
            timer.next_due = next_due = due + timer.period_ns
            heapreplace(timers, (next_due, seq, timer))
            if not timer.queued:
                timer.queued = True
                ready.append(timer.ready_item)
        return True

    def run_ready(self) -> None:
        """Run ready callbacks until none is left."""
        ready = self.ready
        while ready:
            ready.popleft()[1]()

    # -- nodes --------------------------------------------------------------
    def add_node(
        self,
        name: str,
        namespace: str = "",
        owner: str = "local",
        *,
        parameter_setter: Callable[[str, Any], str | None] | None = None,
        rclcpp: bool = False,
    ) -> NodeRecord:
        """A new node; ``parameter_setter`` is how ``ros2 param set`` reaches it
        (see NodeRecord.parameter_setter); ``rclcpp`` for a C++ node of the
        simulator's (see NodeRecord.rclcpp)."""
        self.version += 1
        node = NodeRecord(name, namespace or "", owner, parameter_setter=parameter_setter, rclcpp=rclcpp)
        self.nodes.append(node)
        if self.outbox is not None:
            self.outbox.declared(node)
        if self.on_node is not None:
            self.on_node(node)
        return node

    def remove_node(self, node: NodeRecord) -> None:
        """Destroy a node and every endpoint it owns."""
        self.version += 1
        node.alive = False
        if node in self.nodes:
            self.nodes.remove(node)
        for topic in self.channels():
            topic.publishers = [p for p in topic.publishers if p.node is not node]
            for sub in topic.subscriptions:
                if sub.node is node:
                    sub.queue.clear()  # nothing more reaches a destroyed node
            topic.subscriptions = [s for s in topic.subscriptions if s.node is not node]
            self._drop_if_unused(topic)
        for name in [n for n, s in self.services.items() if s.node is node]:
            del self.services[name]
        for name in [n for n, a in self.action_servers.items() if a.node is node]:
            del self.action_servers[name]
        self.clients = [c for c in self.clients if c.node is not node]
        self.action_clients = [c for c in self.action_clients if c.node is not node]
        for _, _, timer in self._timers:
            if timer.node is node:
                timer.canceled = True
        if self.outbox is not None:
            self.outbox.removed(node)
        if self.on_endpoints is not None:
            self.on_endpoints()

    def set_parameter(self, node: NodeRecord, name: str, value: Any, *, remove: bool = False) -> None:
        """Record a node's parameter value (what ``ros2 param get`` shows)."""
        if remove:
            node.parameters.pop(name, None)
        else:
            node.parameters[name] = value
        if self.outbox is not None:
            self.outbox.parameter_set(node, name, value, remove)

    def remove_owner(self, owner: str) -> None:
        """Destroy every node of one controller host (it ended or crashed)."""
        for node in [n for n in self.nodes if n.owner == owner]:
            self.remove_node(node)
        # In place: the pump loop holds a reference to this deque.
        kept = [item for item in self.ready if item[0] != owner]
        self.ready.clear()
        self.ready.extend(kept)

    def node_names_and_namespaces(self) -> list[tuple[str, str]]:
        """(name, namespace) of every node, in creation order; the root namespace is "/"."""
        return [(node.name, node.namespace or "/") for node in self.nodes]

    def find_node(self, name: str, namespace: str) -> NodeRecord | None:
        """The live node called ``name`` in ``namespace`` ("/" or "" for the root)."""
        namespace = namespace.rstrip("/")
        for node in self.nodes:
            if node.name == name and node.namespace.rstrip("/") == namespace:
                return node
        return None

    def names_and_types_by_node(self, node: NodeRecord, kind: EndpointKind) -> list[tuple[str, list[str]]]:
        """The names and types of one kind of endpoint ``node`` has, sorted by name
        (with the hidden ones behind its actions: ``action_topic_endpoints``...)."""
        if kind == "publishers":
            found = {(t.name, t.type_name) for t in self.channels() for p in t.publishers if p.node is node}
        elif kind == "subscriptions":
            found = {(t.name, t.type_name) for t in self.channels() for s in t.subscriptions if s.node is node}
        else:
            records = {
                "services": self.services.values(),
                "clients": self.clients,
                "action_servers": self.action_servers.values(),
                "action_clients": self.action_clients,
            }[kind]
            found = {(r.name, r.type_name) for r in records if r.node is node}
        if kind == "publishers" or kind == "subscriptions":
            found.update((e.topic.name, e.topic.type_name) for e in self.action_topic_endpoints(kind) if e.node is node)
        elif kind == "services" or kind == "clients":
            found.update((e.name, e.type_name) for e in self.action_service_endpoints(kind) if e.node is node)
        return _grouped(found)

    # rcl_action's endpoints behind every action (turtletui.graph.action_endpoints):
    # derived from the action records, so that every host answers the same.
    def action_topic_endpoints(self, kind: Literal["publishers", "subscriptions"]) -> list[ActionTopicEndpoint]:
        """The feedback and status publishers of every action server, or the
        subscriptions of every action client."""
        records = self.action_servers.values() if kind == "publishers" else self.action_clients
        return [endpoint for record in records for endpoint in topic_endpoints(record)]

    def action_service_endpoints(self, kind: Literal["services", "clients"]) -> list[ActionServiceEndpoint]:
        """The send_goal, cancel_goal and get_result servers of every action
        server, or the clients of every action client."""
        records = self.action_servers.values() if kind == "services" else self.action_clients
        return [endpoint for record in records for endpoint in service_endpoints(record)]

    # -- topics -------------------------------------------------------------
    def channels(self) -> list[Topic]:
        """Every topic channel, of every type, by name (first type first)."""
        retyped = self.retyped
        if not retyped:
            return list(self.topics.values())
        return [t for name, first in self.topics.items() for t in (first, *retyped.get(name, ()))]

    def channels_of(self, name: str) -> list[Topic]:
        """The channels of topic ``name``: one per type in use, first type first."""
        first = self.topics.get(name)
        return [] if first is None else [first, *self.retyped.get(name, ())]

    def topic(self, name: str, msg_type: type, owner: str | None = None) -> Topic:
        """The channel of topic ``name`` with type ``msg_type``, created if new.
        Raises TopicTypeConflict when ``owner`` (a process; not the other part
        of the graph, which stands for many) already uses the name with
        another type."""
        channels = self.channels_of(name)
        found = None
        for channel in channels:
            if channel.msg_type is msg_type:
                found = channel
            elif owner is not None and (self.outbox is None or owner != self.outbox.remote_owner) and any(
                e.owner == owner for e in (*channel.publishers, *channel.subscriptions)
            ):
                raise TopicTypeConflict(name, self._type_name(msg_type), channel.type_name)
        if found is not None:
            return found
        topic = Topic(name, msg_type, self._type_name(msg_type))
        if channels:
            self.retyped.setdefault(name, []).append(topic)
        else:
            self.topics[name] = topic
        return topic

    def add_publisher(
        self, node: NodeRecord, name: str, msg_type: type, depth: int, *, qos: Any = None
    ) -> Publisher:
        topic = self.topic(name, msg_type, node.owner)
        self.version += 1
        pub = Publisher(node, topic, depth, node.owner, qos, self.now_ns)
        topic.publishers.append(pub)
        topic.publishers_made[node.owner] = topic.publishers_made.get(node.owner, 0) + 1
        if self.outbox is not None:
            self.outbox.declared(pub)
        for sub in topic.subscriptions:
            self._match(pub, sub)
        if self.on_endpoints is not None:
            self.on_endpoints()
        return pub

    def add_subscription(
        self,
        node: NodeRecord,
        name: str,
        msg_type: type,
        depth: int,
        callback: Callable[[Any], None],
        *,
        qos: Any = None,
        copy: Callable[[Any], Any] | None = None,
        delivery: Callable[[Subscription], Callable[[], None]] | None = None,
        stamped: bool = False,
    ) -> Subscription:
        """Subscribe ``callback`` to topic ``name``; with ``copy``, each message is
        queued as ``copy(msg)``, the subscription's own (see Subscription.copy).
        ``delivery(sub)``, if given, makes what hands ``sub``'s queue to the
        callback in place of Subscription.deliver: the same steps fused with
        the callback's own layers (it clears ``sub.pending`` first, then
        takes the messages oldest first). ``stamped``: each message is queued
        and handed out as ``(msg, MessageOrigin)`` (see StampedQueue)."""
        topic = self.topic(name, msg_type, node.owner)
        self.version += 1
        sub = Subscription(node, topic, depth, callback, node.owner, qos, copy, self.now_ns)
        if stamped:
            sub.queue = StampedQueue(self, depth)
        deliver = sub.deliver if delivery is None else delivery(sub)
        if name == ROSOUT:
            deliver = self._counted_rosout_delivery(deliver)
        sub.ready_item = (sub.owner, deliver)
        topic.subscriptions.append(sub)
        if self.outbox is not None:
            self.outbox.declared(sub)
        for pub in topic.publishers:
            self._match(pub, sub)
        if self.on_endpoints is not None:
            self.on_endpoints()
        return sub

    def _match(self, pub: Publisher, sub: Subscription) -> None:
        """Match a new publisher or subscription with an endpoint of its topic:
        an incompatible QoS mutes the pair; a transient-local subscription
        gets what a transient-local publisher kept once the two have
        discovered each other (at once in one process), as DDS does. A
        C++ node's side of a mismatch logs rclcpp's warning."""
        policy = incompatible_policy(pub.qos, sub.qos)
        if policy:
            pub.muted.add(sub)
            for record in (pub, sub):
                if record.node.rclcpp:
                    self.log(record.node.name, WARN, rclcpp_incompatible_qos(record is pub, pub.topic.name, policy))
            if self.on_mismatch is not None:
                self.on_mismatch(pub, sub, policy)
            return
        if pub.kept is None or not is_transient_local(sub.qos):
            return
        remote = self.outbox.remote_owner if self.outbox is not None else None
        if remote in (pub.owner, sub.owner):
            return  # the other part of the graph gives those
        if pub.owner == sub.owner:
            if pub.owner not in self.self_delivering:
                self._give_kept(pub, sub, self.now_ns + 1)
        elif self.discovery_ns <= 0:
            self._give_kept(pub, sub, self.now_ns + 1)
        else:
            at = self.discovered_at(pub, sub)
            self.call_later(sub.node, at - self.now_ns, lambda: self._give_kept(pub, sub, at))

    def _give_kept(self, pub: Publisher, sub: Subscription, before_ns: int) -> None:
        """Queue for ``sub`` what ``pub`` kept from before ``before_ns`` (later
        messages reached it as they were published)."""
        topic = pub.topic
        if pub not in topic.publishers or sub not in topic.subscriptions or sub in pub.muted:
            return
        copy = sub.copy
        queue = sub.queue
        given = False
        for stamp, msg, sequence in pub.kept or ():
            if stamp < before_ns:
                msg = msg if copy is None else copy(msg)
                if type(queue) is StampedQueue:
                    queue.append_stamped(msg, MessageOrigin(stamp, self.now_ns, sequence, pub))
                else:
                    queue.append(msg)
                given = True
        if given and not sub.pending:
            sub.pending = True
            self.ready.append(sub.ready_item)

    def remove_endpoint(self, endpoint: Publisher | Subscription) -> bool:
        """Take a publisher or subscription off its topic; False if it was not on it."""
        self.version += 1
        topic = endpoint.topic
        if isinstance(endpoint, Publisher):
            kept = [p for p in topic.publishers if p is not endpoint]
            removed = len(kept) != len(topic.publishers)
            topic.publishers = kept
        else:
            kept = [s for s in topic.subscriptions if s is not endpoint]
            removed = len(kept) != len(topic.subscriptions)
            topic.subscriptions = kept
            endpoint.queue.clear()
        self._drop_if_unused(topic)
        if removed and self.outbox is not None:
            self.outbox.removed(endpoint)
        if removed and self.on_endpoints is not None:
            self.on_endpoints()
        return removed

    def drop_unused_topics(self) -> None:
        """Every topic with no endpoints left leaves the graph (see _drop_if_unused)."""
        for topic in self.channels():
            self._drop_if_unused(topic)

    def _drop_if_unused(self, topic: Topic) -> None:
        """A topic channel with no endpoints left leaves the graph, as in ROS 2:
        it may come back with another type, and the topics of thousands of
        spawned and killed turtles cost nothing. The next type on the name,
        if any, becomes its first."""
        if topic.publishers or topic.subscriptions:
            return
        name = topic.name
        others = self.retyped.get(name)
        if self.topics.get(name) is topic:
            if others:
                self.topics[name] = others.pop(0)
            else:
                del self.topics[name]
        elif others and topic in others:
            others.remove(topic)
        if others is not None and not others:
            del self.retyped[name]

    def topic_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every topic someone publishes or subscribes to, with its type, sorted by
        name; the hidden topics of actions included (``action_topic_endpoints``)."""
        found = {(topic.name, topic.type_name) for topic in self.channels() if topic.publishers or topic.subscriptions}
        for kind in ("publishers", "subscriptions"):
            found.update((e.topic.name, e.topic.type_name) for e in self.action_topic_endpoints(kind))
        return _grouped(found)

    def publishers_of(self, name: str) -> list[Publisher | ActionTopicEndpoint]:
        """The publishers on topic ``name`` (none for an unknown topic), oldest
        first, then an action server's if it is one of its hidden topics."""
        return self._topic_endpoints(name, "publishers")

    def subscriptions_of(self, name: str) -> list[Subscription | ActionTopicEndpoint]:
        """The subscriptions of topic ``name`` (none for an unknown topic), oldest
        first, then the action clients' if it is one of their hidden topics."""
        return self._topic_endpoints(name, "subscriptions")

    def _topic_endpoints(self, name: str, kind: Literal["publishers", "subscriptions"]) -> list[Any]:
        """A topic's publishers or subscriptions: its own, then those of actions."""
        channels = self.channels_of(name)
        own = [e for topic in channels for e in getattr(topic, kind)]
        if len(channels) > 1:
            own.sort(key=lambda e: e.created_ns)  # oldest first, whatever their type
        return own + [e for e in self.action_topic_endpoints(kind) if e.topic.name == name]

    def discovered_at(self, one: Any, other: Any) -> int:
        """When two records of different owners (processes) have discovered
        each other: ``discovery_ns`` after the younger was made."""
        return max(one.created_ns, other.created_ns) + self.discovery_ns

    def known_to_others(self, record: Any) -> bool:
        """Whether every other process has discovered ``record`` by now."""
        return record.created_ns + self.discovery_ns <= self.now_ns

    def matched(self, pub: Publisher, sub: Subscription) -> bool:
        """Whether ``pub`` and ``sub`` have discovered each other (QoS aside)."""
        return pub.owner == sub.owner or self.discovered_at(pub, sub) <= self.now_ns

    def count_publishers(self, name: str) -> int:
        """How many publishers topic ``name`` has (an action server's hidden ones included)."""
        return len(self.publishers_of(name))

    def count_subscribers(self, name: str) -> int:
        """How many subscriptions topic ``name`` has (action clients' hidden ones included)."""
        return len(self.subscriptions_of(name))

    def publish(
        self,
        topic: Topic,
        msg: Any,
        source: str | None = None,
        publisher: Publisher | None = None,
        *,
        young: bool | None = None,
        fresh: bool = False,
        snapshot: Callable[[Any], Any] | None = None,
    ) -> None:
        """Deliver ``msg`` to every subscription of ``topic`` that has discovered
        ``publisher`` (see ``discovery_ns``; without one, the subscription's own
        age decides) and whose QoS matches its own, except those owned by
        ``source`` (a sandboxed host already delivered to its own subscribers).
        ``young`` says whether the other processes have yet to discover the
        publisher, when the caller knows better (the sandboxed host decided).

        ``fresh`` says the caller made ``msg`` for this call and will not
        change it: when the topic's one subscription would get a copy of its
        own and nothing else keeps ``msg`` (no tap, no transient-local
        history, no other part of the graph), it gets ``msg`` itself, a copy
        saved on every pose turtlesim publishes.

        ``snapshot`` says ``msg`` stays the caller's, who may change it after
        this call (rclpy's publish()): ``snapshot(msg)`` copies it once for
        whatever keeps it (a tap, a transient-local history, a subscription
        without a copy function of its own), and nothing is copied when
        nothing keeps it (turtlesim takes only the values it reads of a
        Twist: TurtlesimNode; the outbox to the other part of the graph
        takes the values it sends)."""
        outbox = self.outbox
        if outbox is not None:
            source = outbox.remote_owner  # the outbox delivers to those
        now = self.now_ns
        settled = now - self.discovery_ns  # endpoints made by then: discovered by all
        if publisher is None:
            owner = source
            muted = ()
            young = bool(young)
        else:
            owner = publisher.owner
            muted = publisher.muted
            publisher.sequence += 1
            if young is None:
                young = publisher.created_ns > settled
            if publisher.kept is not None:
                if snapshot is not None:
                    msg, snapshot = snapshot(msg), None
                publisher.kept.append((now, msg, publisher.sequence))
                fresh = False  # kept for late joiners: every subscription gets a copy
        self.sending = publisher
        if not young:  # others count only what reaches them (a sandboxed host forwards nothing young)
            topic.count += 1
            topic._stamps.append(now)
        if snapshot is not None and self.taps:
            msg, snapshot = snapshot(msg), None
        subscriptions = topic.subscriptions
        if fresh and (len(subscriptions) != 1 or self.taps or outbox is not None):
            fresh = False  # msg may be shared or kept: every subscription gets a copy
        ready = self.ready
        for sub in subscriptions:
            if (
                (sub.owner != owner and (young or sub.created_ns > settled))
                or (source is not None and sub.owner == source)
                or (muted and sub in muted)
            ):
                continue
            copy = sub.copy
            if copy is None:
                if snapshot is not None:
                    msg, snapshot = snapshot(msg), None
                sub.queue.append(msg)
            else:
                sub.queue.append(msg if fresh else copy(msg))
            if not sub.pending:
                sub.pending = True
                ready.append(sub.ready_item)
        if self.taps and not young:
            for tap in self.taps:
                tap("topic", (topic, msg))
        if outbox is not None and (not young or (publisher is not None and publisher.kept is not None)):
            # a young publisher's messages reach no other process yet; the
            # other part keeps a transient-local one's for late joiners
            outbox.published(topic, msg, publisher, young)

    # -- timers -------------------------------------------------------------
    def add_timer(
        self, node: NodeRecord, period_ns: int, callback: Callable[[], None], *, autostart: bool = True
    ) -> Timer:
        """A timer calling ``callback`` every ``period_ns``; with ``autostart=False``
        it starts canceled (``reset_timer`` starts it)."""
        if period_ns <= 0:
            raise GraphError(f"timer period must be positive, got {period_ns / NS_PER_S} s")
        self._seq += 1
        timer = Timer(node, period_ns, callback, node.owner, self.now_ns + period_ns, seq=self._seq)
        if autostart:
            heapq.heappush(self._timers, (timer.next_due, timer.seq, timer))
        else:
            timer.canceled = True
        if self.outbox is not None:
            self.outbox.declared(timer)
        return timer

    def call_later(self, node: NodeRecord, delay_ns: int, callback: Callable[[], None]) -> Timer:
        """A timer that fires once, ``delay_ns`` from now (cancel it to call nothing)."""
        holder: list[Timer] = []

        def fire() -> None:
            holder[0].canceled = True
            callback()

        holder.append(self.add_timer(node, delay_ns, fire))
        return holder[0]

    def cancel_timer(self, timer: Timer) -> None:
        """Stop a timer (``reset_timer`` starts it again)."""
        timer.canceled = True

    def park_timer(self, timer: Timer) -> None:
        """Take ``timer`` off the simulated clock: the graph no longer fires it
        (a node's /clock does: turtletui.compat.timer); ``schedule_timer`` puts it back."""
        timer.next_due = None  # its entry in the heap is stale now

    def schedule_timer(self, timer: Timer, due_ns: int) -> None:
        """Put ``timer`` (back) on the simulated clock, next due at ``due_ns``."""
        timer.next_due = due_ns
        if not timer.canceled:
            heapq.heappush(self._timers, (due_ns, timer.seq, timer))

    def reset_timer(self, timer: Timer) -> None:
        """Restart a timer: its next call is one period from now."""
        timer.reset(self.now_ns)
        heapq.heappush(self._timers, (timer.next_due, timer.seq, timer))

    # -- services -----------------------------------------------------------
    def add_service(
        self,
        node: NodeRecord,
        name: str,
        srv_type: type,
        handler: Callable[[Any, Callable[[Any], None]], None],
    ) -> Service:
        self.version += 1
        if name in self.services:
            raise GraphError(f"service {name} is already provided by {self.services[name].node.fqn}")
        service = Service(node, name, srv_type, self._type_name(srv_type), handler, node.owner, self.now_ns)
        self.services[name] = service
        if self.outbox is not None:
            self.outbox.declared(service)
        return service

    def remove_service(self, service: Service) -> bool:
        """Take a service server off the graph: calls queued to it stay
        unanswered, as in ROS. False if it was not on the graph."""
        self.version += 1
        if self.services.get(service.name) is not service:
            return False
        del self.services[service.name]
        if self.outbox is not None:
            self.outbox.removed(service)
        return True

    def has_service(self, name: str) -> bool:
        """Whether a server provides service ``name`` (``service_is_ready``)."""
        return name in self.services

    def service_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every service with a server or a client, with its type, sorted by name;
        the hidden services of actions included (``action_service_endpoints``)."""
        found = {(name, s.type_name) for name, s in self.services.items()}
        found.update((c.name, c.type_name) for c in self.clients)
        for kind in ("services", "clients"):
            found.update((e.name, e.type_name) for e in self.action_service_endpoints(kind))
        return _grouped(found)

    def service_matched(self, client: ServiceClient) -> bool:
        """Whether ``client`` has discovered the server of its service (and the
        server the client): requests sent before that are lost, as in ROS 2."""
        return self._server_matched(self.services.get(client.name), client)

    def count_services(self, name: str) -> int:
        """How many servers service ``name`` has (an action server's hidden ones included)."""
        hidden = sum(1 for e in self.action_service_endpoints("services") if e.name == name)
        return (1 if name in self.services else 0) + hidden

    def count_clients(self, name: str) -> int:
        """How many clients service ``name`` has (action clients' hidden ones included)."""
        hidden = sum(1 for e in self.action_service_endpoints("clients") if e.name == name)
        return sum(1 for c in self.clients if c.name == name) + hidden

    def add_client(self, node: NodeRecord, name: str, srv_type: type) -> ServiceClient:
        self.version += 1
        client = ServiceClient(node, name, srv_type, self._type_name(srv_type), node.owner, self.now_ns)
        self.clients.append(client)
        if self.outbox is not None:
            self.outbox.declared(client)
        return client

    def remove_client(self, client: ServiceClient) -> bool:
        """Take a service client off the graph; False if it was not on it."""
        self.version += 1
        if client not in self.clients:
            return False
        self.clients.remove(client)
        if self.outbox is not None:
            self.outbox.removed(client)
        return True

    def call(self, name: str, request: Any, on_response: Callable[[Any], None], owner: str) -> None:
        """Queue a call of service ``name``; ``on_response`` runs for ``owner`` with
        the response. A call to a service that does not exist is never answered,
        as in ROS."""
        service = self.services.get(name)
        if service is None:
            return
        if self.outbox is not None and service.owner == self.outbox.remote_owner:
            self.outbox.call(service, request, on_response)
            return

        def respond(response: Any) -> None:
            if self.taps:
                for tap in self.taps:
                    tap("service", (name, request, response))
            self.ready.append((owner, lambda: on_response(response)))

        def handle() -> None:
            if self.services.get(name) is service:  # not destroyed meanwhile
                service.handler(request, respond)

        self.ready.append((service.owner, handle))

    # -- actions ------------------------------------------------------------
    def add_action_server(
        self,
        node: NodeRecord,
        name: str,
        action_type: type,
        on_goal: Callable[[GoalHandle], None],
        *,
        answers: bool = False,
    ) -> ActionServer:
        """A server of action ``name``; with ``answers`` it accepts or rejects
        each goal itself (see ActionServer.answers)."""
        self.version += 1
        if name in self.action_servers:
            raise GraphError(f"action {name} is already provided by {self.action_servers[name].node.fqn}")
        server = ActionServer(
            node, name, action_type, self._type_name(action_type), on_goal, node.owner, answers, self.now_ns
        )
        self.action_servers[name] = server
        if self.outbox is not None:
            self.outbox.declared(server)
        return server

    def remove_action_server(self, server: ActionServer) -> bool:
        """Take an action server off the graph; False if it was not on it."""
        self.version += 1
        if self.action_servers.get(server.name) is not server:
            return False
        del self.action_servers[server.name]
        if self.outbox is not None:
            self.outbox.removed(server)
        return True

    def has_action_server(self, name: str) -> bool:
        """Whether a server provides action ``name`` (``server_is_ready``)."""
        return name in self.action_servers

    def action_matched(self, client: ActionClientRecord) -> bool:
        """Whether ``client`` has discovered the server of its action (and the
        server the client): goals sent before that are lost, as in ROS 2."""
        return self._server_matched(self.action_servers.get(client.name), client)

    def _server_matched(self, server: Service | ActionServer | None, client: Any) -> bool:
        if server is None:
            return False
        return server.owner == client.owner or self.discovered_at(server, client) <= self.now_ns

    def action_names_and_types(self) -> list[tuple[str, list[str]]]:
        """Every action with a server or a client, with its type, sorted by name."""
        found = {(name, a.type_name) for name, a in self.action_servers.items()}
        found.update((c.name, c.type_name) for c in self.action_clients)
        return [(name, [type_name]) for name, type_name in sorted(found)]

    def add_action_client(self, node: NodeRecord, name: str, action_type: type) -> ActionClientRecord:
        self.version += 1
        client = ActionClientRecord(node, name, action_type, self._type_name(action_type), node.owner, self.now_ns)
        self.action_clients.append(client)
        if self.outbox is not None:
            self.outbox.declared(client)
        return client

    def remove_action_client(self, client: ActionClientRecord) -> bool:
        """Take an action client off the graph; False if it was not on it."""
        self.version += 1
        if client not in self.action_clients:
            return False
        self.action_clients.remove(client)
        if self.outbox is not None:
            self.outbox.removed(client)
        return True

    def send_goal(
        self,
        name: str,
        goal: Any,
        owner: str,
        on_accepted: Callable[[GoalHandle | None], None],
        on_feedback: Callable[[Any], None],
        on_result: Callable[[str, Any], None],
        on_status: Callable[[str], None] | None = None,
    ) -> GoalHandle | None:
        """Queue a goal for action ``name``; replies run for ``owner``:
        ``on_accepted(handle)`` (None if rejected), ``on_status`` when it moves
        to executing or canceling, feedback, and the result. Returns the
        goal's handle; None when no server has the action (as in ROS, the goal
        is then never answered)."""
        server = self.action_servers.get(name)
        if server is None:
            return None
        if self.outbox is not None and server.owner == self.outbox.remote_owner:
            return self.outbox.send_goal(server, goal, on_accepted, on_feedback, on_result, on_status)
        if self.taps:
            for tap in self.taps:
                tap("goal", (name, goal))
        self._goal_ids += 1
        ready = self.ready

        def reply(callback: Callable[..., None]) -> Callable[..., None]:
            return lambda *args: ready.append((owner, lambda: callback(*args)))

        handle = GoalHandle(
            server,
            self._goal_ids,
            goal,
            on_feedback=reply(on_feedback),
            on_result=reply(on_result),
            status="pending" if server.answers else "executing",
            on_answer=reply(on_accepted),
            on_status=_ignore if on_status is None else reply(on_status),
        )

        def accept() -> None:
            server.on_goal(handle)
            if not server.answers:
                handle.on_answer(handle)

        ready.append((server.owner, accept))
        return handle

    def cancel_goal(
        self, handle: GoalHandle, owner: str | None = None, on_answer: Callable[[int, bool], None] | None = None
    ) -> None:
        """Ask the server to cancel a goal; ``on_answer(code, canceling)`` (see
        GoalHandle.request_cancel) then runs for ``owner``."""
        if self.outbox is not None and handle.action.owner == self.outbox.remote_owner:
            self.outbox.cancel_goal(handle, on_answer)
            return
        ready = self.ready

        def answer(code: int, canceling: bool) -> None:
            if on_answer is not None:
                ready.append((owner or handle.action.owner, lambda: on_answer(code, canceling)))

        ready.append((handle.action.owner, lambda: handle.request_cancel(answer)))

    # -- logs ---------------------------------------------------------------
    def log(
        self,
        node: str,
        level: int,
        msg: str,
        origin: tuple[str, str, int] | Callable[[], tuple[str, str, int]] | None = None,
        *,
        in_callback: bool = True,
        call: int = 0,
    ) -> LogRecord:
        """Log ``msg`` as the logger ``node``; ``origin`` is the call site
        (file, function, line) that /rosout subscriptions see, or what finds
        it, called only when one will (see ``hears_rosout``); ``in_callback``
        whether an executor's callback logged it, ``call`` which call (LogRecord)."""
        now = self.now_ns
        record = _new_tuple(LogRecord, (self.epoch_ns + now, now / NS_PER_S, level, node, msg, in_callback, call))
        # Taps (the recorder) first: a line a Ctrl-C cuts short after it was
        # shown (sinks print it) is in the record too.
        if self.taps:
            for tap in self.taps:
                tap("log", record)
        for sink in self.log_sinks:
            sink(record)
        if self.outbox is not None:
            self.outbox.logged(record)
        rosout = self.topics.get(ROSOUT)
        if rosout is not None and rosout.subscriptions:
            self._to_rosout(rosout, record, origin() if callable(origin) else origin)
        return record

    def hears_rosout(self) -> bool:
        """Whether a subscription listens on /rosout (a logger then says where it was called)."""
        rosout = self.topics.get(ROSOUT)
        return rosout is not None and bool(rosout.subscriptions)

    def _to_rosout(
        self, topic: Topic, record: LogRecord, origin: tuple[str, str, int] | None, *, now: bool = False
    ) -> None:
        """Deliver ``record`` as an rcl_interfaces/msg/Log from its node's /rosout
        publisher, as rcl_logging_rosout does (a child logger ``node.part``
        through its node's; a logger of no node, or of a node without /rosout,
        reaches nobody). Each graph delivers the lines of its own nodes to its
        own subscriptions; the trusted graph also every line to the
        subscriptions of other processes (a sandboxed child sends its lines).

        A line logged in a /rosout callback is delivered ROSOUT_ECHO_NS later,
        not at once: a node that logs whatever it hears there floods its log
        as on ROS 2 instead of looping for ever in one instant (and its log
        budget stops the flood)."""
        publisher = self._rosout_publisher(topic, record.node)
        if publisher is None:
            return
        if self._in_rosout_callback and not now:
            if not self._rosout_later:
                self.soon(publisher.node, ROSOUT_ECHO_NS, self._deliver_rosout_later)
            self._rosout_later.append((record, origin))
            return
        msg = to_log_message(record, origin)
        remote = self.outbox.remote_owner if self.outbox is not None else None
        publisher.sequence += 1
        self.sending = publisher
        if publisher.kept is not None:
            publisher.kept.append((self.now_ns, msg, publisher.sequence))
        own = publisher.owner
        ready = self.ready
        for sub in topic.subscriptions:
            if sub.owner == remote or (sub.owner == own and own in self.self_delivering):
                continue  # delivered by the process they live in
            if sub in publisher.muted or not self.matched(publisher, sub):
                continue
            sub.queue.append(msg if sub.copy is None else sub.copy(msg))
            if not sub.pending:
                sub.pending = True
                ready.append(sub.ready_item)

    def _counted_rosout_delivery(self, deliver: Callable[[], None]) -> Callable[[], None]:
        def counted() -> None:
            self._in_rosout_callback += 1
            try:
                deliver()
            finally:
                self._in_rosout_callback -= 1

        return counted

    def soon(self, node: NodeRecord, delay_ns: int, callback: Callable[[], None]) -> None:
        """Call ``callback`` once, ``delay_ns`` from now, as a timer of ``node``
        that no other process is told of (the graph's own business, or a note
        turtletui's rclpy makes later: turtletui.compat.dispatch)."""
        self._seq += 1
        timer = Timer(node, delay_ns, callback, node.owner, self.now_ns + delay_ns, seq=self._seq)

        def once() -> None:
            timer.canceled = True
            callback()

        timer.ready_item = (node.owner, once)
        heapq.heappush(self._timers, (timer.next_due, timer.seq, timer))

    def _deliver_rosout_later(self) -> None:
        later, self._rosout_later = self._rosout_later, []
        rosout = self.topics.get(ROSOUT)
        if rosout is not None:
            for record, origin in later:
                self._to_rosout(rosout, record, origin, now=True)

    def _rosout_publisher(self, topic: Topic, logger: str) -> Publisher | None:
        """The /rosout publisher of the node whose logger is ``logger`` or its parent's."""
        by_logger = {}
        remote = self.outbox.remote_owner if self.outbox is not None else None
        for pub in topic.publishers:
            if pub.owner == remote:
                continue  # a child logs for its own nodes only
            node = pub.node
            name = f"{node.namespace.strip('/').replace('/', '.')}.{node.name}".lstrip(".")
            by_logger.setdefault(name, pub)
        while True:
            found = by_logger.get(logger)
            if found is not None or "." not in logger:
                return found
            logger = logger.rsplit(".", 1)[0]

    def info(self, node: str, msg: str) -> LogRecord:
        return self.log(node, INFO, msg)
