"""ROS 2 command-line arguments: ``--ros-args -p name:=value -r from:=to ...``."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from turtletui.errors import TurtletuiError

_INT = re.compile(r"[-+]?(0|[1-9][0-9]*)\Z")
_FLOAT = re.compile(r"[-+]?(\d+\.\d*|\.\d+|\d+)([eE][-+]?\d+)?\Z")
_NAME = re.compile(r"[A-Za-z_~/][A-Za-z0-9_./~]*\Z")


class RosArgsError(TurtletuiError, ValueError):
    """A malformed ``--ros-args`` section; the message names the argument."""


@dataclass
class RosArgs:
    """What a ``--ros-args`` section asks for. Node-scoped entries (``node:...``)
    are kept with their node name; ``None`` means every node."""

    params: list[tuple[str | None, str, Any]] = field(default_factory=list)
    remaps: list[tuple[str | None, str, str]] = field(default_factory=list)
    log_level: str | None = None
    user_args: list[str] = field(default_factory=list)

    def params_for(self, node_name: str) -> dict[str, Any]:
        return {name: value for node, name, value in self.params if node in (None, node_name)}

    def remaps_for(self, node_name: str) -> dict[str, str]:
        return {src: dst for node, src, dst in self.remaps if node in (None, node_name)}


def parse_value(text: str) -> Any:
    """A parameter value as ROS reads it: YAML scalars and flat lists."""
    value = text.strip()
    lowered = value.lower()
    if lowered in ("true", "yes", "on"):
        return True
    if lowered in ("false", "no", "off"):
        return False
    if _INT.match(value):
        return int(value)
    if _FLOAT.match(value):
        return float(value)
    if lowered in (".inf", "+.inf"):
        return float("inf")
    if lowered == "-.inf":
        return float("-inf")
    if lowered == ".nan":
        return float("nan")
    if value.startswith("[") and value.endswith("]"):
        inner = value[1:-1].strip()
        items = [parse_value(part) for part in inner.split(",")] if inner else []
        kinds = {type(item) for item in items}
        if kinds == {int, float}:
            items = [float(item) for item in items]
        elif len(kinds) > 1:
            raise RosArgsError(f"parameter list {text!r} mixes types: ROS needs one type per list")
        return items
    if len(value) >= 2 and value[0] == value[-1] and value[0] in "'\"":
        return value[1:-1]
    return value


def _split_assignment(flag: str, text: str) -> tuple[str | None, str, str]:
    if ":=" not in text:
        raise RosArgsError(f"malformed --ros-args: '{flag} {text}' must look like NAME:=VALUE")
    left, right = text.split(":=", 1)
    node = None
    if ":" in left:
        node, left = left.split(":", 1)
    if not left or not _NAME.match(left):
        raise RosArgsError(f"malformed --ros-args: '{flag} {text}': {left!r} is not a valid name")
    return node, left, right


def parse_ros_args(argv: list[str]) -> RosArgs:
    """Split ``argv`` into user arguments and ROS arguments, as rcl does."""
    result = RosArgs()
    i = 0
    in_ros = False
    while i < len(argv):
        arg = argv[i]
        if arg == "--ros-args":
            in_ros = True
        elif in_ros and arg == "--":
            in_ros = False
        elif not in_ros:
            result.user_args.append(arg)
        elif arg in ("-p", "--param", "-r", "--remap", "--log-level", "-e", "--enclave", "--params-file"):
            if i + 1 >= len(argv):
                raise RosArgsError(f"malformed --ros-args: {arg} needs a value after it")
            text = argv[i + 1]
            i += 1
            if arg in ("-p", "--param"):
                node, name, raw = _split_assignment(arg, text)
                result.params.append((node, name, parse_value(raw)))
            elif arg in ("-r", "--remap"):
                node, src, dst = _split_assignment(arg, text)
                result.remaps.append((node, src, dst))
            elif arg == "--log-level":
                result.log_level = text.split(":=")[-1]
            elif arg == "--params-file":
                raise RosArgsError(
                    f"--params-file {text}: parameter files are not supported yet; pass each with -p NAME:=VALUE"
                )
        else:
            raise RosArgsError(f"Found unknown ROS arguments: ['{arg}']")
        i += 1
    return result
