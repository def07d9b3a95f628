"""rclpy.exceptions: the exception classes rclpy raises, with rclpy's messages.

A student's ``except ParameterNotDeclaredException`` or
``except InvalidTopicNameException`` must catch what turtletui raises, and
the text they see must be the text ROS prints (observed with rclpy 9.1).
The name validators follow rmw's and rcl's rules and report the first
offending character with a caret under it, as rclpy does.
"""

from __future__ import annotations

import re
from typing import Any

from turtletui.compat.identity import as_rclpy

__all__ = [
    "InvalidHandle",
    "InvalidNamespaceException",
    "InvalidNodeNameException",
    "InvalidParameterException",
    "InvalidParameterTypeException",
    "InvalidParameterValueException",
    "InvalidServiceNameException",
    "InvalidTopicNameException",
    "NameValidationException",
    "NoTypeSupportImportedException",
    "NotInitializedException",
    "ParameterAlreadyDeclaredException",
    "ParameterException",
    "ParameterImmutableException",
    "ParameterNotDeclaredException",
    "ParameterUninitializedException",
    "ROSInterruptException",
    "TimerCancelledError",
]


class NotInitializedException(Exception):
    """rclpy.init() was not called (or the context was shut down)."""

    def __init__(self, message: str | None = None) -> None:
        text = "rclpy.init() has not been called."
        super().__init__(f"{text} msg:{message}" if message else text)


class NoTypeSupportImportedException(Exception):
    """A message type without its type support."""

    def __init__(self) -> None:
        super().__init__("no type_support imported")


class InvalidHandle(RuntimeError):
    """An entity (node, publisher, ...) used after it was destroyed."""


class TimerCancelledError(RuntimeError):
    """A timer used after it was canceled."""


class NameValidationException(Exception):
    """A node name, namespace, topic or service name that ROS refuses."""

    def __init__(self, name_type: str, name: str, error_msg: str, invalid_index: int) -> None:
        super().__init__(f"Invalid {name_type}: {error_msg}:\n  '{name}'\n   {' ' * invalid_index}^")
        self._error_msg = error_msg
        """Why, without the name (what rcl's own errors say)."""


class InvalidNamespaceException(NameValidationException):
    def __init__(self, name: str, error_msg: str, invalid_index: int) -> None:
        super().__init__("namespace", name, error_msg, invalid_index)


class InvalidNodeNameException(NameValidationException):
    def __init__(self, name: str, error_msg: str, invalid_index: int) -> None:
        super().__init__("node name", name, error_msg, invalid_index)


class InvalidTopicNameException(NameValidationException):
    def __init__(self, name: str, error_msg: str, invalid_index: int) -> None:
        super().__init__("topic name", name, error_msg, invalid_index)


class InvalidServiceNameException(NameValidationException):
    def __init__(self, name: str, error_msg: str, invalid_index: int) -> None:
        super().__init__("service name", name, error_msg, invalid_index)


class ParameterException(Exception):
    """Base of the parameter errors: ``'<what>: <parameter(s)>'``."""

    def __init__(self, error_msg: str, parameters: Any) -> None:
        super().__init__(f"{error_msg}: {parameters}")


class ParameterNotDeclaredException(ParameterException):
    def __init__(self, parameters: Any) -> None:
        super().__init__("Invalid access to undeclared parameter(s)", parameters)


class ParameterAlreadyDeclaredException(ParameterException):
    def __init__(self, parameters: Any) -> None:
        super().__init__("Parameter(s) already declared", parameters)


class InvalidParameterException(ParameterException):
    def __init__(self, parameter_name: str) -> None:
        super().__init__("Invalid parameter name", parameter_name)


class InvalidParameterTypeException(ParameterException):
    """A parameter set to a value of another type than it was declared with."""

    def __init__(self, desired_parameter: Any, expected_type: Any) -> None:
        from turtletui.compat.parameter import Parameter

        value = desired_parameter.value
        got = Parameter.Type.from_parameter_value(value).name
        expected = getattr(expected_type, "name", expected_type)
        hint = ""
        if expected == "DOUBLE" and got == "INTEGER":  # a teaching aid beyond rclpy's text
            hint = f" (write {value}.0: ROS reads {value} as an integer)"
        super().__init__(
            f"Trying to set parameter '{desired_parameter.name}' to '{value}' of type '{got}',"
            f" expecting type '{expected}'",
            f"{desired_parameter.name}{hint}",
        )


class InvalidParameterValueException(ParameterException):
    def __init__(self, parameter: str, value: Any, reason: str) -> None:
        super().__init__(f"Invalid parameter value ({value}) for parameter. Reason: {reason}", parameter)


class ParameterImmutableException(ParameterException):
    def __init__(self, parameter_name: str) -> None:
        super().__init__("Attempted to modify read-only parameter", parameter_name)


class ParameterUninitializedException(ParameterException):
    def __init__(self, parameter_name: str) -> None:
        super().__init__(f"The parameter '{parameter_name}' is not initialized", parameter_name)


class ROSInterruptException(Exception):
    def __init__(self) -> None:
        super().__init__("rclpy.shutdown() has been called")


# -- name validation (rmw_validate_node_name, rmw_validate_namespace, rcl_validate_topic_name) --

_NODE_NAME_MAX = 255
_NOT_ALNUM = re.compile(r"[^A-Za-z0-9_]")


