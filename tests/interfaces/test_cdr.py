"""turtletui's CDR writer against independent decoders (mcap_ros2 and rosbags),
for every message type turtletui knows, with every field set."""

from __future__ import annotations

import struct
from typing import Any

import numpy as np
import pytest
from mcap_ros2._dynamic import generate_dynamic
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from turtletui.interfaces import Message, all_interfaces, from_dict, get_interface, to_dict
from turtletui.interfaces.cdr import serialize
from turtletui.interfaces.cdr_reader import CdrError, deserialize
from turtletui.recording.schema import message_definition, recorded_type_name


def _message_classes() -> list[type]:
    classes = []
    for name in all_interfaces():
        cls = get_interface(name)
        if issubclass(cls, Message):
            classes.append(cls)
        elif hasattr(cls, "Request"):
            classes += [cls.Request, cls.Response]
        else:
            classes += [cls.Goal, cls.Result, cls.Feedback]
    return classes


def _has_wstring(cls: type) -> bool:
    return any(
        spec.base.startswith("wstring") or (spec.kind == "msg" and _has_wstring(spec.msg_cls)) for spec in cls._FIELDS
    )


# Neither mcap_ros2 nor rosbags reads wstring (example_interfaces/WString): nothing to check those against.
CLASSES = [cls for cls in _message_classes() if not _has_wstring(cls)]


def _filled(cls: type, salt: int = 0) -> dict[str, Any]:
    """Every field set to a value unlike its default (float32-exact floats,
    integers at the ends of their range, non-ASCII text)."""
    out: dict[str, Any] = {}
    for i, spec in enumerate(cls._FIELDS):
        def one(j: int, spec=spec, i=i) -> Any:
            if spec.kind == "msg":
                return _filled(spec.msg_cls, salt + i + j + 1)
            if spec.kind == "float":
                return 1.5 + 0.25 * (i + j + salt)
            if spec.kind == "int":
                return spec.lo if (i + j) % 2 else spec.hi
            if spec.kind == "bool":
                return True
            if spec.kind == "byte":
                return 200 + j
            text = f"tört{i}-{j}"
            return text[: spec.strlen] if spec.strlen is not None else text

        if spec.array == 0:
            out[spec.name] = one(0)
        else:
            count = spec.size if spec.array == 3 else min(3, spec.size or 3)
            out[spec.name] = [one(j) for j in range(count)]
    return out


def _plain(value: Any, cls: type) -> dict[str, Any]:
    """A decoded message (either library's) as plain dicts, by turtletui's fields
    (rosbags adds constants and the empty message's dummy member)."""
    out = {}
    for spec in cls._FIELDS:
        item = getattr(value, spec.name)
        if spec.kind == "msg":
            out[spec.name] = _plain(item, spec.msg_cls) if spec.array == 0 else [_plain(v, spec.msg_cls) for v in item]
        elif isinstance(item, (bytes, bytearray)):
            out[spec.name] = list(item)
        elif isinstance(item, np.ndarray):
            out[spec.name] = item.tolist()
        elif isinstance(item, np.generic):
            out[spec.name] = item.item()
        else:
            out[spec.name] = list(item) if isinstance(item, (list, tuple)) else item
        if spec.kind == "byte" or spec.base == "char":  # octet and char read as int8 by some
            out[spec.name] = [v % 256 for v in out[spec.name]] if spec.array else out[spec.name] % 256
    return out


@pytest.mark.parametrize("cls", CLASSES, ids=lambda cls: cls._TYPE_NAME)
def test_every_message_decodes_with_mcap_ros2_as_written(cls: type) -> None:
    msg = from_dict(cls, _filled(cls))
    type_name = recorded_type_name(cls._TYPE_NAME)
    decode = generate_dynamic(type_name, message_definition(type_name))[type_name]
    assert _plain(decode(serialize(msg)), cls) == to_dict(msg)


@pytest.mark.parametrize("cls", CLASSES, ids=lambda cls: cls._TYPE_NAME)
def test_every_message_decodes_with_rosbags_as_written(cls: type) -> None:
    msg = from_dict(cls, _filled(cls))
    type_name = recorded_type_name(cls._TYPE_NAME)
    store = get_typestore(Stores.EMPTY)
    store.register(get_types_from_msg(message_definition(type_name), type_name))
    decoded = _plain(store.deserialize_cdr(serialize(msg), type_name), cls)
    assert decoded == to_dict(msg)


def test_defaults_and_empty_messages_decode_too() -> None:
    for cls in CLASSES:
        type_name = recorded_type_name(cls._TYPE_NAME)
        decode = generate_dynamic(type_name, message_definition(type_name))[type_name]
        assert _plain(decode(serialize(cls())), cls) == to_dict(cls()), type_name


def test_a_pose_is_the_bytes_ros_puts_on_the_wire() -> None:
    from turtletui.interfaces.turtlesim import Pose

    data = serialize(Pose(x=1.0, y=2.0, theta=0.5, linear_velocity=1.0, angular_velocity=-0.5))
    # encapsulation header (CDR little endian), then five float32
    assert data.hex() == "00010000" "0000803f" "00000040" "0000003f" "0000803f" "000000bf"


def test_an_empty_sequence_is_its_count_alone() -> None:
    """Fast CDR aligns an array's first element, not an empty one: an empty float64
    sequence before a full one is 4 bytes, as rmw_fastrtps (and rosbags) write it."""
    from turtletui.interfaces.sensor_msgs import JointState

    msg = JointState(name=["left"], position=[0.5], velocity=[], effort=[1.0])
    store = get_typestore(Stores.ROS2_JAZZY)
    assert serialize(msg) == store.serialize_cdr(store.deserialize_cdr(serialize(msg), "sensor_msgs/msg/JointState"),
                                                 "sensor_msgs/msg/JointState")
    assert serialize(msg).hex().endswith("00000000" "01000000" "000000000000f03f")  # no padding between


@pytest.mark.parametrize("cls", CLASSES, ids=lambda cls: cls._TYPE_NAME)
def test_every_message_reads_back_as_written(cls: type) -> None:
    for msg in (from_dict(cls, _filled(cls)), cls()):
        assert deserialize(serialize(msg), cls) == msg


def test_the_header_says_the_byte_order() -> None:
    from turtletui.interfaces.geometry_msgs import Vector3

    assert deserialize(b"\x00\x00\x00\x00" + struct.pack(">3d", 1.0, 2.0, -3.0), Vector3) == Vector3(x=1.0, y=2.0, z=-3.0)


def test_bytes_that_end_too_soon_are_a_cdr_error() -> None:
    from turtletui.interfaces.geometry_msgs import Twist, Vector3
    from turtletui.interfaces.std_msgs import String

    with pytest.raises(CdrError):
        deserialize(serialize(Vector3(x=1.0)), Twist)
    with pytest.raises(CdrError):
        deserialize(b"\x00\x01\x00\x00\x09\x00\x00\x00abc", String)
    assert deserialize(b"\x00\x01\x00\x00\x03\x00\x00\x00abc", String) == String(data="abc")  # no NUL: Fast CDR's too
