"""The parent's graph as a sandboxed controller sees it.

A controller in the sandbox has its own nodes in its own Graph; everyone
else's (turtlesim's, other controllers') live in the parent. Whenever the
parent's graph changed, the next exchange carries a :class:`GraphMirror` of
it, and the child rebuilds the records of everyone else's nodes, endpoints,
services and actions from it (owned by :data:`MIRROR_OWNER`). Graph queries
in the child then answer as they do in-process. Updates come with the
lockstep exchanges, so at the same instants in every run.

The child's own records are listed by wire id, in the parent's order, so
that ``get_node_names()`` and endpoint lists come in creation order as
in-process. This module must not import numpy or Textual (the child loads it).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any, NamedTuple

from turtletui.graph.core import (
    ActionClientRecord,
    ActionServer,
    Graph,
    NodeRecord,
    Publisher,
    Service,
    ServiceClient,
    Subscription,
)
from turtletui.interfaces import InterfaceError, get_interface

MIRROR_OWNER = "mirror"
"""Owner of the child's records that stand for the parent's."""


class QosPolicies(NamedTuple):
    """What rmw tells others of an endpoint's QoS (rclpy's enum values)."""

    reliability: int
    durability: int
    liveliness: int

    @classmethod
    def of(cls, qos: Any) -> QosPolicies | None:
        """The policies of a QoSProfile; None for a bare depth or no profile."""
        try:
            return cls(int(qos.reliability), int(qos.durability), int(qos.liveliness))
        except (AttributeError, TypeError, ValueError):
            return None

    @classmethod
    def parse(cls, fields: Any) -> QosPolicies:
        """Check what an untrusted child sent."""
        if (
            not isinstance(fields, list)
            or len(fields) != 3
            or any(type(v) is not int or v not in known for v, known in zip(fields, _KNOWN_POLICIES, strict=True))
        ):
            raise ValueError(f"not QoS policies: {str(fields)[:100]}")
        return cls(*fields)


_KNOWN_POLICIES = (range(5), range(5), (0, 1, 3, 4, 5))
"""rclpy's values of each policy (ReliabilityPolicy, DurabilityPolicy, LivelinessPolicy)."""


class MirrorNode(NamedTuple):
    name: str
    namespace: str
    own: int
    """The child's wire id if it is the child's own node, else 0."""


class MirrorEndpoint(NamedTuple):
    """A publisher or subscription of a topic."""

    node: int
    """Index into GraphMirror.nodes (unused for the child's own)."""
    qos: QosPolicies | None
    own: int
    """The child's wire id if it is the child's own endpoint, else 0."""
    created_ns: int = 0
    """When it was made (for discovery: Graph.discovery_ns; unused for the child's own)."""


class MirrorTopic(NamedTuple):
    name: str
    type_name: str
    publishers: tuple[MirrorEndpoint, ...]
    subscriptions: tuple[MirrorEndpoint, ...]


class MirrorRecord(NamedTuple):
    """A service, client, action server or action client of someone else."""

    node: int
    """Index into GraphMirror.nodes."""
    name: str
    type_name: str
    created_ns: int = 0
    """When it was made (services and action servers: for discovery, Graph.discovery_ns)."""


class GraphMirror(NamedTuple):
    """Parent to child: who is on the parent's graph (see the module's doc)."""

    nodes: tuple[MirrorNode, ...]
    topics: tuple[MirrorTopic, ...]
    services: tuple[MirrorRecord, ...]
    clients: tuple[MirrorRecord, ...]
    action_servers: tuple[MirrorRecord, ...]
    action_clients: tuple[MirrorRecord, ...]

    def to_wire(self) -> tuple:
        """Plain nested tuples: marshal takes no NamedTuples."""
        return _plain(self)

    @classmethod
    def from_wire(cls, fields: Any) -> GraphMirror:
        nodes, topics, services, clients, action_servers, action_clients = fields

        def endpoint(e: Any) -> MirrorEndpoint:
            return MirrorEndpoint(e[0], None if e[1] is None else QosPolicies(*e[1]), e[2], e[3])

        def records(rows: Any) -> tuple[MirrorRecord, ...]:
            return tuple(MirrorRecord(*row) for row in rows)

        return cls(
            tuple(MirrorNode(*n) for n in nodes),
            tuple(
                MirrorTopic(name, type_name, tuple(map(endpoint, pubs)), tuple(map(endpoint, subs)))
                for name, type_name, pubs, subs in topics
            ),
            records(services),
            records(clients),
            records(action_servers),
            records(action_clients),
        )


def _plain(value: Any) -> Any:
    if isinstance(value, tuple):
        return tuple(_plain(v) for v in value)
    return value


