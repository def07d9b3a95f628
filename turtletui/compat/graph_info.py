"""What rclpy's graph queries return about endpoints (``rclpy.topic_endpoint_info``)."""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from enum import IntEnum
from typing import Any

from turtletui.compat.distro import current_distro, type_description_names
from turtletui.compat.identity import as_rclpy
from turtletui.compat.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    LivelinessPolicy,
    QoSProfile,
    ReliabilityPolicy,
)
from turtletui.graph import core
from turtletui.graph.action_endpoints import ActionTopicEndpoint
from turtletui.interfaces import get_interface
from turtletui.interfaces.type_descriptions import type_hash

_HASH_SIZE = 32


class TypeHash:
    """A type's hash (``rclpy.type_hash.TypeHash``): ``version`` (1 for RIHS01,
    -1 unset) and ``value`` (32 bytes); ``str()`` gives ``RIHS01_<hex>``."""

    __slots__ = ("_version", "_value")

    def __init__(self, version: int = -1, value: bytes = bytes(_HASH_SIZE)) -> None:
        self.version = version
        self.value = value

    @property
    def version(self) -> int:
        return self._version

    @version.setter
    def version(self, value: int) -> None:
        assert isinstance(value, int)
        self._version = value

    @property
    def value(self) -> bytes:
        return self._value

    @value.setter
    def value(self, value: bytes) -> None:
        assert isinstance(value, bytes)
        self._value = value

    def __eq__(self, other: object) -> bool:
        return isinstance(other, TypeHash) and (self._version, self._value) == (other._version, other._value)

    __hash__ = None  # type: ignore[assignment]  # as rclpy's

    def __str__(self) -> str:
        if self._version <= 0 or len(self._value) != _HASH_SIZE:
            return "INVALID"
        return f"RIHS{self._version:02}_{self._value.hex()}"


def type_hash_of(type_name: str) -> TypeHash:
    """The TypeHash of an interface type as this process's distro names it."""
    text = type_hash(get_interface(type_name), None, type_description_names(current_distro()) or ())
    return TypeHash(1, bytes.fromhex(text.partition("_")[2]))


class NodeNameNonExistentError(RuntimeError):
    """rclpy's error for a query about a node that is not in the graph."""


class TopicEndpointTypeEnum(IntEnum):
    """Whether an endpoint publishes or subscribes (rmw's numbers)."""

    INVALID = 0
    PUBLISHER = 1
    SUBSCRIPTION = 2


class TopicEndpointInfo:
    """One publisher or subscription of a topic, as rclpy describes it."""

    __slots__ = (
        "node_name", "node_namespace", "topic_type", "topic_type_hash", "endpoint_type", "endpoint_gid", "qos_profile",
    )

    def __init__(
        self,
        node_name: str = "",
        node_namespace: str = "",
        topic_type: str = "",
        topic_type_hash: TypeHash | None = None,
        endpoint_type: TopicEndpointTypeEnum | int = TopicEndpointTypeEnum.INVALID,
        endpoint_gid: list[int] | None = None,
        qos_profile: QoSProfile | None = None,
    ) -> None:
        self.node_name = node_name
        self.node_namespace = node_namespace
        self.topic_type = topic_type
        self.topic_type_hash = topic_type_hash if topic_type_hash is not None else TypeHash()
        self.endpoint_type = TopicEndpointTypeEnum(endpoint_type)
        self.endpoint_gid = list(endpoint_gid or [])
        self.qos_profile = qos_profile if qos_profile is not None else _reported_qos(None)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, TopicEndpointInfo):
            return False
        return all(getattr(self, slot) == getattr(other, slot) for slot in self.__slots__)

    __hash__ = None  # type: ignore[assignment]  # as rclpy's

    def __str__(self) -> str:
        qos = self.qos_profile
        if qos.history != HistoryPolicy.KEEP_LAST:
            history = qos.history.name
        else:
            history = f"{qos.history.name} ({qos.depth})"
        return "\n".join(
            [
                f"Node name: {self.node_name}",
                f"Node namespace: {self.node_namespace}",
                f"Topic type: {self.topic_type}",
                f"Topic type hash: {self.topic_type_hash}",
                f"Endpoint type: {self.endpoint_type.name}",
                f"GID: {gid_text(self.endpoint_gid)}",
                "QoS profile:",
                f"  Reliability: {qos.reliability.name}",
                f"  History (Depth): {history}",
                f"  Durability: {qos.durability.name}",
                "  Lifespan: Infinite",  # rmw reports no lifespan, deadline or lease here: rclpy's default
                "  Deadline: Infinite",
                f"  Liveliness: {qos.liveliness.name}",
                "  Liveliness lease duration: Infinite",
            ]
        )


