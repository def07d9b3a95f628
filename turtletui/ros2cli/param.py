"""``ros2 param``: list, get, set, dump.

``param set`` goes through the node's ``parameter_setter`` (turtlesim and the
controllers turtletui runs have one), so the node's own rules apply.
"""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from typing import TYPE_CHECKING, Any

from turtletui.graph.introspection import snapshot
from turtletui.ros2cli.arguments import Command, Verb
from turtletui.ros2cli.common import (
    CommandResult,
    PlainError,
    hint,
    node_or_error,
    one_line,
    visible_nodes,
)
from turtletui.ros2cli.values import YamlError, parse_yaml, yaml_lines

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

_NODE_HELP = "Name of the ROS node"


def _list_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("node_name", nargs="?", help=_NODE_HELP)
    parser.add_argument("--param-type", action="store_true",
                        help="Print parameter types with parameter names")


def _list(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    snap = snapshot(cli.graph)
    nodes = [node_or_error(snap, args.node_name)] if args.node_name is not None else visible_nodes(snap)
    lines = []
    for node in nodes:
        if args.node_name is None and node.parameters:
            lines.append(f"{node.name}:")
        for name, value in sorted(node.parameters):
            lines.append(f"  {name} (type: {_type_word(value)})" if args.param_type else f"  {name}")
    return CommandResult(lines)


def _get_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("node_name", help=_NODE_HELP)
    parser.add_argument("parameter_name", help="Name of the parameter")
    parser.add_argument("--hide-type", action="store_true", help="Hide the type information")


def _get(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    node = node_or_error(snapshot(cli.graph), args.node_name)
    params = dict(node.parameters)
    if args.parameter_name not in params:
        raise PlainError(f"Parameter not set.{hint(args.parameter_name, sorted(params))}")
    value = params[args.parameter_name]
    return CommandResult([str(value) if args.hide_type else _type_line(value)])


def _set_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("node_name", help=_NODE_HELP)
    parser.add_argument("parameter_name", help="Name of the parameter")
    parser.add_argument("value", help="Value of the parameter")


def _set(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    node = node_or_error(snapshot(cli.graph), args.node_name)
    value = _parameter_value(args.value)
    name = args.parameter_name
    params = dict(node.parameters)
    record = next((n for n in cli.graph.nodes if n.fqn == node.name), None)
    setter = None if record is None else record.parameter_setter
    if name not in params:
        reason = f"parameter '{name}' is not declared by {node.name}{hint(name, sorted(params))}"
    elif setter is None:
        reason = f"turtletui can not set parameters of {node.name} from here"
    else:
        reason = setter(name, value)
    if reason:
        raise PlainError(f"Setting parameter failed: {one_line(reason)}")
    return CommandResult(["Set parameter successful"])


def _parameter_value(text: str) -> Any:
    """ros2param's get_parameter_value: YAML if it reads as a parameter type, else the text."""
    try:
        value = parse_yaml(text)
    except YamlError:
        return text
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, list) and value and all(type(v) is type(value[0]) for v in value) \
            and isinstance(value[0], (bool, int, float, str)):
        return value
    return text


def _dump_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("node_name", help=_NODE_HELP)


def _dump(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    node = node_or_error(snapshot(cli.graph), args.node_name)
    params: dict[str, Any] = {}
    for name, value in sorted(node.parameters):
        # as ros2param's insert_dict: "qos_overrides./parameter_events.publisher.depth" nests
        *parents, leaf = name.split(".")
        level = params
        for part in parents:
            level = level.setdefault(part, {})
        level[leaf] = list(value) if isinstance(value, tuple) else value
    return CommandResult(yaml_lines({node.name: {"ros__parameters": params}}))


def _type_word(value: Any) -> str:
    """The type as ``ros2 param list --param-type`` names it."""
    words = {bool: "boolean", int: "integer", float: "double", str: "string"}
    if isinstance(value, (list, tuple)):
        return f"{words.get(type(value[0]), 'string') if value else 'string'} array"
    if isinstance(value, (bytes, bytearray)):
        return "byte array"
    return words.get(type(value), "not set")


def _type_line(value: Any) -> str:
    """``ros2 param get``'s sentence for a value."""
    if value is None:
        return "Parameter not set."
    words = {bool: "Boolean", int: "Integer", float: "Double", str: "String"}
    if type(value) in words:
        return f"{words[type(value)]} value is: {value}"
    if isinstance(value, (bytes, bytearray)):
        return f"Byte values are: {list(value)}"
    if isinstance(value, (list, tuple)):
        items = list(value)
        kind = type(items[0]) if items else str
        return f"{words.get(kind, 'String')} values are: {items}"
    return f"String value is: {value}"


COMMAND = Command("param", "Various param related sub-commands", verbs=(
    Verb("dump", "Show all of the parameters of a node in a YAML file format", _dump_arguments, _dump),
    Verb("get", "Get parameter", _get_arguments, _get),
    Verb("list", "Output a list of available parameters", _list_arguments, _list),
    Verb("set", "Set parameter", _set_arguments, _set),
))