def validate_node_name(name: str) -> None:
    """InvalidNodeNameException unless ``name`` is a valid ROS node name."""
    if not name:
        raise InvalidNodeNameException(name, "node name must not be empty", 0)
    bad = _NOT_ALNUM.search(name)
    if bad:
        raise InvalidNodeNameException(
            name, "node name must not contain characters other than alphanumerics or '_'", bad.start()
        )
    if name[0].isdigit():
        raise InvalidNodeNameException(name, "node name must not start with a number", 0)
    if len(name) > _NODE_NAME_MAX:
        raise InvalidNodeNameException(name, f"node name length should not exceed '{_NODE_NAME_MAX}'", _NODE_NAME_MAX)


def validate_namespace(namespace: str) -> None:
    """InvalidNamespaceException unless ``namespace`` (absolute) is valid."""
    if not namespace:
        raise InvalidNamespaceException(namespace, "namespace must not be empty", 0)
    if namespace[0] != "/":
        raise InvalidNamespaceException(namespace, "namespace must be absolute, it must lead with a '/'", 0)
    if len(namespace) > 1 and namespace.endswith("/"):
        raise InvalidNamespaceException(
            namespace, "namespace must not end with a '/', unless only a '/'", len(namespace) - 1
        )
    for i, char in enumerate(namespace):
        if not (char.isascii() and (char.isalnum() or char in "_/")):
            raise InvalidNamespaceException(
                namespace, "namespace must not contain characters other than alphanumerics, '_', or '/'", i
            )
    for i in range(1, len(namespace)):
        if namespace[i] == "/" and namespace[i - 1] == "/":
            raise InvalidNamespaceException(namespace, "namespace must not contain repeated '/'", i)
        if namespace[i].isdigit() and namespace[i - 1] == "/":
            raise InvalidNamespaceException(
                namespace, "namespace must not have a token that starts with a number", i
            )


def validate_topic_name(name: str, *, is_service: bool = False) -> None:
    """InvalidTopicNameException (or InvalidServiceNameException) unless ``name``,
    as the program wrote it (before expansion), is a valid topic name: rcl's
    checks in rcl's order (rcl_validate_topic_name), so the first fault found
    and its index are rcl's."""
    error = InvalidServiceNameException if is_service else InvalidTopicNameException
    if not name:
        raise error(name, "topic name must not be empty string", 0)
    if name[0] in _DIGITS:
        raise error(name, _TOKEN_STARTS_WITH_NUMBER, 0)
    if name.endswith("/"):
        raise error(name, "topic name must not end with a forward slash", len(name) - 1)
    in_braces = False
    opened = 0
    for i, char in enumerate(name):
        if char.isascii() and char.isalnum():
            if char in _DIGITS and in_braces and i - 1 == opened:
                raise error(name, "substitution name must not start with a number", i)
        elif char == "_":
            pass
        elif char == "/":
            if in_braces:
                raise error(name, _SUBSTITUTION_CHARACTERS, i)
        elif char == "~":
            if i != 0:
                raise error(name, "topic name must not have tilde '~' unless it is the first character", i)
        elif char == "{":
            if in_braces:
                raise error(name, _SUBSTITUTION_CHARACTERS, i)
            in_braces, opened = True, i
        elif char == "}":
            if not in_braces:
                raise error(name, _UNMATCHED_BRACES, i)
            in_braces = False
        else:
            message = _SUBSTITUTION_CHARACTERS if in_braces else (
                "topic name must not contain characters other than alphanumerics, '_', '~', '{', or '}'"
            )
            raise error(name, message, i)
    if in_braces:
        raise error(name, _UNMATCHED_BRACES, opened)
    for i in range(len(name) - 1):
        if name[i] == "/":
            if name[i + 1] in _DIGITS:
                raise error(name, _TOKEN_STARTS_WITH_NUMBER, i + 1)
        elif i == 1 and name[0] == "~":
            raise error(name, "topic name must not have a tilde '~' that is not followed by a forward slash '/'", 1)


_DIGITS = "0123456789"
_TOKEN_STARTS_WITH_NUMBER = "topic name token must not start with a number"
_UNMATCHED_BRACES = "topic name must not have unmatched (unbalanced) curly braces '{}'"
_SUBSTITUTION_CHARACTERS = "substitution name must not contain characters other than alphanumerics or '_'"


def validate_full_topic_name(name: str, *, is_service: bool = False) -> None:
    """The check rmw makes on a fully qualified name (rmw_validate_full_topic_name)."""
    error = InvalidServiceNameException if is_service else InvalidTopicNameException
    if not name:
        raise error(name, "topic name must not be empty", 0)
    if name[0] != "/":
        raise error(name, "topic name must be absolute, it must lead with a '/'", 0)
    if name.endswith("/"):
        raise error(name, "topic name must not end with a '/'", len(name) - 1)
    for i, char in enumerate(name):
        if not (char.isascii() and (char.isalnum() or char in "_/")):
            raise error(name, "topic name must not contain characters other than alphanumerics, '_', or '/'", i)
    for i in range(1, len(name)):
        if name[i - 1] == "/" and name[i] == "/":
            raise error(name, "topic name must not contain repeated '/'", i)
        if name[i - 1] == "/" and name[i].isdigit():
            raise error(name, "topic name must not have a token that starts with a number", i)


# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.exceptions", NotInitializedException, NoTypeSupportImportedException, NameValidationException, InvalidNamespaceException, InvalidNodeNameException, InvalidTopicNameException, InvalidServiceNameException, ParameterException, ParameterNotDeclaredException, ParameterAlreadyDeclaredException, InvalidParameterException, InvalidParameterTypeException, InvalidParameterValueException, ParameterImmutableException, ParameterUninitializedException, ROSInterruptException)
as_rclpy("rclpy._rclpy_pybind11", InvalidHandle, TimerCancelledError)
