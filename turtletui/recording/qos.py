"""Offered QoS profiles as rosbag2 stores them (metadata version 9).

rosbag2 records what each publisher offers, as the middleware reports it:
history and depth are not sent over discovery, so they read ``unknown`` and
0, and unset durations read as infinite (measured with rclpy Kilted and
Fast DDS). ``ros2 bag play`` needs these to choose its publishers' QoS.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from turtletui.graph.qos import Policies, offered

INFINITE = (9223372036, 854775807)
"""RMW_DURATION_INFINITE as rosbag2 writes it: (sec, nsec)."""


@dataclass(frozen=True)
class OfferedQos:
    """The policies of one publisher that matter to a subscriber."""

    reliability: str = "reliable"
    durability: str = "volatile"
    lifespan: tuple[int, int] = INFINITE

    @classmethod
    def of(cls, qos: Any) -> OfferedQos:
        """What a publisher made with ``qos`` (a QoSProfile, Policies or None) offers."""
        policies = offered(qos)
        return cls(
            "best_effort" if policies.reliability == _BEST_EFFORT else "reliable",
            "transient_local" if policies.durability == _TRANSIENT_LOCAL else "volatile",
        )

    def policies(self) -> Policies:
        """This offer as the graph matches it."""
        return Policies.named(self.reliability, self.durability)

    def yaml_lines(self) -> list[str]:
        """This profile as one item of a YAML block sequence (yaml-cpp's layout)."""
        def duration(key: str, value: tuple[int, int]) -> list[str]:
            return [f"  {key}:", f"    sec: {value[0]}", f"    nsec: {value[1]}"]

        return [
            "- history: unknown",
            "  depth: 0",
            f"  reliability: {self.reliability}",
            f"  durability: {self.durability}",
            *duration("deadline", INFINITE),
            *duration("lifespan", self.lifespan),
            "  liveliness: automatic",
            *duration("liveliness_lease_duration", INFINITE),
            "  avoid_ros_namespace_conventions: false",
        ]


_BEST_EFFORT, _TRANSIENT_LOCAL = Policies.named("best_effort", "transient_local")[:2]

DEFAULT = OfferedQos()
"""rclcpp's and rclpy's default: reliable, volatile."""

LATCHED = OfferedQos(durability="transient_local")
"""A latched topic: late subscribers get the last message (the scene)."""

ROSOUT = OfferedQos(durability="transient_local", lifespan=(10, 0))
"""rcl's /rosout publisher: transient local, messages live 10 s."""


def profiles_yaml(profiles: list[OfferedQos]) -> str:
    """The ``offered_qos_profiles`` string of an MCAP channel (YAML::Dump's text)."""
    return "\n".join(line for profile in profiles for line in profile.yaml_lines())


_RELIABILITY_NAMES = {1: "reliable", 2: "best_effort"}
_DURABILITY_NAMES = {1: "transient_local", 2: "volatile"}
"""rmw's numbers, as metadata before version 9 stored the policies."""


def parse_profiles(text: str) -> list[OfferedQos]:
    """The profiles of a channel's ``offered_qos_profiles``; [] when there are
    none or the text is not rosbag2's (as rosbag2 then offers its default)."""
    import yaml

    try:
        items = yaml.safe_load(text) if text else None
    except yaml.YAMLError:
        return []
    if not isinstance(items, list):
        return []
    profiles = []
    for item in items:
        if isinstance(item, dict):
            reliability = item.get("reliability", "reliable")
            durability = item.get("durability", "volatile")
            profiles.append(OfferedQos(
                str(_RELIABILITY_NAMES.get(reliability, reliability)),
                str(_DURABILITY_NAMES.get(durability, durability)),
            ))
    return profiles


def adapted_offer(profiles: Sequence[OfferedQos]) -> OfferedQos | None:
    """What ``ros2 bag play`` offers on a topic recorded with ``profiles``
    (rosbag2_storage's adapt_offer_to_recorded_offers): the recorded offer
    when every publisher made the same, else rosbag2's default; None when
    the publishers differed (rosbag2 warns of that)."""
    if not profiles:
        return DEFAULT
    first = profiles[0]
    if all(p.policies() == first.policies() for p in profiles):
        return first
    return None


def mixed_offers_warning(topic: str) -> str:
    """What rosbag2_storage warns (logger ``rosbag2_storage``) when a topic's
    publishers offered different QoS."""
    return (
        f"Not all original publishers on topic {topic} offered the same QoS profiles. "
        "Rosbag2 cannot yet choose an adapted profile to offer for this mixed case. "
        "Falling back to the rosbag2_storage default publisher offer."
    )
