"""ROS 2 type descriptions and their hashes (REP 2011), as rosidl generates them.

A type's description lists its fields (name, type id, array capacity, string
bound, nested type name, default value) and those of every type it uses,
sorted by name. A service is described by its request, response and event
messages; an action by its goal, result, feedback, its two services and its
feedback message (rosidl_generator_type_description). Its ``RIHS01_`` hash is
the sha256 of that description without default values, as JSON with ``", "``
and ``": "`` separators: the same text rosidl hashes, so the hashes are ROS's,
byte for byte. The descriptions are plain dicts shaped like
type_description_interfaces/msg/TypeDescription.
"""

from __future__ import annotations

import functools
import hashlib
import json
from collections.abc import Mapping
from typing import Any

from turtletui.interfaces._message import (
    _BOUNDED,
    _FIXED,
    _REGISTRY,
    _SCALAR,
    _SEQ,
    Action,
    Service,
)

_TYPE_IDS = {
    "nested": 1, "int8": 2, "uint8": 3, "int16": 4, "uint16": 5, "int32": 6, "uint32": 7,
    "int64": 8, "uint64": 9, "float32": 10, "float64": 11, "char": 3, "bool": 15, "byte": 16,
    "string": 17, "wstring": 18, "bounded_string": 21, "bounded_wstring": 22,
}
_ARRAY_OFFSETS = {_SCALAR: 0, _FIXED: 48, _BOUNDED: 96, _SEQ: 144}
"""Added to the element's id: scalar, fixed array, bounded sequence, unbounded sequence."""
_EMPTY_STRUCTURE = "structure_needs_at_least_one_member"
"""The uint8 member rosidl gives a message without fields."""


def _field(name: str, type_id: int, *, capacity: int = 0, string_capacity: int = 0, nested: str = "",
           default: str = "") -> dict[str, Any]:
    return {
        "name": name,
        "type": {"type_id": type_id, "capacity": capacity, "string_capacity": string_capacity,
                 "nested_type_name": nested},
        "default_value": default,
    }


def _default_text(spec: Any) -> str:
    """The default as rosidl writes it: Python's str of the parsed value
    (``0.0``, ``True``, ``-2``), the repr of a tuple for arrays."""
    if not spec.has_default:
        return ""
    return repr(tuple(spec.default)) if spec.array != _SCALAR else str(spec.default)


def _message_fields(cls: type) -> list[dict[str, Any]]:
    fields = []
    for spec in cls._FIELDS:
        if spec.kind == "msg":
            base = "nested"
        elif spec.strlen is not None:
            base = "bounded_wstring" if spec.base.startswith("wstring") else "bounded_string"
        else:
            base = spec.base
        fields.append(_field(
            spec.name,
            _TYPE_IDS[base] + _ARRAY_OFFSETS[spec.array],
            capacity=spec.size or 0,
            string_capacity=spec.strlen or 0,
            nested=spec.msg_cls._TYPE_NAME if spec.kind == "msg" else "",
            default=_default_text(spec),
        ))
    return fields or [_field(_EMPTY_STRUCTURE, _TYPE_IDS["uint8"])]


def _nested(name: str, type_name: str) -> dict[str, Any]:
    return _field(name, _TYPE_IDS["nested"], nested=type_name)


def _service_parts(cls: type, found: dict[str, dict[str, Any]]) -> list[dict[str, Any]]:
    """The fields of a service's own description; its request, response and
    event message descriptions go into ``found``."""
    parts = (("request_message", cls.Request), ("response_message", cls.Response), ("event_message", cls.Event))
    for _, part in parts:
        _collect(part, found)
    return [_nested(field, part._TYPE_NAME) for field, part in parts]


def _action_parts(cls: type, found: dict[str, dict[str, Any]]) -> list[dict[str, Any]]:
    impl = cls.Impl
    parts = (
        ("goal", cls.Goal), ("result", cls.Result), ("feedback", cls.Feedback),
        ("send_goal_service", impl.SendGoalService), ("get_result_service", impl.GetResultService),
        ("feedback_message", impl.FeedbackMessage),
    )
    for _, part in parts:
        _collect(part, found)
    return [_nested(field, part._TYPE_NAME) for field, part in parts]


