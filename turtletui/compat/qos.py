"""``rclpy.qos``: quality-of-service profiles. Only ``depth`` changes behaviour
here (a keep-last queue per subscription); the rest is kept for ROS parity."""

from __future__ import annotations

from enum import IntEnum

from turtletui.compat.time import Duration


class HistoryPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(IntEnum):
    SYSTEM_DEFAULT = 0
    AUTOMATIC = 1
    MANUAL_BY_TOPIC = 3
    UNKNOWN = 4
    BEST_AVAILABLE = 5


# Older spellings still found in course code.
QoSHistoryPolicy = HistoryPolicy
QoSReliabilityPolicy = ReliabilityPolicy
QoSDurabilityPolicy = DurabilityPolicy
QoSLivelinessPolicy = LivelinessPolicy


class QoSProfile:
    """A QoS profile; ``depth`` is required with KEEP_LAST, as in rclpy."""

    def __init__(
        self,
        *,
        history: HistoryPolicy = HistoryPolicy.KEEP_LAST,
        depth: int | None = None,
        reliability: ReliabilityPolicy = ReliabilityPolicy.RELIABLE,
        durability: DurabilityPolicy = DurabilityPolicy.VOLATILE,
        lifespan: Duration | None = None,
        deadline: Duration | None = None,
        liveliness: LivelinessPolicy = LivelinessPolicy.SYSTEM_DEFAULT,
        liveliness_lease_duration: Duration | None = None,
        avoid_ros_namespace_conventions: bool = False,
    ) -> None:
        if history == HistoryPolicy.KEEP_LAST and depth is None:
            raise ValueError("History policy KEEP_LAST requires a depth")
        self.history = history
        self.depth = depth if depth is not None else 1000
        self.reliability = reliability
        self.durability = durability
        self.lifespan = lifespan or Duration()
        self.deadline = deadline or Duration()
        self.liveliness = liveliness
        self.liveliness_lease_duration = liveliness_lease_duration or Duration()
        self.avoid_ros_namespace_conventions = avoid_ros_namespace_conventions

    def __repr__(self) -> str:
        return (
            f"QoSProfile(history={self.history.name}, depth={self.depth}, "
            f"reliability={self.reliability.name}, durability={self.durability.name})"
        )

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, QoSProfile):
            return NotImplemented
        return (self.history, self.depth, self.reliability, self.durability) == (
            other.history,
            other.depth,
            other.reliability,
            other.durability,
        )


qos_profile_sensor_data = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
qos_profile_system_default = QoSProfile(history=HistoryPolicy.SYSTEM_DEFAULT, depth=10)
qos_profile_services_default = QoSProfile(depth=10)
qos_profile_parameters = QoSProfile(depth=1000)
qos_profile_parameter_events = QoSProfile(depth=1000)
qos_profile_action_status_default = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


def depth_of(qos_profile: QoSProfile | int) -> int:
    """The queue depth a ``create_publisher``/``create_subscription`` argument asks for."""
    if isinstance(qos_profile, bool) or not isinstance(qos_profile, (int, QoSProfile)):
        raise TypeError(
            f"qos_profile must be a QoSProfile or an int history depth, got {qos_profile!r}"
        )
    if isinstance(qos_profile, int):
        if qos_profile < 0:
            raise ValueError(f"history depth must be >= 0, got {qos_profile}")
        return qos_profile
    return qos_profile.depth
