"""Offered QoS profiles as rosbag2 stores them (metadata version 9).

rosbag2 records what each publisher offers, as the middleware reports it:
history and depth are not sent over discovery, so they read ``unknown`` and
0, and unset durations read as infinite (measured with rclpy Kilted and
Fast DDS). ``ros2 bag play`` needs these to choose its publishers' QoS.
"""

from __future__ import annotations

from dataclasses import dataclass

INFINITE = (9223372036, 854775807)
"""RMW_DURATION_INFINITE as rosbag2 writes it: (sec, nsec)."""


@dataclass(frozen=True)
class OfferedQos:
    """The policies of one publisher that matter to a subscriber."""

    reliability: str = "reliable"
    durability: str = "volatile"
    lifespan: tuple[int, int] = INFINITE

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


DEFAULT = OfferedQos()
"""rclcpp's and rclpy's default: reliable, volatile."""

LATCHED = OfferedQos(durability="transient_local")
"""A latched topic: late subscribers get the last message (the scene)."""

ROSOUT = OfferedQos(durability="transient_local", lifespan=(10, 0))
"""rcl's /rosout publisher: transient local, messages live 10 s."""


def profiles_yaml(profiles: list[OfferedQos]) -> str:
    """The ``offered_qos_profiles`` string of an MCAP channel (YAML::Dump's text)."""
    return "\n".join(line for profile in profiles for line in profile.yaml_lines())
