"""``rclpy.type_support``: whether something is an interface class rclpy can use."""

from __future__ import annotations

from typing import Any

from turtletui.interfaces import Action, Message, Service


def check_for_type_support(msg_or_srv_type: Any) -> None:
    """rclpy's type_support.check_for_type_support: what is not an interface class has no
    ``_TYPE_SUPPORT``, and rclpy adds its ROS 1 hint to Python's AttributeError."""
    if isinstance(msg_or_srv_type, type) and issubclass(msg_or_srv_type, (Message, Service, Action)):
        return
    try:
        msg_or_srv_type._TYPE_SUPPORT  # noqa: B018 - the AttributeError, in Python's own words
    except AttributeError as err:
        err.args = (
            err.args[0] + " This might be a ROS 1 message type but it should be a ROS 2 message type."
            " Make sure to source your ROS 2 workspace after your ROS 1 workspace.",
            *err.args[1:],
        )
        raise

