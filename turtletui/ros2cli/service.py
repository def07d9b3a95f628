"""``ros2 service``: list, type, find, info, call."""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from typing import TYPE_CHECKING, Any

from turtletui.graph.introspection import ServiceInfo
from turtletui.interfaces import Service
from turtletui.ros2cli.arguments import Command, Verb, list_options
from turtletui.ros2cli.common import (
    CommandError,
    CommandResult,
    absolute,
    action_behind,
    action_type_shown,
    check_type,
    entity_or_error,
    hidden_error,
    hint,
    interface_or_error,
    is_hidden,
    name_list,
    ros_view,
    type_name,
)
from turtletui.ros2cli.streams import CallStream
from turtletui.ros2cli.values import message_values

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

_HIDDEN_HELP = "Consider hidden services as well"


def _service(cli: Ros2Cli, name: str, what: str = "is not available") -> Any:
    return entity_or_error(cli.graph.services, name, "service", what)


def _list_arguments(parser: ArgumentParser) -> None:
    list_options(parser, "service", "--count-services", "--include-hidden-services")


def _list(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    return name_list(ros_view(cli).services, count=args.count_services, show_types=args.show_types,
                     hidden=args.include_hidden_services)


def _name_arguments(help_text: str):
    def add(parser: ArgumentParser) -> None:
        parser.add_argument("service_name", help=help_text)
    return add


def _parameter_service(cli: Ros2Cli, name: str) -> Any:
    """A service rcl gives every node as ros2 shows it (e.g. get_type_description)
    that turtletui's graph does not have, or None. One that only clients wait
    for (ros2 lists those too) is not served at all."""
    name = absolute(name)
    if name in cli.graph.services:
        return None
    return next((s for s in ros_view(cli).services if s.name == name and s.server), None)


def _shown_service(cli: Ros2Cli, args: Namespace, verb: str) -> ServiceInfo:
    """The service as ``ros2 service list`` shows it (with a server or only
    clients, one rcl gives every node, an action's hidden one), if the
    command considers it."""
    name = absolute(args.service_name)
    shown = ros_view(cli).services
    found = next((s for s in shown if s.name == name), None)
    if found is None:
        raise CommandError(f"service '{name}' does not exist{hint(name, [s.name for s in shown if not is_hidden(s.name)])}")
    if is_hidden(name) and not args.include_hidden_services:
        raise hidden_error("service", verb, name)
    return found


def _type(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    return CommandResult([_shown_service(cli, args, "type").type])


def _find_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("service_type", help="Name of the ROS service type to filter for "
                                             "(e.g. 'rcl_interfaces/srv/ListParameters')")
    list_options(parser, "service", "--count-services", "--include-hidden-services", show_types=False)


def _find(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    wanted = type_name(cli, interface_or_error(cli, args.service_type, Service, "service"))
    found = [s for s in ros_view(cli).services if s.type == wanted]
    return name_list(found, count=args.count_services, show_types=False, hidden=args.include_hidden_services)


def _info(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    service = _shown_service(cli, args, "info")
    return CommandResult([f"Type: {service.type}", f"Clients count: {len(service.clients)}",
                          f"Services count: {1 if service.server else 0}"])


def _call_arguments(parser: ArgumentParser) -> None:
    parser.add_argument("service_name",
                        help="Name of the ROS service to call to (e.g. '/add_two_ints')")
    parser.add_argument("service_type", help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    parser.add_argument("values", nargs="?", default="{}",
                        help="Values to fill the service request with in YAML format "
                             "(e.g. '{a: 1, b: 2}'), otherwise the service request will be "
                             "published with default values")


def _call(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    action = action_behind(absolute(args.service_name))
    if action is not None and cli.graph.count_services(absolute(args.service_name)):
        raise CommandError(
            f"turtletui's actions are reached through "
            f"'ros2 action send_goal {action} {action_type_shown(cli.graph, action)} GOAL' "
            "(Ctrl+C cancels the goal), not through their hidden services"
        )
    if _parameter_service(cli, args.service_name) is not None:
        name = absolute(args.service_name)
        raise CommandError(f"turtletui does not serve {name} (its nodes serve their parameter services only)")
    service = _service(cli, args.service_name)
    srv_type, values = args.service_type, args.values
    if _looks_like_values(srv_type) and values == "{}":
        # The type left out: turtletui knows it from the graph.
        srv_type, values = None, srv_type
    cls = service.srv_type if srv_type is None else interface_or_error(cli, srv_type, Service, "service")
    check_type(cli, cls, service.type_name, f"service '{service.name}'")
    request = message_values(values, cls.Request, "request")
    return cli.start(CallStream(cli, line, service.name, cls, request))


def _looks_like_values(text: str) -> bool:
    return text.lstrip().startswith(("{", "[")) or ":" in text


COMMAND = Command("service", "Various service related sub-commands", verbs=(
    Verb("call", "Call a service", _call_arguments, _call),
    Verb("find", "Output a list of available services of a given type", _find_arguments, _find),
    Verb("info", "Print information about a service",
         _name_arguments("Name of the ROS service to get info (e.g. '/add_two_ints')"), _info),
    Verb("list", "Output a list of available services", _list_arguments, _list),
    Verb("type", "Output a service's type",
         _name_arguments("Name of the ROS service to get type (e.g. '/talker/list_parameters')"), _type),
), add_arguments=lambda parser: parser.add_argument(
    "--include-hidden-services", action="store_true", help=_HIDDEN_HELP))
