"""QoS matching between a topic's publishers and subscriptions, as DDS does it.

A publisher and a subscription whose reliability or durability are
incompatible never match: nothing passes between them, both count only the
endpoints they match, and each side's node logs rclpy's warning (turtlesim's
side logs rclcpp's) when its executor next runs. A transient-local
subscription that joins late gets the last messages (up to the publisher's
depth) of each transient-local publisher it matches.
"""

from __future__ import annotations

from typing import Any

from turtletui.compat.qos import incompatible_policy, is_transient_local
from turtletui.graph import core
from turtletui.graph.logs import WARN

_PUBLISHER_SIDE = (
    "New subscription discovered on topic '{}', requesting incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}"
)
_SUBSCRIPTION_SIDE = (
    "New publisher discovered on topic '{}', offering incompatible QoS. "
    "No messages will be received from it. Last incompatible policy: {}"
)
_RCLCPP_SUBSCRIPTION_SIDE = (
    "New publisher discovered on topic '{}', offering incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}_QOS_POLICY"
)


def muted(record: core.Publisher) -> set:
    """The subscriptions a publisher never reaches (incompatible QoS)."""
    found = getattr(record, "muted", None)
    if found is None:
        found = record.muted = set()  # type: ignore[attr-defined]
    return found


def match_publisher(node: Any, publisher: Any) -> None:
    """Match a new compat publisher with the topic's subscriptions."""
    record = publisher._record
    for sub in record.topic.subscriptions:
        policy = incompatible_policy(publisher.qos_profile, sub.qos)
        if policy:
            _mismatch(node, record, sub, policy)


def match_subscription(node: Any, subscription: Any) -> None:
    """Match a new compat subscription with the topic's publishers; a
    transient-local one gets what matching transient-local publishers kept."""
    record = subscription._record
    for pub in record.topic.publishers:
        policy = incompatible_policy(pub.qos, subscription.qos_profile)
        if policy:
            _mismatch(node, pub, record, policy)
            continue
        kept = getattr(getattr(pub, "entity", None), "history", None)
        if kept and is_transient_local(subscription.qos_profile):
            for msg in kept:
                record.queue.append(record.copy(msg) if record.copy else msg)
            if not record.pending:
                record.pending = True
                node._graph.ready.append(record.ready_item)


def _mismatch(node: Any, pub: core.Publisher, sub: core.Subscription, policy: str) -> None:
    muted(pub).add(sub)
    for record, text in ((pub, _PUBLISHER_SIDE), (sub, _SUBSCRIPTION_SIDE)):
        entity = getattr(record, "entity", None)
        if entity is not None:
            entity._node._qos_event(entity, text.format(entity._topic_as_given, policy))
        elif record is sub:  # turtlesim's own subscription: rclcpp's words
            node._graph.log(sub.node.name, WARN, _RCLCPP_SUBSCRIPTION_SIDE.format(sub.topic.name, policy))
