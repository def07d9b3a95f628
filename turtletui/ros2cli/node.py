"""``ros2 node``: list, info."""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from typing import TYPE_CHECKING

from turtletui.graph.introspection import snapshot
from turtletui.ros2cli.arguments import Command, Verb
from turtletui.ros2cli.common import CommandResult, is_hidden, node_or_error, ros_view

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli


def _list_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("-a", "--all", action="store_true", help="Display all nodes even hidden ones")
    parser.add_argument("-c", "--count-nodes", action="store_true",
                        help="Only display the number of nodes discovered")


def _list(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    names = [n.name for n in snapshot(cli.graph).nodes
             if args.all or not n.name.rsplit("/", 1)[-1].startswith("_")]
    return CommandResult([str(len(names))] if args.count_nodes else names)


def _info_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("node_name", help="Fully qualified node name to request information")
    parser.add_argument("--include-hidden", action="store_true",
                        help="Display hidden topics, services, and actions as well")


def _info(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    node = node_or_error(ros_view(cli), args.node_name)
    lines = [node.name]
    for title, entries in (
        ("Subscribers", node.subscribers),
        ("Publishers", node.publishers),
        ("Service Servers", node.service_servers),
        ("Service Clients", node.service_clients),
        ("Action Servers", node.action_servers),
        ("Action Clients", node.action_clients),
    ):
        shown = [(n, kind) for n, kind in entries if args.include_hidden or not is_hidden(n)]
        lines.append(f"  {title}:")
        # ros2node prints the entries with print(*entries, sep='\n'): an
        # empty section leaves one blank line.
        lines.extend([f"    {name}: {kind}" for name, kind in shown] or [""])
    return CommandResult(lines)


COMMAND = Command("node", "Various node related sub-commands", verbs=(
    Verb("info", "Output information about a node", _info_arguments, _info),
    Verb("list", "Output a list of available nodes", _list_arguments, _list),
))
