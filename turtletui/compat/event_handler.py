"""``rclpy.event_handler``: QoS event callbacks of publishers and subscriptions.

``create_publisher(..., event_callbacks=PublisherEventCallbacks(...))`` and
``create_subscription(..., event_callbacks=SubscriptionEventCallbacks(...))``
as the QoS demos write them. The incompatible-QoS event is the one turtletui's
graph has (turtletui.compat.matching): an ``incompatible_qos`` callback given
receives rmw's status (``total_count``, ``total_count_change``,
``last_policy_kind``) in place of rclpy's default warning, when an executor
next runs the node, and ``use_default_callbacks=False`` without one silences
the warning, as in rclpy. Matched events are turtletui.compat.matched_events'.
Deadline, liveliness, message-lost and incompatible-type events never happen here (deadline and liveliness are kept, not
enforced; an endpoint of another type never matches); a callback given for
one of them is accepted and never called, which turtletui says once.
"""

from __future__ import annotations

from collections.abc import Callable
from enum import IntEnum
from typing import Any

from turtletui.compat.rcl_error import RCLError
from turtletui.graph.logs import WARN

_PYBIND = "rclpy._rclpy_pybind11"


class QoSPublisherEventType(IntEnum):
    """rcl's publisher event types (rclpy's ``rcl_publisher_event_type_t``)."""

    RCL_PUBLISHER_OFFERED_DEADLINE_MISSED = 0
    RCL_PUBLISHER_LIVELINESS_LOST = 1
    RCL_PUBLISHER_OFFERED_INCOMPATIBLE_QOS = 2
    RCL_PUBLISHER_INCOMPATIBLE_TYPE = 3
    RCL_PUBLISHER_MATCHED = 4


class QoSSubscriptionEventType(IntEnum):
    """rcl's subscription event types (rclpy's ``rcl_subscription_event_type_t``)."""

    RCL_SUBSCRIPTION_REQUESTED_DEADLINE_MISSED = 0
    RCL_SUBSCRIPTION_LIVELINESS_CHANGED = 1
    RCL_SUBSCRIPTION_REQUESTED_INCOMPATIBLE_QOS = 2
    RCL_SUBSCRIPTION_MESSAGE_LOST = 3
    RCL_SUBSCRIPTION_INCOMPATIBLE_TYPE = 4
    RCL_SUBSCRIPTION_MATCHED = 5


QoSPublisherEventType.__name__ = QoSPublisherEventType.__qualname__ = "rcl_publisher_event_type_t"
QoSPublisherEventType.__module__ = _PYBIND
QoSSubscriptionEventType.__name__ = QoSSubscriptionEventType.__qualname__ = "rcl_subscription_event_type_t"
QoSSubscriptionEventType.__module__ = _PYBIND


class rmw_qos_policy_kind_t(IntEnum):  # noqa: N801 - rclpy's pybind11 name, as events print it
    """The policy an incompatible-QoS event names (equal to ``rclpy.qos.QoSPolicyKind``'s)."""

    RMW_QOS_POLICY_INVALID = 1 << 0
    RMW_QOS_POLICY_DURABILITY = 1 << 1
    RMW_QOS_POLICY_DEADLINE = 1 << 2
    RMW_QOS_POLICY_LIVELINESS = 1 << 3
    RMW_QOS_POLICY_RELIABILITY = 1 << 4
    RMW_QOS_POLICY_HISTORY = 1 << 5
    RMW_QOS_POLICY_LIFESPAN = 1 << 6
    RMW_QOS_POLICY_DEPTH = 1 << 7
    RMW_QOS_POLICY_LIVELINESS_LEASE_DURATION = 1 << 8
    RMW_QOS_POLICY_AVOID_ROS_NAMESPACE_CONVENTIONS = 1 << 9


rmw_qos_policy_kind_t.__module__ = _PYBIND


class UnsupportedEventTypeError(RCLError):
    """Raised for an event the middleware does not support (rclpy's)."""

    __module__ = _PYBIND


def _status(name: str, fields: tuple[str, ...]) -> type:
    """A class like the pybind11 struct rclpy hands an event callback: the
    fields, 0 by default, and the object's default repr under rclpy's name."""

    def __init__(self: Any, **values: Any) -> None:
        for field in fields:
            setattr(self, field, values.pop(field, 0))
        if values:
            raise TypeError(f"{name}() got unexpected fields {sorted(values)}")

    cls = type(name, (), {"__init__": __init__, "__slots__": fields, "__module__": _PYBIND})
    return cls


