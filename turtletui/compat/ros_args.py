"""ROS 2 command-line arguments: ``--ros-args -p name:=value -r from:=to ...``."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from turtletui.errors import TurtletuiError
from turtletui.graph.logs import parse_level

_INT = re.compile(r"[-+]?(0|[1-9][0-9]*)\Z")
_FLOAT = re.compile(r"[-+]?(\d+\.\d*|\.\d+|\d+)([eE][-+]?\d+)?\Z")
_NAME = re.compile(r"[A-Za-z_~/][A-Za-z0-9_./~]*\Z")


class RosArgsError(TurtletuiError, ValueError):
    """A malformed ``--ros-args`` section; the message names the argument."""

    def __init__(self, message: str, rcl: str | None = None) -> None:
        super().__init__(message)
        self.rcl = rcl
        """rcl's own sentence for the mistake (what rclpy.init reports), where it is known."""


class UnknownRosArgs(RosArgsError):
    """Flags after ``--ros-args`` that ROS does not know (rcl lists them all)."""

    def __init__(self, unknown: list[str]) -> None:
        super().__init__(f"Found unknown ROS arguments: {unknown}")
        self.unknown = unknown


_TRAILING = {
    "-r": "Couldn't parse trailing {flag} flag. No remap rule found.",
    "-p": "Couldn't parse trailing {flag} flag. No parameter override rule found.",
    "--params-file": "Couldn't parse trailing {flag} flag. No file path provided.",
    "--log-level": "Couldn't parse trailing log level flag: '{flag}'. No log level provided.",
    "-e": "Couldn't parse trailing {flag} flag. No enclave path provided.",
}
"""rcl's errors (arguments.c) for a flag with nothing after it, by its short form."""
_SHORT = {"--remap": "-r", "--param": "-p", "--enclave": "-e"}


@dataclass
class RosArgs:
    """What a ``--ros-args`` section asks for. Node-scoped entries (``node:...``)
    are kept with their node name; ``None`` means every node."""

    params: list[tuple[str | None, str, Any]] = field(default_factory=list)
    remaps: list[tuple[str | None, str, str]] = field(default_factory=list)
    log_level: str | None = None
    """``--log-level LEVEL``: every logger's default level."""
    log_levels: dict[str, str] = field(default_factory=dict)
    """``--log-level NAME:=LEVEL``: one logger's level (and its children's)."""
    user_args: list[str] = field(default_factory=list)
    file_params: list[tuple[str, str, Any]] = field(default_factory=list)
    """(node name pattern, name, value) from ``--params-file`` files, in order."""

    def params_for(self, fqn: str) -> dict[str, Any]:
        """The parameters for the node ``fqn`` (its fully qualified name, after any
        ``-r __node``/``__ns``), as rclpy applies them: first those for every node
        (``--params-file`` sections with ``*`` or ``**``, then ``-p NAME:=V``), then those
        naming this node (a file's ``/ns/node:`` section, then ``-p node:NAME:=V``), which win."""
        return {name: value for _, name, value in self.param_rules(fqn)}

    def param_rules(self, fqn: str) -> list[tuple[str, str, Any]]:
        """(where it came from, name, value) for the node ``fqn``, in the order they apply
        (a later one wins); where is ``--params-file`` or ``-p``. ``-p NODE:...`` names the
        node as rcl does: ``driver`` is ``/driver``, so not ``/robot/driver``."""
        files = [(pattern, name, value) for pattern, name, value in self.file_params if node_matches(pattern, fqn)]
        return [
            *(("--params-file", name, value) for pattern, name, value in files if "*" in pattern),
            *(("-p", name, value) for node, name, value in self.params if node is None),
            *(("--params-file", name, value) for pattern, name, value in files if "*" not in pattern),
            *(("-p", name, value) for node, name, value in self.params if node is not None and node_matches(node, fqn)),
        ]

    def remaps_for(self, node_name: str) -> dict[str, str]:
        """The remap rules for the node named ``node_name`` (``node:from:=to`` names it by
        name, as rcl matches them), the first rule for a name winning, as in rcl."""
        rules: dict[str, str] = {}
        for node, src, dst in self.remaps:
            if node in (None, node_name):
                rules.setdefault(src, dst)
        return rules


def parse_value(text: str) -> Any:
    """A parameter value as ROS reads it: YAML scalars and flat lists (``[]``: not set, None)."""
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
        return _one_type(items, f"parameter list {text!r}")
    if len(value) >= 2 and value[0] == value[-1] and value[0] in "'\"":
        return value[1:-1]
    return value


_YAML_TYPE = {bool: ("bool", 309), int: ("integer", 350), float: ("double", 391), str: ("string", 435)}
"""rcl_yaml_param_parser's name of each type, and the line of parse.c that refuses it in a list of another."""


