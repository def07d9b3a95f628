"""``rclpy.qos``: quality-of-service profiles. Only the history (``depth``, or KEEP_ALL)
changes behaviour here (a queue per subscription); the rest is kept for ROS parity,
with rclpy's checks: a profile needs a history or a depth, and fields are validated."""

from __future__ import annotations

import warnings
from enum import Enum, IntEnum
from typing import Any

from turtletui.compat.identity import as_rclpy
from turtletui.compat.time import Duration
from turtletui.graph.qos import incompatible_policy, is_transient_local  # noqa: F401  (the middleware's matching)


class InvalidQoSProfileException(ValueError):
    """Raised for a QoSProfile without history and depth, as rclpy does. (rclpy's derives
    from Exception only; a ValueError here too, as turtletui raised before.)"""


class QoSPolicyKind(IntEnum):
    """The QoS policies an incompatible-QoS event can name (rmw's values)."""

    INVALID = 1 << 0
    DURABILITY = 1 << 1
    DEADLINE = 1 << 2
    LIVELINESS = 1 << 3
    RELIABILITY = 1 << 4
    HISTORY = 1 << 5
    LIFESPAN = 1 << 6
    DEPTH = 1 << 7
    LIVELINESS_LEASE_DURATION = 1 << 8
    AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9


def qos_policy_name_from_kind(policy_kind: QoSPolicyKind | int) -> str:
    """The name of a QoS policy kind (``QoSPolicyKind.RELIABILITY`` or 16: "RELIABILITY")."""
    return QoSPolicyKind(policy_kind).name


class QoSPolicyEnum(IntEnum):
    """Base of the QoS policy enums."""

    @classmethod
    def short_keys(cls) -> list[str]:
        return [k.lower() for k in cls.__members__]

    @classmethod
    def get_from_short_key(cls, name: str) -> int:
        return cls[name.upper()].value

    @property
    def short_key(self) -> str:
        return self.name.lower()


class HistoryPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    KEEP_LAST = 1
    KEEP_ALL = 2
    UNKNOWN = 3


class ReliabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    RELIABLE = 1
    BEST_EFFORT = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class DurabilityPolicy(QoSPolicyEnum):
    SYSTEM_DEFAULT = 0
    TRANSIENT_LOCAL = 1
    VOLATILE = 2
    UNKNOWN = 3
    BEST_AVAILABLE = 4


class LivelinessPolicy(QoSPolicyEnum):
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

# rmw's qos_profile_default: what a QoSProfile field left as None becomes.
_DEFAULTS: dict[str, Any] = {
    "depth": 10,
    "reliability": ReliabilityPolicy.RELIABLE,
    "durability": DurabilityPolicy.VOLATILE,
    "liveliness": LivelinessPolicy.SYSTEM_DEFAULT,
    "avoid_ros_namespace_conventions": False,
}