# -- parent side -------------------------------------------------------------------
def snapshot(graph: Graph, owner: str, own_ids: Mapping[int, int]) -> GraphMirror:
    """The mirror of ``graph`` for the child whose records belong to ``owner``;
    ``own_ids`` maps ``id(record)`` of its nodes and topic endpoints to their
    wire ids."""
    index: dict[int, int] = {}
    """``id(node)`` to its place in the mirror's nodes."""
    nodes = []
    for node in graph.nodes:
        own = own_ids.get(id(node), 0) if node.owner == owner else 0
        if own or node.owner != owner:
            index[id(node)] = len(nodes)
            nodes.append(MirrorNode(node.name, node.namespace, own))

    def endpoints(records: Iterable[Publisher | Subscription]) -> tuple[MirrorEndpoint, ...]:
        listed = []
        for e in records:
            if e.owner == owner:
                if id(e) in own_ids:
                    listed.append(MirrorEndpoint(0, None, own_ids[id(e)]))
            elif id(e.node) in index:
                listed.append(MirrorEndpoint(index[id(e.node)], QosPolicies.of(e.qos), 0, e.created_ns))
        return tuple(listed)

    def others(records: Iterable[Any]) -> tuple[MirrorRecord, ...]:
        return tuple(
            MirrorRecord(index[id(r.node)], r.name, r.type_name, getattr(r, "created_ns", 0))
            for r in records
            if r.owner != owner and id(r.node) in index
        )

    return GraphMirror(
        tuple(nodes),
        tuple(
            MirrorTopic(t.name, t.type_name, endpoints(t.publishers), endpoints(t.subscriptions))
            for t in graph.channels()
            if t.publishers or t.subscriptions
        ),
        others(graph.services.values()),
        others(graph.clients),
        others(graph.action_servers.values()),
        others(graph.action_clients),
    )


# -- child side --------------------------------------------------------------------
def apply(graph: Graph, mirror: GraphMirror, own: Mapping[int, Any]) -> None:
    """Replace the records standing for the parent's in ``graph`` with those of
    ``mirror``; ``own`` maps wire ids to the child's own nodes and endpoints.
    The child's own records the parent does not know yet come after the
    parent's, in their order."""
    _forget(graph)
    nodes = [NodeRecord(n.name, n.namespace, MIRROR_OWNER) if not n.own else own.get(n.own) for n in mirror.nodes]
    graph.nodes = _ordered(graph.nodes, nodes)
    for t in mirror.topics:
        try:
            topic = graph.topic(t.name, get_interface(t.type_name))
        except InterfaceError:
            continue  # a type the child cannot import: its endpoints stay out of the child's view
        topic.publishers = _ordered(
            topic.publishers,
            [
                own.get(e.own) if e.own else Publisher(nodes[e.node], topic, 1, MIRROR_OWNER, e.qos, e.created_ns)
                for e in t.publishers
            ],
        )
        topic.subscriptions = _ordered(
            topic.subscriptions,
            [
                own.get(e.own)
                if e.own
                else Subscription(nodes[e.node], topic, 1, _never, MIRROR_OWNER, e.qos, None, e.created_ns)
                for e in t.subscriptions
            ],
        )
    graph.drop_unused_topics()  # the parent's endpoints on them are gone
    for r in mirror.services:
        srv_type = _interface(r.type_name)
        if srv_type is not None and r.name not in graph.services:
            graph.services[r.name] = Service(
                nodes[r.node], r.name, srv_type, r.type_name, _never, MIRROR_OWNER, r.created_ns
            )
    for r in mirror.action_servers:
        action_type = _interface(r.type_name)
        if action_type is not None and r.name not in graph.action_servers:
            graph.action_servers[r.name] = ActionServer(
                nodes[r.node], r.name, action_type, r.type_name, _never, MIRROR_OWNER, created_ns=r.created_ns
            )
    for r in mirror.clients:
        srv_type = _interface(r.type_name)
        if srv_type is not None:
            graph.clients.append(ServiceClient(nodes[r.node], r.name, srv_type, r.type_name, MIRROR_OWNER))
    for r in mirror.action_clients:
        action_type = _interface(r.type_name)
        if action_type is not None:
            graph.action_clients.append(
                ActionClientRecord(nodes[r.node], r.name, action_type, r.type_name, MIRROR_OWNER)
            )


def _forget(graph: Graph) -> None:
    """Take the last mirror's records off ``graph``."""
    graph.nodes = [n for n in graph.nodes if n.owner != MIRROR_OWNER]
    for topic in graph.channels():
        topic.publishers = [p for p in topic.publishers if p.owner != MIRROR_OWNER]
        topic.subscriptions = [s for s in topic.subscriptions if s.owner != MIRROR_OWNER]
    for name in [n for n, s in graph.services.items() if s.owner == MIRROR_OWNER]:
        del graph.services[name]
    for name in [n for n, a in graph.action_servers.items() if a.owner == MIRROR_OWNER]:
        del graph.action_servers[name]
    graph.clients = [c for c in graph.clients if c.owner != MIRROR_OWNER]
    graph.action_clients = [c for c in graph.action_clients if c.owner != MIRROR_OWNER]


def _ordered(current: list, placed: list) -> list:
    """``placed`` (the parent's order) without the child's own records it has
    destroyed since (None, or no longer in ``current``), then the records of
    ``current`` the parent does not know yet."""
    live = {id(item) for item in current}
    kept = [item for item in placed if item is not None and (item.owner == MIRROR_OWNER or id(item) in live)]
    listed = {id(item) for item in kept}
    return kept + [item for item in current if id(item) not in listed]


def _interface(type_name: str) -> Any:
    try:
        return get_interface(type_name)
    except InterfaceError:
        return None


def _never(*_: Any) -> None:
    """What a record standing for the parent's would call: never called (the
    child sends calls and goals for such records to the parent)."""
