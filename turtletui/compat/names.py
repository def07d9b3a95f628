"""rclpy's modules for names: the validate_* functions (True, or rclpy's exception),
``expand_topic_name`` and ``topic_or_service_is_hidden``."""

from __future__ import annotations

import re
from typing import Literal

from turtletui.compat import exceptions
from turtletui.compat.exceptions import NameValidationException

RCL_EXPAND_AT = "at /project/src/rcl/expand_topic_name.c:"
"""Where rcl's errors for a name it cannot expand say they come from (the Kilted wheels' build)."""
_SUBSTITUTION = re.compile(r"\{[^}]*\}")
_KNOWN = ("{node}", "{ns}", "{namespace}")
"""The substitutions rcl makes in a topic name."""


def unknown_substitution(topic: str) -> str | None:
    """The first ``{...}`` of ``topic`` rcl cannot substitute, if any."""
    return next((found for found in _SUBSTITUTION.findall(topic) if found not in _KNOWN), None)


def check_substitutions(topic: str) -> None:
    """A ValueError with rcl's text (rclpy's expand_topic_name's) for an unknown substitution."""
    unknown = unknown_substitution(topic)
    if unknown is not None:
        raise ValueError(f"topic name '{topic}' is invalid: unknown substitution: {unknown}, {RCL_EXPAND_AT}164")


def validate_node_name(node_name: str) -> Literal[True]:
    exceptions.validate_node_name(node_name)
    return True


def validate_namespace(namespace: str) -> Literal[True]:
    exceptions.validate_namespace(namespace)
    return True


def validate_topic_name(name: str, *, is_service: bool = False) -> Literal[True]:
    exceptions.validate_topic_name(name, is_service=is_service)
    return True


def validate_full_topic_name(name: str, *, is_service: bool = False) -> Literal[True]:
    exceptions.validate_full_topic_name(name, is_service=is_service)
    return True


def expand_topic_name(topic_name: str, node_name: str, node_namespace: str) -> str:
    """``topic_name`` fully qualified for a node ``node_name`` in ``node_namespace``, as
    rcl_expand_topic_name: ``~``, ``{node}``, ``{ns}`` and ``{namespace}`` substituted;
    ValueError with rcl's text for an invalid name or an unknown substitution."""
    checks = (
        ("topic name", topic_name, exceptions.validate_topic_name, 73),
        ("node name", node_name, exceptions.validate_node_name, 84),
        ("node namespace", node_namespace, exceptions.validate_namespace, 94),
    )
    for what, value, validate, line in checks:
        try:
            validate(value)
        except NameValidationException as err:
            raise ValueError(f"{what} '{value}' is invalid: {err._error_msg}, {RCL_EXPAND_AT}{line}") from None
    node_path = f"{node_namespace.rstrip('/')}/{node_name}"
    substitutions = {"{node}": node_name, "{ns}": node_namespace, "{namespace}": node_namespace}
    check_substitutions(topic_name)
    name = node_path + topic_name[1:] if topic_name.startswith("~") else topic_name
    name = _SUBSTITUTION.sub(lambda match: substitutions[match.group()], name)
    if not name.startswith("/"):
        name = f"{node_namespace.rstrip('/')}/{name}"
    return name


def topic_or_service_is_hidden(name: str) -> bool:
    """Whether a token of ``name`` starts with ``_`` (a hidden topic or service)."""
    return any(token for token in name.split("/") if token.startswith("_"))
