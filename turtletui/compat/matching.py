"""QoS warnings between a topic's publishers and subscriptions, as rclpy logs them.

The graph mutes a publisher and a subscription whose reliability or
durability are incompatible (turtletui.graph.qos): nothing passes between
them and neither counts the other. Each side's node logs rclpy's warning
when its executor next runs (the simulator's C++ nodes, turtlesim's...,
log rclcpp's as the graph matches them: Graph._match). An endpoint
of another process (a sandboxed controller's on the simulator's graph, or
the simulator's as a sandboxed controller sees it) warns in its own
process: :func:`warn_others` and :func:`match_mirror` are those processes'
halves.
"""

from __future__ import annotations

from typing import Any

from turtletui.compat.event_handler import incompatible_qos_event
from turtletui.graph import core
from turtletui.graph.qos import incompatible_policy

_PUBLISHER_SIDE = (
    "New subscription discovered on topic '{}', requesting incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}"
)
_SUBSCRIPTION_SIDE = (
    "New publisher discovered on topic '{}', offering incompatible QoS. "
    "No messages will be received from it. Last incompatible policy: {}"
)
REMOTE = "remote"
"""``record.entity`` of an endpoint that stands for another process's on the
simulator's graph: that process warns for it."""


def match_publisher(node: Any, publisher: Any) -> None:
    """Warn of the new compat publisher's incompatible subscriptions."""
    record = publisher._record
    for sub in record.topic.subscriptions:
        policy = incompatible_policy(publisher.qos_profile, sub.qos)
        if policy:
            _warn_both(node._graph, record, sub, policy)


def match_subscription(node: Any, subscription: Any) -> None:
    """Warn of the new compat subscription's incompatible publishers."""
    record = subscription._record
    for pub in record.topic.publishers:
        policy = incompatible_policy(pub.qos, subscription.qos_profile)
        if policy:
            _warn_both(node._graph, pub, record, policy)


def watch_mismatches(graph: core.Graph) -> None:
    """Have ``graph`` tell this process's endpoints of the incompatible
    endpoints made after them (a turtle spawned later, a bag's player): the
    endpoint being made warns in match_publisher or match_subscription."""
    graph.on_mismatch = _mismatched


def _mismatched(pub: core.Publisher, sub: core.Subscription, policy: str) -> None:
    for record in (pub, sub):
        entity = getattr(record, "entity", None)
        if entity is not None and entity is not REMOTE:
            _warn(None, record, policy, pub, sub)


def warn_others(graph: core.Graph, record: core.Publisher | core.Subscription) -> None:
    """A sandboxed controller's new endpoint ``record`` is on the simulator's
    graph: the endpoints of this process it does not match warn (the
    controller warns for its own side itself)."""
    record.entity = REMOTE  # type: ignore[union-attr]
    if isinstance(record, core.Publisher):
        pairs = [(record, sub) for sub in record.topic.subscriptions]
    else:
        pairs = [(pub, record) for pub in record.topic.publishers]
    for pub, sub in pairs:
        policy = incompatible_policy(pub.qos, sub.qos)
        if policy:
            _warn(graph, sub if pub is record else pub, policy, pub, sub)


def match_mirror(graph: core.Graph, remote_owner: str) -> None:
    """The endpoints of other processes (owned by ``remote_owner``) a
    sandboxed controller has just heard of: its own endpoints they do not
    match warn, once for each."""
    for topic in graph.channels():
        theirs_pubs = [p for p in topic.publishers if p.owner == remote_owner]
        theirs_subs = [s for s in topic.subscriptions if s.owner == remote_owner]
        if not theirs_pubs and not theirs_subs:
            continue
        for pub in topic.publishers:
            if pub.owner != remote_owner:
                for sub in theirs_subs:
                    _warn_once(graph, pub, sub, pub, sub)
        for sub in topic.subscriptions:
            if sub.owner != remote_owner:
                for pub in theirs_pubs:
                    _warn_once(graph, sub, pub, pub, sub)


def _warn_once(graph: core.Graph, own: Any, theirs: Any, pub: Any, sub: Any) -> None:
    policy = incompatible_policy(pub.qos, sub.qos)
    if policy:
        _warn(graph, own, policy, pub, sub)


def _warned(record: Any) -> set:
    """The other processes' endpoints ``record`` has warned of."""
    found = getattr(record, "warned_of", None)
    if found is None:
        found = record.warned_of = set()
    return found


def _key(record: Any) -> tuple:
    """Another process's endpoint, the same in every mirror of the graph."""
    return (type(record).__name__, record.node.fqn, record.created_ns)


def _warn_both(graph: core.Graph, pub: core.Publisher, sub: core.Subscription, policy: str) -> None:
    for record in (pub, sub):
        _warn(graph, record, policy, pub, sub)


def _warn(graph: core.Graph | None, record: Any, policy: str, pub: Any, sub: Any) -> None:
    """``record``'s side of a mismatch between ``pub`` and ``sub`` logs its
    warning, once; ``graph`` None: ``record`` is this process's own."""
    other = sub if record is pub else pub
    warned = _warned(record)
    if _key(other) in warned:
        return
    warned.add(_key(other))
    entity = getattr(record, "entity", None)
    remote = graph.outbox.remote_owner if graph is not None and graph.outbox is not None else None
    if entity is REMOTE or record.owner == remote:
        return  # another process warns for its own endpoints
    if entity is not None:
        event = incompatible_qos_event(entity, policy)
        if event is None:
            return  # use_default_callbacks=False and no incompatible_qos callback: nothing, as in rclpy
        callback, status = event
        text = _PUBLISHER_SIDE if record is pub else _SUBSCRIPTION_SIDE
        entity._node._qos_event(entity, text.format(entity._topic_as_given, policy), callback, status)
    # a C++ node of the simulator's (turtlesim's...) warned as the graph matched it