class QoSProfile:
    """A QoS profile. ``QoSProfile(depth=10)`` keeps the last 10 messages; a history or
    a depth is required, as in rclpy."""

    __slots__ = (
        "_history",
        "_depth",
        "_reliability",
        "_durability",
        "_lifespan",
        "_deadline",
        "_liveliness",
        "_liveliness_lease_duration",
        "_avoid_ros_namespace_conventions",
    )

    def __init__(
        self,
        history: HistoryPolicy | int | None = None,
        depth: int | None = None,
        reliability: ReliabilityPolicy | int | None = None,
        durability: DurabilityPolicy | int | None = None,
        lifespan: Duration | None = None,
        deadline: Duration | None = None,
        liveliness: LivelinessPolicy | int | None = None,
        liveliness_lease_duration: Duration | None = None,
        avoid_ros_namespace_conventions: bool | None = None,
    ) -> None:
        if history is None:
            if depth is None:
                raise InvalidQoSProfileException("History and/or depth settings are required.")
            history = HistoryPolicy.KEEP_LAST
        self.history = history
        if self.history == HistoryPolicy.KEEP_LAST and depth is None:
            raise InvalidQoSProfileException(
                "History set to KEEP_LAST without a depth setting (KEEP_LAST requires a depth)."
            )
        self.depth = _DEFAULTS["depth"] if depth is None else depth
        self.reliability = _DEFAULTS["reliability"] if reliability is None else reliability
        self.durability = _DEFAULTS["durability"] if durability is None else durability
        self.lifespan = Duration() if lifespan is None else lifespan
        self.deadline = Duration() if deadline is None else deadline
        self.liveliness = _DEFAULTS["liveliness"] if liveliness is None else liveliness
        self.liveliness_lease_duration = (
            Duration() if liveliness_lease_duration is None else liveliness_lease_duration
        )
        self.avoid_ros_namespace_conventions = (
            _DEFAULTS["avoid_ros_namespace_conventions"]
            if avoid_ros_namespace_conventions is None
            else avoid_ros_namespace_conventions
        )

    @property
    def history(self) -> HistoryPolicy:
        return self._history

    @history.setter
    def history(self, value: HistoryPolicy | int) -> None:
        assert isinstance(value, int), f"history must be a HistoryPolicy, got {value!r}"
        self._history = HistoryPolicy(value)

    @property
    def depth(self) -> int:
        return self._depth

    @depth.setter
    def depth(self, value: int) -> None:
        assert isinstance(value, int), f"depth must be an int, got {value!r}"
        if self.history == HistoryPolicy.KEEP_LAST and value == 0:
            warnings.warn(
                "A zero depth with KEEP_LAST doesn't make sense; no data could be stored. "
                "This will be interpreted as SYSTEM_DEFAULT",
                stacklevel=2,
            )
        self._depth = value

    @property
    def reliability(self) -> ReliabilityPolicy:
        return self._reliability

    @reliability.setter
    def reliability(self, value: ReliabilityPolicy | int) -> None:
        assert isinstance(value, int), f"reliability must be a ReliabilityPolicy, got {value!r}"
        self._reliability = ReliabilityPolicy(value)

    @property
    def durability(self) -> DurabilityPolicy:
        return self._durability

    @durability.setter
    def durability(self, value: DurabilityPolicy | int) -> None:
        assert isinstance(value, int), f"durability must be a DurabilityPolicy, got {value!r}"
        self._durability = DurabilityPolicy(value)

    @property
    def lifespan(self) -> Duration:
        return self._lifespan

    @lifespan.setter
    def lifespan(self, value: Duration) -> None:
        assert isinstance(value, Duration), f"lifespan must be a Duration, got {value!r}"
        self._lifespan = value

    @property
    def deadline(self) -> Duration:
        return self._deadline

    @deadline.setter
    def deadline(self, value: Duration) -> None:
        assert isinstance(value, Duration), f"deadline must be a Duration, got {value!r}"
        self._deadline = value

    @property
    def liveliness(self) -> LivelinessPolicy:
        return self._liveliness

    @liveliness.setter
    def liveliness(self, value: LivelinessPolicy | int) -> None:
        assert isinstance(value, int), f"liveliness must be a LivelinessPolicy, got {value!r}"
        self._liveliness = LivelinessPolicy(value)

    @property
    def liveliness_lease_duration(self) -> Duration:
        return self._liveliness_lease_duration

    @liveliness_lease_duration.setter
    def liveliness_lease_duration(self, value: Duration) -> None:
        assert isinstance(value, Duration), f"liveliness_lease_duration must be a Duration, got {value!r}"
        self._liveliness_lease_duration = value

    @property
    def avoid_ros_namespace_conventions(self) -> bool:
        return self._avoid_ros_namespace_conventions

    @avoid_ros_namespace_conventions.setter
    def avoid_ros_namespace_conventions(self, value: bool) -> None:
        assert isinstance(value, bool), f"avoid_ros_namespace_conventions must be a bool, got {value!r}"
        self._avoid_ros_namespace_conventions = value

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, QoSProfile):
            return False
        return all(getattr(self, slot) == getattr(other, slot) for slot in self.__slots__)

    __hash__ = None  # type: ignore[assignment]  # as rclpy's

    def __str__(self) -> str:
        # rclpy's format: IntEnum fields print as numbers, durations as 'N nanoseconds'.
        return f"{type(self).__name__}(%s)" % ", ".join(
            f"{slot[1:]}=%s" % _plain(getattr(self, slot)) for slot in self.__slots__
        )


def _plain(value: Any) -> Any:
    return int(value) if isinstance(value, IntEnum) else value


def _preset(history: HistoryPolicy, depth: int, reliability: ReliabilityPolicy, durability: DurabilityPolicy) -> QoSProfile:
    return QoSProfile(
        history=history,
        depth=depth,
        reliability=reliability,
        durability=durability,
        liveliness=LivelinessPolicy.SYSTEM_DEFAULT,
    )


