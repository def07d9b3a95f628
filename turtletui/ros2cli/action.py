"""``ros2 action``: list, info, send_goal."""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from typing import TYPE_CHECKING, Any

from turtletui.graph.introspection import snapshot
from turtletui.interfaces import Action
from turtletui.ros2cli.arguments import Command, Verb, list_options
from turtletui.ros2cli.common import (
    CommandResult,
    check_type,
    entity_or_error,
    interface_or_error,
    name_list,
)
from turtletui.ros2cli.streams import GoalStream
from turtletui.ros2cli.values import message_values

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli


def _server(cli: Ros2Cli, name: str, what: str = "is not available") -> Any:
    return entity_or_error(cli.graph.action_servers, name, "action", what)


def _list_arguments(parser: ArgumentParser) -> None:
    list_options(parser, "action", "--count-actions")


def _list(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    return name_list(snapshot(cli.graph).actions, count=args.count_actions, show_types=args.show_types)


def _info_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("action_name", help="Name of the ROS action to get info (e.g. '/fibonacci')")
    parser.add_argument("-t", "--show-types", action="store_true",
                        help="Additionally show the action type")
    parser.add_argument("-c", "--count", action="store_true",
                        help="Only display the number of action clients and action servers")


def _info(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    server = _server(cli, args.action_name, "does not exist")
    suffix = f" [{server.type_name}]" if args.show_types else ""
    clients = sorted(c.node.fqn for c in cli.graph.action_clients if c.name == server.name)
    if args.count:
        return CommandResult([f"Action: {server.name}", f"Action clients: {len(clients)}",
                              "Action servers: 1"])
    return CommandResult([
        f"Action: {server.name}",
        f"Action clients: {len(clients)}",
        *(f"    {client}{suffix}" for client in clients),
        "Action servers: 1",
        f"    {server.node.fqn}{suffix}",
    ])


def _send_goal_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("action_name", help="Name of the ROS action (e.g. '/fibonacci')")
    parser.add_argument("action_type",
                        help="Type of the ROS action (e.g. 'example_interfaces/action/Fibonacci')")
    parser.add_argument("goal", nargs="?", default="{}",
                        help="Goal request values in YAML format (e.g. '{order: 10}')")
    parser.add_argument("-f", "--feedback", action="store_true",
                        help="Echo feedback messages for the goal")


def _send_goal(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    server = _server(cli, args.action_name)
    cls = interface_or_error(cli, args.action_type, Action, "action")
    check_type(cli, cls, server.type_name, f"action '{server.name}'")
    goal = message_values(args.goal, cls.Goal, "goal")
    return cli.start(GoalStream(cli, line, server.name, cls, goal, args.feedback))


COMMAND = Command("action", "Various action related sub-commands", verbs=(
    Verb("info", "Print information about an action", _info_arguments, _info),
    Verb("list", "Output a list of action names", _list_arguments, _list),
    Verb("send_goal", "Send an action goal", _send_goal_arguments, _send_goal),
))
