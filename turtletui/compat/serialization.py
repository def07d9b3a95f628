"""rclpy.serialization: a message to the CDR bytes rmw (Fast DDS) puts on the wire, and back."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from turtletui.compat.rcl_error import RMWError
from turtletui.compat.type_support import check_for_type_support
from turtletui.interfaces import Message
from turtletui.interfaces.cdr import CODES, SIZES, fixed_size, serialize
from turtletui.interfaces.cdr_reader import CdrError, deserialize

_FAST_CDR_AT = "at /project/src/type_support_common.cpp:139"
"""Where rmw_fastrtps says a failed deserialization comes from (the Kilted wheels' build)."""


def serialize_message(message: Any) -> bytes:
    """The CDR payload of ``message``, header included."""
    if isinstance(message, type) and issubclass(message, Message):
        # a class: its metaclass passes rclpy's check, then rclpy's C code asks the metaclass's class
        raise AttributeError("type object 'type' has no attribute '_TYPE_SUPPORT'")
    check_for_type_support(type(message))
    data = serialize(message)
    return data + bytes(_fast_cdr_size(message) - len(data))


def _fast_cdr_size(message: Any) -> int:
    """The length rmw_fastrtps gives a message's bytes: Fast CDR's computed size,
    which aligns the elements of empty sequences too (their padding comes at the
    end, where rmw leaves memory it never wrote: zeros here) and rounds a
    fixed-size message up to 4 bytes."""
    size = _size(type(message), message, 4)
    return size + (-size % 4 if fixed_size(type(message)) else 0)


def _size(cls: type, message: Any, pos: int) -> int:
    if not cls._FIELDS:
        return pos + 1
    for spec in cls._FIELDS:
        value = spec.get(message)
        values = [value] if spec.array == 0 else value
        if spec.array in (1, 2):
            pos = _aligned(pos, 4) + 4
        code = None if spec.strlen is not None else CODES.get(spec.base)
        if spec.kind == "msg":
            for item in values:
                pos = _size(spec.msg_cls, item, pos)
        elif code is None:
            for item in values:
                pos = _aligned(pos, 4) + 4 + len(item.encode()) + 1
        else:
            pos = _aligned(pos, SIZES[code]) + SIZES[code] * len(values)
    return pos


def _aligned(pos: int, size: int) -> int:
    return pos + -(pos - 4) % size


def raw_callback(callback: Callable[..., Any], with_info: bool) -> Callable[..., Any]:
    """The callback of a subscription made with ``raw=True``: it gets each message's bytes."""
    if with_info:

        @functools.wraps(callback)
        def with_bytes_and_info(msg: Any, info: Any) -> Any:
            return callback(serialize_message(msg), info)

        return with_bytes_and_info

    @functools.wraps(callback)
    def with_bytes(msg: Any) -> Any:
        return callback(serialize_message(msg))

    return with_bytes


def deserialize_message(serialized_message: bytes, message_type: type) -> Any:
    """The ``message_type`` message that ``serialized_message`` holds; RMWError if it holds none."""
    check_for_type_support(message_type)
    if not isinstance(serialized_message, bytes):
        raise TypeError(
            "rclpy_deserialize(): incompatible function arguments. The following argument types are supported:\n"
            "    1. (arg0: bytes, arg1: object) -> object\n\n"
            f"Invoked with: {serialized_message!r}, {message_type!r}"
        )
    if not (isinstance(message_type, type) and issubclass(message_type, Message)):
        raise TypeError(f"deserialize_message() needs a message class, got {message_type!r}")
    try:
        return deserialize(serialized_message, message_type)
    except CdrError:
        package, kind = message_type.__module__.split(".")[:2]
        raise RMWError(
            "failed to deserialize ROS message: Fast CDR exception deserializing message of type"
            f" {package}::{kind}::dds_::{message_type.__name__}_., {_FAST_CDR_AT}"
        ) from None