# The presets as rmw (and rcl_action) define them.
qos_profile_default = _preset(HistoryPolicy.KEEP_LAST, 10, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_sensor_data = _preset(
    HistoryPolicy.KEEP_LAST, 5, ReliabilityPolicy.BEST_EFFORT, DurabilityPolicy.VOLATILE
)
qos_profile_system_default = _preset(
    HistoryPolicy.SYSTEM_DEFAULT, 0, ReliabilityPolicy.SYSTEM_DEFAULT, DurabilityPolicy.SYSTEM_DEFAULT
)
qos_profile_services_default = _preset(
    HistoryPolicy.KEEP_LAST, 10, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE
)
qos_profile_parameters = _preset(HistoryPolicy.KEEP_LAST, 1000, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE)
qos_profile_parameter_events = _preset(
    HistoryPolicy.KEEP_LAST, 1000, ReliabilityPolicy.RELIABLE, DurabilityPolicy.VOLATILE
)
qos_profile_action_status_default = _preset(
    HistoryPolicy.KEEP_LAST, 1, ReliabilityPolicy.RELIABLE, DurabilityPolicy.TRANSIENT_LOCAL
)

qos_profile_rosout_default = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=1000,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
    lifespan=Duration(seconds=10),
    liveliness=LivelinessPolicy.SYSTEM_DEFAULT,
)

qos_profile_unknown = QoSProfile(
    history=HistoryPolicy.UNKNOWN,
    depth=0,
    reliability=ReliabilityPolicy.UNKNOWN,
    durability=DurabilityPolicy.UNKNOWN,
    liveliness=LivelinessPolicy.UNKNOWN,
)
qos_profile_best_available = _preset(
    HistoryPolicy.KEEP_LAST, 10, ReliabilityPolicy.BEST_AVAILABLE, DurabilityPolicy.BEST_AVAILABLE
)
qos_profile_best_available.liveliness = LivelinessPolicy.BEST_AVAILABLE
# rmw's RMW_QOS_DEADLINE_BEST_AVAILABLE and RMW_QOS_LIVELINESS_LEASE_DURATION_BEST_AVAILABLE
qos_profile_best_available.deadline = Duration(nanoseconds=2**63 - 2)
qos_profile_best_available.liveliness_lease_duration = Duration(nanoseconds=2**63 - 2)


class QoSPresetProfiles(Enum):
    """The presets by name, as rclpy's (presets equal to an earlier one are its aliases)."""

    UNKNOWN = qos_profile_unknown
    DEFAULT = qos_profile_default
    SYSTEM_DEFAULT = qos_profile_system_default
    SENSOR_DATA = qos_profile_sensor_data
    SERVICES_DEFAULT = qos_profile_services_default
    PARAMETERS = qos_profile_parameters
    PARAMETER_EVENTS = qos_profile_parameter_events
    ACTION_STATUS_DEFAULT = qos_profile_action_status_default
    BEST_AVAILABLE = qos_profile_best_available
    ROSOUT_DEFAULT = qos_profile_rosout_default

    @classmethod
    def short_keys(cls) -> list[str]:
        return [k.lower() for k in cls.__members__ if not k.startswith("RMW")]

    @classmethod
    def get_from_short_key(cls, name: str) -> QoSProfile:
        return cls[name.upper()].value


KEEP_ALL_DEPTH = 10_000
"""Queue length standing in for KEEP_ALL (unbounded in DDS, up to its resource limits)."""


def profile_of(qos_or_depth: QoSProfile | int) -> QoSProfile:
    """The QoSProfile a ``create_publisher``/``create_subscription`` argument stands for (an
    int is a KEEP_LAST depth), with rclpy's errors (Node._validate_qos_or_depth_parameter)."""
    if isinstance(qos_or_depth, QoSProfile):
        return qos_or_depth
    if isinstance(qos_or_depth, int):
        if qos_or_depth < 0:
            raise ValueError("history depth must be greater than or equal to zero")
        return QoSProfile(depth=qos_or_depth)
    raise TypeError(f"Expected QoSProfile or int, but received {type(qos_or_depth)!r}")


def depth_of(qos_profile: QoSProfile | int) -> int:
    """The queue length a ``create_publisher``/``create_subscription`` argument asks for.

    KEEP_ALL keeps (nearly) everything; SYSTEM_DEFAULT history, and a depth of 0, mean the
    DDS default, which keeps the last message."""
    qos_profile = profile_of(qos_profile)
    if qos_profile.history == HistoryPolicy.KEEP_ALL:
        return KEEP_ALL_DEPTH
    if qos_profile.history == HistoryPolicy.KEEP_LAST:
        return max(qos_profile.depth, 1)
    return 1

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.qos", QoSProfile, HistoryPolicy, ReliabilityPolicy, DurabilityPolicy, LivelinessPolicy, QoSPresetProfiles, QoSPolicyKind)
