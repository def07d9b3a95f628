"""ROS 2's type hashes (``RIHS01_<sha256>``), which rosbag2 stores for each topic.

rosidl_generator_type_description hashes a type's description: its fields
(name, type id, array capacity, string bound, nested type) and those of every
type it uses, sorted, as JSON with ``", "`` and ``": "`` separators. A
message without fields has rosidl's ``structure_needs_at_least_one_member``.
"""

from __future__ import annotations

import functools
import hashlib
import json
from typing import Any

from turtletui.recording.schema import interface_of

_TYPE_IDS = {
    "nested": 1, "int8": 2, "uint8": 3, "int16": 4, "uint16": 5, "int32": 6, "uint32": 7,
    "int64": 8, "uint64": 9, "float32": 10, "float64": 11, "char": 3, "bool": 15, "byte": 16,
    "string": 17, "wstring": 18, "bounded_string": 21, "bounded_wstring": 22,
}
_ARRAY_OFFSETS = (0, 144, 96, 48)
"""Added to the id: scalar, unbounded sequence, bounded sequence, fixed array."""


def _field(spec: Any) -> dict[str, Any]:
    if spec.kind == "msg":
        base = "nested"
    elif spec.strlen is not None:
        base = "bounded_wstring" if spec.base.startswith("wstring") else "bounded_string"
    else:
        base = spec.base
    return {
        "name": spec.name,
        "type": {
            "type_id": _TYPE_IDS[base] + _ARRAY_OFFSETS[spec.array],
            "capacity": spec.size or 0,
            "string_capacity": spec.strlen or 0,
            "nested_type_name": spec.msg_cls._TYPE_NAME if spec.kind == "msg" else "",
        },
    }


def _description(cls: type, type_name: str | None = None) -> dict[str, Any]:
    fields = [_field(spec) for spec in cls._FIELDS] or [
        {
            "name": "structure_needs_at_least_one_member",
            "type": {"type_id": 3, "capacity": 0, "string_capacity": 0, "nested_type_name": ""},
        }
    ]
    return {"type_name": type_name or cls._TYPE_NAME, "fields": fields}


def _referenced(cls: type, found: dict[str, type]) -> None:
    for spec in cls._FIELDS:
        if spec.kind == "msg" and spec.msg_cls._TYPE_NAME not in found:
            found[spec.msg_cls._TYPE_NAME] = spec.msg_cls
            _referenced(spec.msg_cls, found)


@functools.cache
def type_hash(type_name: str) -> str:
    """The RIHS01 hash of a recorded message type (``turtlesim/msg/Pose``);
    a request recorded as ``turtlesim/msg/SetPen_Request`` is hashed under that
    name, as readers that check hashes (rosbags) hash the type they are given."""
    cls = interface_of(type_name)
    found: dict[str, type] = {}
    _referenced(cls, found)
    hashable = {
        "type_description": _description(cls, type_name),
        "referenced_type_descriptions": [_description(found[name]) for name in sorted(found)],
    }
    text = json.dumps(hashable, ensure_ascii=True, separators=(", ", ": "))
    return "RIHS01_" + hashlib.sha256(text.encode()).hexdigest()
