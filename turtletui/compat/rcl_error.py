"""rclpy's error from the rcl layer, shared by every part of the compat layer that raises it."""

from __future__ import annotations


class RCLError(RuntimeError):
    """An error from rcl, as ``rclpy._rclpy_pybind11.RCLError`` (an invalid goal
    or lifecycle transition, a topic used with two types in one process...)."""

    __module__ = "rclpy._rclpy_pybind11"  # as tracebacks name rclpy's


class UnknownROSArgsError(RuntimeError):
    """rclpy.init(args=...) with flags after --ros-args that rcl does not know; its text
    is the list of them, as rclpy's."""

    __module__ = "rclpy._rclpy_pybind11"


def topic_type_error(kind: str, name: str, type_name: str) -> RCLError:
    """What rcl raises when a process asks for ``name`` with another type than
    it already uses there (Fast DDS refuses a second type in one participant);
    ``kind`` is "publisher" or "subscription"."""
    package, _, short = type_name.partition("/msg/")
    return RCLError(
        f"Failed to create {kind}: create_{kind}() called for existing topic name rt{name} "
        f"with incompatible type {package}::msg::dds_::{short}_"
    )


class RMWError(RuntimeError):
    """An error from the middleware, as ``rclpy._rclpy_pybind11.RMWError`` (bytes
    that do not deserialize as the type asked)."""

    __module__ = "rclpy._rclpy_pybind11"
