"""Message definitions as recordings carry them (MCAP schema encoding ``ros2msg``).

The text is what rosbag2 stores (rosbag2_cpp's LocalMessageDefinitionSource):
the type's own .msg text, then each type it uses, in sorted order and once
each, after a line of 80 ``=`` and a ``MSG: pkg/Type`` line, depth first.
The .msg texts are turtletui's own (``turtletui.interfaces``), the same bytes
as the ROS packages' files.

A service's request and response are recorded as messages of the same
package under ``msg/`` (``turtlesim/msg/SetPen_Request``): ROS keeps them
under ``srv/``, where neither mcap_ros2 nor rosbags decodes a recording
(rosbags files ``srv/`` names under ``msg/``, and mcap_ros2 refuses the
``_Event`` types of ROS 2's service introspection).
"""

from __future__ import annotations

import functools
import re

from turtletui.interfaces import InterfaceError, get_interface

SEPARATOR = "=" * 80

_FIELD_TYPE = re.compile(r"(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+")
_PRIMITIVES = frozenset((
    "bool", "byte", "char", "float32", "float64", "int8", "uint8",
    "int16", "uint16", "int32", "uint32", "int64", "uint64", "string", "wstring",
))


def _dependencies(text: str, package: str) -> list[str]:
    """The message types a definition uses, as rosbag2 finds them (sorted)."""
    found = set()
    for match in _FIELD_TYPE.finditer(text):
        name = match.group(1)
        if name in _PRIMITIVES:
            continue
        found.add(name if "/" in name else f"{package}/{name}")
    return sorted(found)


def _full_text(root_text: str, package: str) -> str:
    seen: set[str] = set()

    def append(text: str, package: str) -> str:
        result = text
        for dep in _dependencies(text, package):
            if dep in seen:
                continue
            seen.add(dep)
            cls = get_interface(dep)
            result += f"\n{SEPARATOR}\nMSG: {dep}\n" + append(cls._DEFINITION, dep.split("/", 1)[0])
        return result

    return append(root_text, package)


def recorded_type_name(type_name: str) -> str:
    """The type a recording gives a message: ``turtlesim/srv/Spawn_Request``
    -> ``turtlesim/msg/Spawn_Request``; anything else as it is."""
    package, kind, name = type_name.split("/")
    return f"{package}/msg/{name}" if kind == "srv" else type_name


def interface_of(recorded: str) -> type:
    """The class of a recorded type name (``recorded_type_name`` undone);
    InterfaceError if turtletui does not know it."""
    package, kind, name = recorded.split("/") if recorded.count("/") == 2 else ("", "", "")
    if kind == "msg" and name.endswith(("_Request", "_Response")):
        try:
            return get_interface(f"{package}/srv/{name}")
        except InterfaceError:
            pass
    return get_interface(recorded)


@functools.cache
def message_definition(type_name: str) -> str:
    """The ros2msg schema text of a recorded message type (``turtlesim/msg/Pose``)."""
    package = type_name.split("/", 1)[0]
    return _full_text(interface_of(type_name)._DEFINITION, package)
