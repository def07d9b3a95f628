"""What ``ros2 node/topic/service/action list|info`` and rqt_graph show, as data.

``snapshot(graph)`` copies the graph's state into plain frozen records that a
view, the grader or a test can keep and compare; nothing in them refers back
to live endpoints.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from difflib import get_close_matches
from typing import Any

from turtletui.graph.action_endpoints import ActionTopicEndpoint
from turtletui.graph.core import Graph
from turtletui.graph.qos import incompatible_policy, policy_names


@dataclass(frozen=True)
class NodeInfo:
    """A node and its endpoints (``ros2 node info``); names are fully qualified."""

    name: str
    publishers: tuple[tuple[str, str], ...]
    """(topic, type) pairs."""
    subscribers: tuple[tuple[str, str], ...]
    service_servers: tuple[tuple[str, str], ...]
    service_clients: tuple[tuple[str, str], ...]
    action_servers: tuple[tuple[str, str], ...]
    action_clients: tuple[tuple[str, str], ...]
    parameters: tuple[tuple[str, Any], ...]


@dataclass(frozen=True)
class TopicInfo:
    """A topic (``ros2 topic info`` and ``hz``): its type, endpoints and rate."""

    name: str
    type: str
    publishers: tuple[str, ...]
    """Fully qualified names of the publishing nodes (once per publisher)."""
    subscribers: tuple[str, ...]
    rate_hz: float
    """Messages per simulated second over the last 64 (0 when idle for 2 s)."""
    count: int
    """Messages published since the start."""
    other_types: tuple[str, ...] = ()
    """Further types some processes use the name with (``type`` is the first's;
    rate and count are of ``type``'s messages): see turtletui.graph.core.Topic."""

    @property
    def types(self) -> list[str]:
        """Every type in use on the name, sorted, as rcl's names-and-types lists give them."""
        return sorted({self.type, *self.other_types})


@dataclass(frozen=True)
class ServiceInfo:
    """A service that has a server or a client (``ros2 service list`` lists both)."""

    name: str
    type: str
    server: str
    """The serving node's full name; "" while only clients wait for one."""
    clients: tuple[str, ...]


@dataclass(frozen=True)
class ActionInfo:
    name: str
    type: str
    server: str
    clients: tuple[str, ...]


@dataclass(frozen=True)
class GraphSnapshot:
    """The whole graph at simulated time ``t``; every list sorted by name."""

    t: float
    nodes: tuple[NodeInfo, ...]
    topics: tuple[TopicInfo, ...]
    services: tuple[ServiceInfo, ...]
    actions: tuple[ActionInfo, ...]

    def node(self, name: str) -> NodeInfo:
        """The node called ``name`` (with or without its leading slash)."""
        wanted = name if name.startswith("/") else f"/{name}"
        for node in self.nodes:
            if node.name == wanted:
                return node
        raise KeyError(_unknown("node", name, [n.name for n in self.nodes]))

    def topic(self, name: str) -> TopicInfo:
        for topic in self.topics:
            if topic.name == name:
                return topic
        raise KeyError(_unknown("topic", name, [t.name for t in self.topics]))

    def edges(self) -> tuple[tuple[str, str], ...]:
        """rqt_graph's arrows: node -> topic for publishers, topic -> node for
        subscribers, e.g. ('/turtlesim', '/turtle1/pose')."""
        arrows = set()
        for topic in self.topics:
            arrows.update((node, topic.name) for node in topic.publishers)
            arrows.update((topic.name, node) for node in topic.subscribers)
        return tuple(sorted(arrows))


def _unknown(kind: str, name: str, known: list[str]) -> str:
    close = get_close_matches(name, known, n=3)
    hint = f" (did you mean {', '.join(close)}?)" if close else ""
    return f"unknown {kind} {name}{hint}"


def snapshot(graph: Graph, *, action_endpoints: bool = False) -> GraphSnapshot:
    """Copy what the graph holds now into a GraphSnapshot. With
    ``action_endpoints``, the hidden topics and services behind every action
    (``<action>/_action/...``) are in it too, as the ros2 tools see them; the
    views leave them out, as rqt_graph does."""
    now = graph.now_ns
    per_node: dict[int, dict[str, list]] = {
        id(node): {key: [] for key in ("pub", "sub", "srv", "cli", "asrv", "acli")} for node in graph.nodes
    }

    def add(node: Any, key: str, entry: tuple[str, str]) -> None:
        if id(node) in per_node:
            per_node[id(node)][key].append(entry)

    topics: dict[str, TopicInfo] = {}
    for name, first in graph.topics.items():
        channels = [t for t in graph.channels_of(name) if t.publishers or t.subscriptions]
        if not channels:
            continue
        for topic in channels:
            for pub in topic.publishers:
                add(pub.node, "pub", (name, topic.type_name))
            for sub in topic.subscriptions:
                add(sub.node, "sub", (name, topic.type_name))
        topics[name] = TopicInfo(
            name,
            first.type_name,
            tuple(sorted(p.node.fqn for t in channels for p in t.publishers)),
            tuple(sorted(s.node.fqn for t in channels for s in t.subscriptions)),
            first.rate(now),
            first.count,
            tuple(t.type_name for t in channels if t is not first),
        )
    servers = [(name, service.type_name, service.node) for name, service in graph.services.items()]
    callers = [(c.name, c.type_name, c.node) for c in graph.clients]
    if action_endpoints:
        for key, kind in (("pub", "publishers"), ("sub", "subscriptions")):
            for endpoint in graph.action_topic_endpoints(kind):
                add(endpoint.node, key, (endpoint.topic.name, endpoint.topic.type_name))
                _add_action_topic(topics, endpoint, key)
        servers += [(e.name, e.type_name, e.node) for e in graph.action_service_endpoints("services")]
        callers += [(e.name, e.type_name, e.node) for e in graph.action_service_endpoints("clients")]
    services: dict[str, ServiceInfo] = {}
    for name, type_name, node in servers:
        add(node, "srv", (name, type_name))
        services.setdefault(name, ServiceInfo(name, type_name, node.fqn, ()))
    for name, type_name, node in callers:
        add(node, "cli", (name, type_name))
        info = services.get(name) or ServiceInfo(name, type_name, "", ())
        services[name] = replace(info, clients=tuple(sorted((*info.clients, node.fqn))))
    actions = []
    for name, server in graph.action_servers.items():
        add(server.node, "asrv", (name, server.type_name))
        action_clients = tuple(sorted(c.node.fqn for c in graph.action_clients if c.name == name))
        actions.append(ActionInfo(name, server.type_name, server.node.fqn, action_clients))
    for client in graph.action_clients:
        add(client.node, "acli", (client.name, client.type_name))
    nodes = []
    for node in graph.nodes:
        entries = per_node[id(node)]
        nodes.append(
            NodeInfo(
                node.fqn,
                *(tuple(sorted(set(entries[key]))) for key in ("pub", "sub", "srv", "cli", "asrv", "acli")),
                tuple(sorted(node.parameters.items())),
            )
        )
    return GraphSnapshot(
        now / 1e9,
        tuple(sorted(nodes, key=lambda n: n.name)),
        tuple(sorted(topics.values(), key=lambda t: t.name)),
        tuple(sorted(services.values(), key=lambda s: s.name)),
        tuple(sorted(actions, key=lambda a: a.name)),
    )


def _add_action_topic(topics: dict[str, TopicInfo], endpoint: ActionTopicEndpoint, key: str) -> None:
    """Count an action's hidden publisher (``key`` "pub") or subscription on its topic."""
    name = endpoint.topic.name
    info = topics.get(name) or TopicInfo(name, endpoint.topic.type_name, (), (), 0.0, 0)
    if key == "pub":
        info = replace(info, publishers=tuple(sorted((*info.publishers, endpoint.node.fqn))))
    else:
        info = replace(info, subscribers=tuple(sorted((*info.subscribers, endpoint.node.fqn))))
    topics[name] = info


def dangling_endpoints(graph: Graph, owner_prefix: str = "") -> list[str]:
    """One warning per controller subscription that nothing publishes to, per
    controller publisher that nothing listens to (when a similar name
    exists), and per service or action client that nothing serves, with the
    closest existing names: the usual sign of a typo in a name."""
    warnings = []
    live = {t.name for t in graph.channels() if t.publishers or t.subscriptions}
    for topic in sorted(graph.channels(), key=lambda t: t.name):
        name = topic.name
        for sub in topic.subscriptions:
            # (graph.count_*: an action's hidden endpoints count, though no view shows them)
            if sub.owner.startswith(owner_prefix) and sub.owner != "sim" and not graph.count_publishers(name) \
                    and name not in OPTIONAL_INPUTS:
                warnings.append(_dangling(sub.node.fqn, "subscribes to", name, "publishes", live))
        for pub in topic.publishers:
            if pub.owner.startswith(owner_prefix) and pub.owner != "sim" and not graph.count_subscribers(name) \
                    and not is_plumbing_topic(name):
                # Publishing to no one is normal (a debug topic): say so only
                # when a topic of a very similar name exists.
                if _close(name, live):
                    warnings.append(_dangling(pub.node.fqn, "publishes on", name, "subscribes to", live))
    # a client of a service or an action that nothing serves waits for ever
    # (wait_for_service, wait_for_server): /rotate_absolute for /turtle1/rotate_absolute
    for clients, servers, what in (
        (graph.clients, graph.services, "a client of"),
        (graph.action_clients, graph.action_servers, "an action client of"),
    ):
        for client in clients:
            if client.owner.startswith(owner_prefix) and client.owner != "sim" and client.name not in servers:
                warnings.append(_dangling(client.node.fqn, f"is {what}", client.name, "serves", set(servers)))
    return sorted(set(warnings))


NEVER_MATCH = "endpoints of different types never match, so nothing passes between them"
"""How every warning of ``mistyped_endpoints`` ends (the grader finds them by it)."""


def mistyped_endpoints(graph: Graph, owner_prefix: str = "") -> list[str]:
    """One warning per controller endpoint that uses a topic with another type
    than the other side's (a geometry_msgs/msg/Pose subscription on
    turtlesim's /turtle1/pose): as in ROS 2 the two never match and nothing
    arrives, which looks exactly like a silent robot."""
    warnings = []
    for name in sorted(graph.retyped):
        channels = graph.channels_of(name)
        for topic in channels:
            others = [t for t in channels if t is not topic]
            for mine, verb, side, their_verb in (
                (topic.subscriptions, "subscribes to", "publishers", "publishes"),
                (topic.publishers, "publishes on", "subscriptions", "subscribes to"),
            ):
                theirs = [(e, t) for t in others for e in getattr(t, side)]
                if not theirs:
                    continue
                other, other_topic = min(theirs, key=lambda pair: pair[0].created_ns)
                for endpoint in mine:
                    if endpoint.owner.startswith(owner_prefix) and endpoint.owner != "sim":
                        warnings.append(
                            f"{endpoint.node.fqn} {verb} {name} with type {topic.type_name}, but "
                            f"{other.node.fqn} {their_verb} it with type {other_topic.type_name}: {NEVER_MATCH}"
                        )
    return sorted(set(warnings))


QOS_NEVER_MATCH = "their QoS never match, so nothing passes between them"
"""How every warning of ``mismatched_qos`` ends (the grader finds them by it)."""

_QOS_ADVICE = {
    ("RELIABILITY", "sub"): "subscribe with qos_profile_sensor_data: best effort hears best-effort and reliable "
    "publishers alike, and a robot's sensors publish best effort",
    ("RELIABILITY", "pub"): "publish with a plain depth such as 10, which is reliable and heard by every "
    "subscription",
    ("DURABILITY", "sub"): "subscribe with a plain depth such as 10, which is volatile and hears every publisher",
    ("DURABILITY", "pub"): "publish with TRANSIENT_LOCAL durability, or have the subscription ask for VOLATILE",
}


def mismatched_qos(graph: Graph) -> list[str]:
    """One warning per publisher and subscription, one of them a controller's,
    that never match for their QoS (a reliable subscription of a best-effort
    scan), with what to change on the controller's side: ROS 2 says so once
    in a warning and then nothing arrives, which looks like a silent sensor."""
    warnings = []
    for topic in graph.channels():
        live = set(topic.subscriptions)
        for pub in topic.publishers:
            for sub in sorted(pub.muted & live, key=lambda s: s.created_ns):
                policy = incompatible_policy(pub.qos, sub.qos)
                if policy is None:
                    continue
                index = 0 if policy == "RELIABILITY" else 1
                asked, offered = policy_names(sub.qos)[index], policy_names(pub.qos)[index]
                what = "delivery" if index == 0 else "durability"
                ends = ((sub, "sub"), (pub, "pub"))
                advice = [_QOS_ADVICE[policy, side] for mine, side in ends if mine.owner != "sim"]
                if advice:
                    warnings.append(
                        f"{sub.node.fqn} subscribes to {topic.name} asking for {asked} {what}, but "
                        f"{pub.node.fqn} publishes it {offered}: {QOS_NEVER_MATCH} ({'; or '.join(advice)})"
                    )
    return sorted(set(warnings))


def is_qos_warning(text: str) -> bool:
    """Whether ``text`` is one of :func:`mismatched_qos`' warnings."""
    return f": {QOS_NEVER_MATCH} (" in text


def _close(topic: str, live: set[str]) -> list[str]:
    """Up to two live topics ``topic`` may have meant: similar names, or the
    same last name in another namespace (/scan for /turtle1/scan, /cmd_vel
    for /turtle1/cmd_vel: a name written without its turtle's namespace)."""
    others = sorted(live - {topic})
    base = topic.rsplit("/", 1)[-1]
    namesakes = [name for name in others if name.rsplit("/", 1)[-1] == base]
    return list(dict.fromkeys([*get_close_matches(topic, others, n=2, cutoff=0.75), *namesakes]))[:2]


_DANGLING = re.compile(r", but nothing (?:publishes|subscribes to|serves) it(?: \(did you mean [^()]*\?\))?$")


def is_dangling_warning(text: str) -> bool:
    """Whether ``text`` is one of :func:`dangling_endpoints`' warnings."""
    return _DANGLING.search(text) is not None


def _dangling(node: str, verb: str, topic: str, other: str, live: set[str]) -> str:
    close = _close(topic, live)
    hint = f" (did you mean {' or '.join(close)}?)" if close else ""
    return f"{node} {verb} {topic}, but nothing {other} it{hint}"


OPTIONAL_INPUTS = frozenset({"/tf_static"})
"""Topics a library subscribes to whether or not anything will publish there
(every tf2_ros TransformListener listens to /tf_static): no sign of a typo."""


PLUMBING_TOPICS = (
    ("/parameter_events", "rcl_interfaces/msg/ParameterEvent"),
    ("/rosout", "rcl_interfaces/msg/Log"),
)
"""What every ROS 2 node publishes besides its own topics."""
_PLUMBING_NAMES = frozenset(name for name, _ in PLUMBING_TOPICS)


def is_plumbing_topic(name: str) -> bool:
    """Whether ``name`` is a topic every node has (/rosout, /parameter_events):
    rqt_graph hides them, and no one needs to be told nothing listens there."""
    return name in _PLUMBING_NAMES
