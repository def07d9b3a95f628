"""Matched events: a publisher's or subscription's ``matched`` event callback.

``PublisherEventCallbacks(matched=...)`` and ``SubscriptionEventCallbacks(matched=...)``
(demo_nodes_py's matched_event_detect) are called, as rmw's matched status
changes, with its counts: ``current_count`` (the endpoints matched now),
``total_count`` (every match so far) and the change of each since the last
call. An endpoint matches one of the other side of its topic whose QoS is
compatible once the two have discovered each other (turtletui.graph.core's
``Graph.matched``). Changes that come before the executor runs the event
are told in one call, as rmw does.
"""

from __future__ import annotations

from typing import Any

from turtletui.compat.event_handler import QoSPublisherMatchedInfo
from turtletui.graph import core
from turtletui.graph.qos import incompatible_policy


def watch_matches(node: Any, entity: Any) -> None:
    """Call ``entity``'s matched callback, if it has one, as its matches change
    (its first matches included)."""
    callbacks = getattr(entity, "_event_callbacks", None)
    if getattr(callbacks, "matched", None) is None:
        return
    graph = node._graph
    watchers = getattr(graph, "match_watchers", None)
    if watchers is None:
        watchers = graph.match_watchers = []
        graph.on_endpoints = lambda: recheck(graph)
    entity._matched_keys = set()
    entity._matched_total = 0
    entity._matched_status = None
    watchers.append(entity)
    recheck(graph)


def recheck(graph: core.Graph) -> None:
    """Tell each watching endpoint of ``graph`` whose matches changed."""
    watchers = getattr(graph, "match_watchers", None)
    if not watchers:
        return
    for entity in list(watchers):
        if entity._destroyed:
            watchers.remove(entity)
            continue
        _recheck_one(graph, entity)


def _recheck_one(graph: core.Graph, entity: Any) -> None:
    record = entity._record
    is_publisher = isinstance(record, core.Publisher)
    others = record.topic.subscriptions if is_publisher else record.topic.publishers
    keys = set()
    later: list[int] = []
    seen: dict[tuple, int] = {}
    for other in others:
        pub, sub = (record, other) if is_publisher else (other, record)
        if incompatible_policy(pub.qos, sub.qos):
            continue
        if not graph.matched(pub, sub):
            later.append(graph.discovered_at(pub, sub))
            continue
        keys.add(_key(other, seen))
    for at in sorted(set(later)):
        if not hasattr(entity, "_match_checks"):
            entity._match_checks = set()
        if at not in entity._match_checks:
            entity._match_checks.add(at)
            graph.call_later(record.node, max(at - graph.now_ns, 0), lambda: recheck(graph))
    before = entity._matched_keys
    if keys == before:
        return
    added = len(keys - before)
    entity._matched_keys = keys
    status = entity._matched_status
    if status is None:
        status = entity._matched_status = QoSPublisherMatchedInfo()
        callback = entity._event_callbacks.matched

        def run(info: Any) -> None:
            entity._matched_status = None
            callback(info)

        entity._node._qos_event(entity, "", run, status)
    entity._matched_total += added
    status.total_count = entity._matched_total
    status.total_count_change += added
    status.current_count = len(keys)
    status.current_count_change += len(keys) - len(before)


_MIRRORED = "mirror"
"""The owner of the records a sandboxed child makes anew with each mirror of
the parent's graph (turtletui.runtime.graph_mirror's MIRROR_OWNER, a layer above)."""


def _key(record: Any, seen: dict[tuple, int]) -> Any:
    """The same endpoint from one look at the graph to the next."""
    if record.owner != _MIRRORED:
        return id(record)
    base = (type(record).__name__, record.node.fqn, record.created_ns)
    seen[base] = seen.get(base, 0) + 1
    return (*base, seen[base])