def _collect(cls: type, found: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """``cls``'s own description; every type it uses (at any depth) goes into ``found``."""
    name = cls._TYPE_NAME
    if name in found:
        return found[name]
    if issubclass(cls, Service):
        fields = _service_parts(cls, found)
    elif issubclass(cls, Action):
        fields = _action_parts(cls, found)
    else:
        fields = _message_fields(cls)
        for spec in cls._FIELDS:
            if spec.kind == "msg":
                _collect(spec.msg_cls, found)
    own = found[name] = {"type_name": name, "fields": fields}
    return own


Names = tuple[tuple[str, str], ...]
"""Package renames, e.g. ``(("turtlesim", "turtlesim_msgs"),)``: turtlesim's
types as a distro from Kilted on names them."""


@functools.cache
def _full(cls: type, type_name: str, names: Names) -> dict[str, Any]:
    found: dict[str, dict[str, Any]] = {}
    own = dict(_collect(cls, found), type_name=type_name)
    del found[cls._TYPE_NAME]
    full = {"type_description": own, "referenced_type_descriptions": list(found.values())}
    if names:
        full = _renamed(full, dict(names))
    full["referenced_type_descriptions"].sort(key=lambda t: t["type_name"])
    return full


def _renamed(full: dict[str, Any], names: dict[str, str]) -> dict[str, Any]:
    def individual(t: dict[str, Any]) -> dict[str, Any]:
        fields = [dict(f, type=dict(f["type"], nested_type_name=renamed_type_name(f["type"]["nested_type_name"], names)))
                  for f in t["fields"]]
        return {"type_name": renamed_type_name(t["type_name"], names), "fields": fields}

    return {"type_description": individual(full["type_description"]),
            "referenced_type_descriptions": [individual(t) for t in full["referenced_type_descriptions"]]}


def type_description(cls: type, type_name: str | None = None, names: Names = ()) -> dict[str, Any]:
    """The full description of a message, service or action class (a fresh
    copy): ``{"type_description": ..., "referenced_type_descriptions": [...]}``.
    ``type_name`` describes the type under another name (a recording's),
    ``names`` renames packages (see Names)."""
    return json.loads(json.dumps(_full(cls, type_name or cls._TYPE_NAME, names)))


@functools.cache
def type_hash(cls: type, type_name: str | None = None, names: Names = ()) -> str:
    """The ``RIHS01_<sha256>`` hash of a message, service or action class."""
    full = _full(cls, type_name or cls._TYPE_NAME, names)
    hashable = {
        "type_description": _without_defaults(full["type_description"]),
        "referenced_type_descriptions": [_without_defaults(t) for t in full["referenced_type_descriptions"]],
    }
    text = json.dumps(hashable, ensure_ascii=True, separators=(", ", ": "))
    return "RIHS01_" + hashlib.sha256(text.encode()).hexdigest()


def _without_defaults(individual: dict[str, Any]) -> dict[str, Any]:
    return {
        "type_name": individual["type_name"],
        "fields": [{"name": f["name"], "type": f["type"]} for f in individual["fields"]],
    }


def type_sources(cls: type, names: Names = ()) -> list[dict[str, str]]:
    """What rosidl keeps of the files ``cls`` and the types it uses come from,
    in the order of its description: each type's name, its encoding (``msg``,
    ``srv``, ``action``; ``implicit`` for the parts of a service or action,
    which have no file of their own) and the file's text."""
    full = _full(cls, cls._TYPE_NAME, ())
    top, *used = [full["type_description"]["type_name"]] + [t["type_name"] for t in full["referenced_type_descriptions"]]
    renames = dict(names)
    sources = [_source(name, renamed_type_name(name, renames)) for name in used]
    return [_source(top, renamed_type_name(top, renames)), *sorted(sources, key=lambda source: source["type_name"])]


def renamed_type_name(type_name: str, names: Mapping[str, str]) -> str:
    """``type_name`` with its package renamed by ``names`` (old -> new, see
    Names): ``turtlesim/msg/Pose`` -> ``turtlesim_msgs/msg/Pose``."""
    package, slash, rest = type_name.partition("/")
    return names.get(package, package) + slash + rest


def _source(type_name: str, shown: str) -> dict[str, str]:
    cls = _REGISTRY.get(type_name)
    kind = type_name.split("/")[1]
    if cls is None or not (issubclass(cls, (Service, Action)) or kind == "msg"):
        return {"type_name": shown, "encoding": "implicit", "raw_file_contents": ""}
    # rosidl_generator_c keeps the file's lines, without the last line's end
    return {"type_name": shown, "encoding": kind, "raw_file_contents": "\n".join(cls._DEFINITION.splitlines())}