def endpoints_info(
    endpoints: Sequence[core.Publisher | core.Subscription | ActionTopicEndpoint], kind: TopicEndpointTypeEnum
) -> list[TopicEndpointInfo]:
    """The TopicEndpointInfo of each of a topic's publishers (or subscriptions),
    an action's hidden ones included."""
    infos = []
    seen: dict[str, int] = {}
    for endpoint in endpoints:
        node = endpoint.node
        nth = seen[node.fqn] = seen.get(node.fqn, -1) + 1
        infos.append(
            TopicEndpointInfo(
                node_name=node.name,
                node_namespace=node.namespace or "/",
                topic_type=endpoint.topic.type_name,
                topic_type_hash=type_hash_of(endpoint.topic.type_name),
                endpoint_type=kind,
                # a publisher's GID, once a message named it, stays what it was then
                endpoint_gid=list(getattr(endpoint, "gid", None) or _gid(node.fqn, endpoint.topic.name, kind, nth)),
                qos_profile=_reported_qos(endpoint.qos),
            )
        )
    return infos


def gid_text(gid: Sequence[int]) -> str:
    """A GID as rclpy and ros2 print it: its bytes in hex, dot-separated."""
    return ".".join(format(x, "02x") for x in gid)


def publisher_gid(graph: core.Graph, publisher: core.Publisher) -> bytes:
    """The GID of ``publisher`` as its TopicEndpointInfo listed it when first
    asked (rmw's MessageInfo names a message's publisher by it), kept on the
    record: worked out once, not for every message."""
    if publisher.gid is None:
        fqn = publisher.node.fqn
        nth = 0
        for endpoint in graph.publishers_of(publisher.topic.name):
            if endpoint is publisher:
                break
            if endpoint.node.fqn == fqn:
                nth += 1
        publisher.gid = bytes(_gid(fqn, publisher.topic.name, TopicEndpointTypeEnum.PUBLISHER, nth))
    return publisher.gid


def _gid(node: str, topic: str, kind: TopicEndpointTypeEnum, nth: int) -> list[int]:
    """16 bytes naming an endpoint (a DDS GUID's size), the same in every run."""
    return list(hashlib.blake2b(f"{node}|{topic}|{kind.name}|{nth}".encode(), digest_size=16).digest())


def _reported_qos(asked: Any) -> QoSProfile:
    """What the middleware reports of an endpoint's QoS: the policies it was
    created with (reliable, volatile and automatic where it asked for the
    system's default, as Fast DDS), but not its history or depth, which rmw
    does not share."""
    reliability = getattr(asked, "reliability", ReliabilityPolicy.SYSTEM_DEFAULT)
    if reliability in (ReliabilityPolicy.SYSTEM_DEFAULT, ReliabilityPolicy.BEST_AVAILABLE):
        reliability = ReliabilityPolicy.RELIABLE
    durability = getattr(asked, "durability", DurabilityPolicy.SYSTEM_DEFAULT)
    if durability in (DurabilityPolicy.SYSTEM_DEFAULT, DurabilityPolicy.BEST_AVAILABLE):
        durability = DurabilityPolicy.VOLATILE
    liveliness = getattr(asked, "liveliness", LivelinessPolicy.SYSTEM_DEFAULT)
    if liveliness in (LivelinessPolicy.SYSTEM_DEFAULT, LivelinessPolicy.BEST_AVAILABLE):
        liveliness = LivelinessPolicy.AUTOMATIC
    return QoSProfile(
        history=HistoryPolicy.UNKNOWN,
        depth=0,
        reliability=reliability,
        durability=durability,
        liveliness=liveliness,
    )

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.topic_endpoint_info", TopicEndpointInfo, TopicEndpointTypeEnum)