QoSRequestedIncompatibleQoSInfo = _status(
    "rmw_requested_qos_incompatible_event_status_t", ("last_policy_kind", "total_count", "total_count_change")
)
QoSOfferedIncompatibleQoSInfo = QoSRequestedIncompatibleQoSInfo
QoSSubscriptionMatchedInfo = _status(
    "rmw_matched_status_t", ("current_count", "current_count_change", "total_count", "total_count_change")
)
QoSPublisherMatchedInfo = QoSSubscriptionMatchedInfo
QoSLivelinessChangedInfo = _status(
    "rmw_liveliness_changed_status_t", ("alive_count", "alive_count_change", "not_alive_count", "not_alive_count_change")
)
QoSMessageLostInfo = _status("rmw_message_lost_status_t", ("total_count", "total_count_change"))
QoSRequestedDeadlineMissedInfo = _status("rmw_requested_deadline_missed_status_t", ("total_count", "total_count_change"))
QoSOfferedDeadlineMissedInfo = _status("rmw_offered_deadline_missed_status_t", ("total_count", "total_count_change"))
QoSLivelinessLostInfo = _status("rmw_liveliness_lost_status_t", ("total_count", "total_count_change"))
IncompatibleTypeInfo = _status("rmw_incompatible_type_status_t", ("total_count_change",))

_NEVER_HERE = (
    "{node}: the {events} {callbacks} of its {kind} on '{topic}' {are} never called in turtletui "
    "(it has no such events: deadline and liveliness are not enforced, an endpoint of another type never "
    "matches); its incompatible_qos and matched callbacks are."
)


class SubscriptionEventCallbacks:
    """The event callbacks of a subscription (``create_subscription(event_callbacks=...)``)."""

    def __init__(
        self,
        *,
        deadline: Callable[[Any], None] | None = None,
        incompatible_qos: Callable[[Any], None] | None = None,
        liveliness: Callable[[Any], None] | None = None,
        message_lost: Callable[[Any], None] | None = None,
        incompatible_type: Callable[[Any], None] | None = None,
        matched: Callable[[Any], None] | None = None,
        use_default_callbacks: bool = True,
    ) -> None:
        self.deadline = deadline
        self.incompatible_qos = incompatible_qos
        self.liveliness = liveliness
        self.message_lost = message_lost
        self.incompatible_type = incompatible_type
        self.matched = matched
        self.use_default_callbacks = use_default_callbacks


class PublisherEventCallbacks:
    """The event callbacks of a publisher (``create_publisher(event_callbacks=...)``)."""

    def __init__(
        self,
        *,
        deadline: Callable[[Any], None] | None = None,
        liveliness: Callable[[Any], None] | None = None,
        incompatible_qos: Callable[[Any], None] | None = None,
        incompatible_type: Callable[[Any], None] | None = None,
        matched: Callable[[Any], None] | None = None,
        use_default_callbacks: bool = True,
    ) -> None:
        self.deadline = deadline
        self.liveliness = liveliness
        self.incompatible_qos = incompatible_qos
        self.incompatible_type = incompatible_type
        self.matched = matched
        self.use_default_callbacks = use_default_callbacks


_NEVER_CALLED = ("deadline", "liveliness", "message_lost", "incompatible_type")


def attach_event_callbacks(node: Any, entity: Any, callbacks: Any, kind: str) -> None:
    """Keep ``callbacks`` on a new publisher or subscription ``entity`` (None:
    rclpy's defaults); say once which of them turtletui never calls."""
    if callbacks is None:
        return
    entity._event_callbacks = callbacks
    never = [name for name in _NEVER_CALLED if getattr(callbacks, name, None) is not None]
    if never and not getattr(node.context, "told_event_callbacks", False):
        node.context.told_event_callbacks = True
        text = _NEVER_HERE.format(
            node=node.get_fully_qualified_name(),
            events=" and ".join(never),
            callbacks="callbacks" if len(never) > 1 else "callback",
            are="are" if len(never) > 1 else "is",
            kind=kind,
            topic=entity.topic_name,
        )
        node._graph.log("turtletui", WARN, text)


def incompatible_qos_event(entity: Any, policy: str) -> tuple[Callable[[Any], None] | None, Any] | None:
    """What ``entity`` does with one more incompatible endpoint: ``(callback,
    status)`` for its own ``incompatible_qos`` callback, ``(None, None)`` for
    rclpy's default warning, None for nothing (``use_default_callbacks=False``)."""
    callbacks = getattr(entity, "_event_callbacks", None)
    if callbacks is None:
        return None, None
    callback = getattr(callbacks, "incompatible_qos", None)
    if callback is None:
        return (None, None) if getattr(callbacks, "use_default_callbacks", True) else None
    total = getattr(entity, "_incompatible_total", 0) + 1
    entity._incompatible_total = total
    status = QoSRequestedIncompatibleQoSInfo(
        last_policy_kind=rmw_qos_policy_kind_t[f"RMW_QOS_POLICY_{policy}"], total_count=total, total_count_change=1
    )
    return callback, status
