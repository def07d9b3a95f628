"""``ros2 interface``: show, list, packages, package."""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from typing import TYPE_CHECKING

from turtletui.compat.distro import distro_interface, distro_interfaces
from turtletui.interfaces import definition_text
from turtletui.ros2cli.arguments import Command, Verb
from turtletui.ros2cli.common import CommandError, CommandResult, hint

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

_KINDS = (("msg", "only_msgs", "Messages"), ("srv", "only_srvs", "Services"),
          ("action", "only_actions", "Actions"))


def _kind_options(parser: ArgumentParser, help_text: str = "Print out only the {} types") -> None:
    for short, long, kind in (("-m", "--only-msgs", "message"), ("-s", "--only-srvs", "service"),
                              ("-a", "--only-actions", "action")):
        parser.add_argument(short, long, action="store_true", help=help_text.format(kind))


def _kinds(args: Namespace) -> set[str]:
    """The kinds the -m/-s/-a options ask for (all when none is given)."""
    chosen = {kind for kind, option, _ in _KINDS if getattr(args, option)}
    return chosen or {kind for kind, _, _ in _KINDS}


def _show_arguments(parser: ArgumentParser) -> None:
    comments = parser.add_mutually_exclusive_group()
    comments.add_argument("--all-comments", action="store_true",
                          help="Show all comments, including for nested interface definitions")
    comments.add_argument("--no-comments", action="store_true",
                          help="Show no comments or whitespace")
    parser.add_argument("type", help="Show an interface definition (e.g. 'example_interfaces/msg/String')")


def _show(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    text = definition_text(distro_interface(args.type, cli.distro), all_comments=args.all_comments, no_comments=args.no_comments)
    return CommandResult(text.split("\n"))


def _list(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    kinds = _kinds(args)
    lines = []
    for kind, _, title in _KINDS:
        if kind in kinds:
            lines.append(f"{title}:")
            lines.extend(f"    {n}" for n in distro_interfaces(cli.distro) if n.split("/")[1] == kind)
    return CommandResult(lines)


def _packages(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    kinds = _kinds(args)
    return CommandResult(sorted({n.split("/")[0] for n in distro_interfaces(cli.distro) if n.split("/")[1] in kinds}))


def _package_arguments(parser: ArgumentParser) -> None:
    _kind_options(parser)
    parser.add_argument("package_name", help="Name of the ROS package (e.g. 'example_interfaces')")


def _package(cli: Ros2Cli, args: Namespace, line: str) -> CommandResult:
    names = [n for n in distro_interfaces(cli.distro) if n.split("/")[0] == args.package_name]
    if not names:
        packages = sorted({n.split("/")[0] for n in distro_interfaces(cli.distro)})
        raise CommandError(f"unknown package '{args.package_name}'{hint(args.package_name, packages)}")
    kinds = _kinds(args)
    return CommandResult([n for n in names if n.split("/")[1] in kinds])


COMMAND = Command("interface", "Show information about ROS interfaces", verbs=(
    Verb("list", "List all interface types available", _kind_options, _list),
    Verb("package", "Output a list of available interface types within one package",
         _package_arguments, _package),
    Verb("packages", "Output a list of packages that provide interfaces",
         lambda parser: _kind_options(parser, "Only list packages that generate {}s"), _packages),
    Verb("show", "Output the interface definition", _show_arguments, _show),
))
