"""``rclpy.qos_overriding_options``: QoS a publisher or subscription takes from parameters.

As rclpy's: each policy the options name becomes a read-only parameter
``qos_overrides.<topic>.<publisher|subscription>[_<id>].<policy>`` declared
with the entity's QoS (so a parameter override, ``-p`` or a file, replaces it)
and read back into the profile; the options' callback may then refuse it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

from turtletui.compat import qos as qos_module
from turtletui.compat.exceptions import ParameterAlreadyDeclaredException
from turtletui.compat.identity import as_rclpy
from turtletui.compat.qos import QoSPolicyEnum, QoSPolicyKind, QoSProfile
from turtletui.compat.time import Duration
from turtletui.interfaces.rcl_interfaces import ParameterDescriptor


class InvalidQosOverridesError(Exception):
    """The options' callback refused the QoS the overrides made."""


class QoSOverridingOptions:
    """Which QoS policies of an entity parameters may override, a callback to
    validate the result, and an id for entities of one topic that differ."""

    def __init__(
        self,
        policy_kinds: Iterable[QoSPolicyKind],
        *,
        callback: Callable[[QoSProfile], Any] | None = None,
        entity_id: str | None = None,
    ) -> None:
        self._policy_kinds = policy_kinds
        self._callback = callback
        self._entity_id = entity_id

    @property
    def policy_kinds(self) -> Iterable[QoSPolicyKind]:
        return self._policy_kinds

    @property
    def callback(self) -> Callable[[QoSProfile], Any] | None:
        return self._callback

    @property
    def entity_id(self) -> str | None:
        return self._entity_id

    @classmethod
    def with_default_policies(
        cls, *, callback: Callable[[QoSProfile], Any] | None = None, entity_id: str | None = None
    ) -> QoSOverridingOptions:
        """History, depth and reliability."""
        return cls(
            policy_kinds=(QoSPolicyKind.HISTORY, QoSPolicyKind.DEPTH, QoSPolicyKind.RELIABILITY),
            callback=callback,
            entity_id=entity_id,
        )


_DURATIONS = (QoSPolicyKind.LIFESPAN, QoSPolicyKind.DEADLINE, QoSPolicyKind.LIVELINESS_LEASE_DURATION)
_ENUMS = (QoSPolicyKind.LIVELINESS, QoSPolicyKind.RELIABILITY, QoSPolicyKind.HISTORY, QoSPolicyKind.DURABILITY)


def declare_qos_parameters(
    entity: str, node: Any, topic_name: str, qos: QoSProfile, options: QoSOverridingOptions
) -> None:
    """Declare the parameters ``options`` name for a ``"publisher"`` or ``"subscription"``
    of ``topic_name`` (fully qualified) and apply their values to ``qos``."""
    id_suffix = "" if options.entity_id is None else f"_{options.entity_id}"
    name = f"qos_overrides.{topic_name}.{entity}{id_suffix}." "{}"
    description = "{}" f" for {entity} `{topic_name}` with id `{options.entity_id}`"
    for policy in options.policy_kinds:
        if entity == "subscription" and policy is QoSPolicyKind.LIFESPAN:
            continue
        policy_name = policy.name.lower()
        descriptor = ParameterDescriptor(description=description.format(policy_name), read_only=True)
        try:
            parameter = node.declare_parameter(name.format(policy_name), _policy_value(qos, policy), descriptor)
        except ParameterAlreadyDeclaredException:
            parameter = node.get_parameter(name.format(policy_name))
        _apply(qos, policy, parameter.value)
    if options.callback is not None:
        result = options.callback(qos)
        if not result.successful:
            raise InvalidQosOverridesError(
                f"{description.format('Provided QoS overrides')}, are not valid: {result.reason}"
            )


def _policy_value(qos: QoSProfile, policy: QoSPolicyKind) -> str | int | bool:
    value = getattr(qos, policy.name.lower())
    if isinstance(value, QoSPolicyEnum):
        if value.name == "UNKNOWN":
            raise ValueError("User provided QoS profile is invalid")
        return value.name.lower()
    if isinstance(value, Duration):
        return value.nanoseconds
    return value


def _apply(qos: QoSProfile, policy: QoSPolicyKind, value: Any) -> None:
    policy_name = policy.name.lower()
    if policy in _ENUMS:
        enum = getattr(qos_module, f"{policy_name[0].upper()}{policy_name[1:]}Policy")
        try:
            value = enum[value.upper()]
        except KeyError:
            raise RuntimeError(f"Unexpected QoS override for policy `{policy_name}`: `{value}`") from None
    if policy in _DURATIONS:
        value = Duration(nanoseconds=value)
    setattr(qos, policy_name, value)


as_rclpy("rclpy.qos_overriding_options", QoSOverridingOptions, InvalidQosOverridesError)
