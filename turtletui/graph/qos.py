"""QoS matching as DDS does it, on the policies' values (rclpy's enums are
ints: a QoSProfile, another process's QosPolicies and None all work here).

A best-effort publisher cannot serve a reliable subscription; a volatile one
cannot serve a transient-local one. An endpoint without policies (None, a
bare depth, SYSTEM_DEFAULT) has rmw's default: reliable, volatile.
"""

from __future__ import annotations

from typing import Any, NamedTuple

_RELIABLE, _BEST_EFFORT = 1, 2
_TRANSIENT_LOCAL, _VOLATILE = 1, 2
_SYSTEM_DEFAULT = 0
_AUTOMATIC = 1


class Policies(NamedTuple):
    """The policies of an endpoint of the simulator's own nodes (teleop_turtle,
    rosbag2's player), numbered as rclpy's enums: what the graph matches on
    and what ``get_publishers_info_by_topic`` reports."""

    reliability: int = _RELIABLE
    durability: int = _VOLATILE
    liveliness: int = _AUTOMATIC

    @classmethod
    def named(cls, reliability: str, durability: str) -> Policies:
        """From rosbag2's names: "reliable" or "best_effort", "volatile" or "transient_local"."""
        return cls(
            _BEST_EFFORT if reliability == "best_effort" else _RELIABLE,
            _TRANSIENT_LOCAL if durability == "transient_local" else _VOLATILE,
        )


DEFAULT = Policies()
"""rclcpp's default: reliable, volatile (teleop_turtle's cmd_vel publisher)."""
SENSOR_DATA = Policies(reliability=_BEST_EFFORT)
"""rclcpp's SensorDataQoS: best effort, volatile (what LiDAR drivers and
Gazebo's ray sensor publish scans with; a reliable subscription never matches)."""
SENSOR_DATA_DEPTH = 5
"""SensorDataQoS keeps the last 5."""


def _effective(qos: Any) -> tuple[int, int]:
    """(reliability, durability) of an endpoint made with ``qos``."""
    try:
        reliability, durability = int(qos.reliability), int(qos.durability)
    except (AttributeError, TypeError, ValueError):
        return _RELIABLE, _VOLATILE
    return (
        _RELIABLE if reliability == _SYSTEM_DEFAULT else reliability,
        _VOLATILE if durability == _SYSTEM_DEFAULT else durability,
    )


def offered(qos: Any) -> Policies:
    """The reliability and durability an endpoint made with ``qos`` has."""
    return Policies(*_effective(qos))


def offer_counts(publishers: Any) -> tuple[int, int, int]:
    """How many of ``publishers`` (each with a ``qos``) offer reliable, how many
    transient local, and how many there are."""
    offers = [_effective(pub.qos) for pub in publishers]
    reliable = sum(r == _RELIABLE for r, _ in offers)
    kept = sum(d == _TRANSIENT_LOCAL for _, d in offers)
    return reliable, kept, len(offers)


def adapted(publishers: Any) -> Policies:
    """The policies ``ros2 topic echo`` and rosbag2's recorder subscribe with
    (ros2topic's choose_qos): reliable and transient local only if every
    publisher (each with a ``qos``) offers it, so they hear them all."""
    reliable, kept, total = offer_counts(publishers)
    return Policies(
        _RELIABLE if total and reliable == total else _BEST_EFFORT,
        _TRANSIENT_LOCAL if total and kept == total else _VOLATILE,
    )


def incompatible_policy(publisher_qos: Any, subscription_qos: Any) -> str | None:
    """Why a publisher and a subscription never match, as the name of the last
    incompatible policy DDS reports ("RELIABILITY" or "DURABILITY"), or None
    when they match."""
    pub_reliability, pub_durability = _effective(publisher_qos)
    sub_reliability, sub_durability = _effective(subscription_qos)
    if pub_reliability == _BEST_EFFORT and sub_reliability == _RELIABLE:
        return "RELIABILITY"
    if pub_durability == _VOLATILE and sub_durability == _TRANSIENT_LOCAL:
        return "DURABILITY"
    return None


def policy_names(qos: Any) -> tuple[str, str]:
    """The reliability and durability an endpoint made with ``qos`` has, as
    rclpy names them: ("RELIABLE" or "BEST_EFFORT", "VOLATILE" or "TRANSIENT_LOCAL")."""
    reliability, durability = _effective(qos)
    return (
        "BEST_EFFORT" if reliability == _BEST_EFFORT else "RELIABLE",
        "TRANSIENT_LOCAL" if durability == _TRANSIENT_LOCAL else "VOLATILE",
    )


def is_transient_local(qos: Any) -> bool:
    """Whether an endpoint keeps (publisher) or asks for (subscription) the
    last messages sent before a subscription joined."""
    return _effective(qos)[1] == _TRANSIENT_LOCAL


_RCLCPP_INCOMPATIBLE = (
    "New publisher discovered on topic '{}', offering incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}_QOS_POLICY",
    "New subscription discovered on topic '{}', requesting incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}_QOS_POLICY",
)


def rclcpp_incompatible_qos(publisher_side: bool, topic: str, policy: str) -> str:
    """What rclcpp's default incompatible-QoS callback logs (WARN, on the
    node's logger) for a publisher (``publisher_side``) or a subscription of
    a C++ node: publisher_base.cpp's and subscription_base.cpp's words, the
    policy as qos_policy_name_from_kind names it."""
    return _RCLCPP_INCOMPATIBLE[publisher_side].format(topic, policy)