def _one_type(items: list, what: str, lines: list[int] | None = None) -> list | None:
    """A list parameter as ROS holds it: one type (RosArgsError for a mixture, with
    rcl's sentence naming the first item of another type and its line, from ``lines``:
    each item's in the YAML file); an empty list is a parameter not set (None), as
    rcl reads ``[]``."""
    if not items:
        return None
    for i, item in enumerate(items):
        if type(item) is not type(items[0]):
            line = lines[i] if lines else 1
            name, at = _YAML_TYPE[type(item)]
            raise RosArgsError(
                f"{what} mixes types: ROS needs one type per list (write 1.0, not 1, among floats)",
                rcl=f"Sequence should be of same type. Value type '{name}' do not belong at line_num {line},"
                f" at /project/src/parse.c:{at}",
            )
    return items


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
    unknown: list[str] = []
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
                raise RosArgsError(
                    f"malformed --ros-args: {arg} needs a value after it",
                    rcl=_TRAILING[_SHORT.get(arg, arg)].format(flag=arg),
                )
            text = argv[i + 1]
            i += 1
            if arg in ("-p", "--param"):
                node, name, raw = _split_assignment(arg, text)
                try:
                    value = parse_value(raw)
                except RosArgsError as err:
                    raise RosArgsError(
                        str(err),
                        rcl=f"Couldn't parse parameter override rule: '{arg} {text}'. Error: {err.rcl},"
                        " at /project/src/rcl/arguments.c:352",
                    ) from None
                result.params.append((node, name, value))
            elif arg in ("-r", "--remap"):
                node, src, dst = _split_assignment(arg, text)
                result.remaps.append((node, src, dst))
            elif arg == "--log-level":
                logger, _, level = text.rpartition(":=")
                try:
                    parse_level(level)
                except ValueError as err:
                    raise RosArgsError(
                        f"--log-level {text}: {err}",
                        rcl=f"Couldn't parse log level: '{arg} {text}'. Error: Argument does not use a valid severity level",
                    ) from None
                if logger:
                    result.log_levels[logger] = level
                else:
                    result.log_level = level
            elif arg == "--params-file":
                try:
                    result.file_params.extend(read_params_file(text))
                except RosArgsError as err:
                    if err.rcl is None:
                        raise
                    raise RosArgsError(
                        str(err),
                        rcl=f"Couldn't parse params file: '{arg} {text}'. Error: {err.rcl},"
                        " at /project/src/rcl/arguments.c:415",
                    ) from None
        else:
            unknown.append(arg)
        i += 1
    if unknown:
        raise UnknownRosArgs(unknown)
    return result


def node_matches(pattern: str, fqn: str) -> bool:
    """Whether a parameter file's node key names the node ``fqn``: a full name
    (``/ns/node``; without its leading slash, from the root), ``*`` one name
    part, ``**`` any number of them (``/**`` every node)."""
    pattern = pattern if pattern.startswith("/") else f"/{pattern}"
    regex = "".join(
        "(/[^/]+)*" if part == "**" else "/[^/]+" if part == "*" else "/" + re.escape(part)
        for part in pattern.strip("/").split("/")
    )
    return re.fullmatch(regex or "/", fqn) is not None


def read_params_file(path: str) -> list[tuple[str, str, Any]]:
    """The (node pattern, name, value) entries of a ROS 2 parameter file:

    .. code-block:: yaml

        /turtlesim:             # or turtlesim, /**, /ns/*
          ros__parameters:
            background_r: 0
            pid: {kp: 1.5}      # the parameter pid.kp

    RosArgsError (one line naming the file) when it cannot be read or is not one."""
    import yaml

    where = f"--params-file {path}"
    try:
        with open(path, encoding="utf-8") as stream:
            text = stream.read()
        data = yaml.safe_load(text)
    except FileNotFoundError:
        raise RosArgsError(f"{where}: no such file", rcl="Error opening YAML file, at /project/src/parser.c:271") from None
    except (OSError, UnicodeDecodeError) as err:
        raise RosArgsError(f"{where}: cannot read it ({getattr(err, 'strerror', None) or err})") from None
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        at = f" at line {mark.line + 1}" if mark is not None else ""
        raise RosArgsError(f"{where}: not valid YAML{at} ({getattr(err, 'problem', None) or 'syntax error'})") from None
    if not isinstance(data, dict):
        raise RosArgsError(f"{where}: expected node names at the top, e.g. '/turtlesim:'")
    entries: list[tuple[str, str, Any]] = []
    lines = _item_lines(yaml.compose(text))
    for node, section in data.items():
        if not isinstance(section, dict) or "ros__parameters" not in section:
            raise RosArgsError(f"{where}: node {node!r} needs a 'ros__parameters:' mapping under it")
        params = section["ros__parameters"]
        if not isinstance(params, dict):
            raise RosArgsError(f"{where}: {node}: 'ros__parameters' must hold name: value pairs")
        for name, value in _flatten(params, ""):
            entries.append((str(node), name, _file_value(value, f"{where}: {node}: {name}", lines.get((node, name)))))
    return entries


def _flatten(params: dict, prefix: str) -> list[tuple[str, Any]]:
    flat = []
    for key, value in params.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            flat.extend(_flatten(value, f"{name}."))
        else:
            flat.append((name, value))
    return flat


def _item_lines(root: Any) -> dict[tuple[Any, str], list[int]]:
    """The line of each item of each list parameter of a parameter file's YAML
    (its composed nodes), by (node as YAML reads it, parameter name)."""
    import yaml

    found: dict[tuple[Any, str], list[int]] = {}

    def walk(node: Any, mapping: Any, prefix: str) -> None:
        for key, value in mapping.value:
            name = f"{prefix}{key.value}"
            if isinstance(value, yaml.MappingNode):
                walk(node, value, f"{name}.")
            elif isinstance(value, yaml.SequenceNode):
                found[(node, name)] = [item.start_mark.line + 1 for item in value.value]

    for key, section in root.value:
        node = yaml.safe_load(key.value) if key.tag != "tag:yaml.org,2002:str" else key.value
        for inner, params in section.value if isinstance(section, yaml.MappingNode) else ():
            if inner.value == "ros__parameters" and isinstance(params, yaml.MappingNode):
                walk(node, params, "")
    return found


def _file_value(value: Any, what: str, lines: list[int] | None = None) -> Any:
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, list):
        if not all(isinstance(v, (bool, int, float, str)) for v in value):
            raise RosArgsError(f"{what}: a list of parameters holds only numbers, booleans or strings")
        return _one_type(value, f"{what}: the list", lines)
    raise RosArgsError(f"{what}: {value!r} is not a value a ROS parameter can hold")
