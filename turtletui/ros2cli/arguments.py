"""The ``ros2`` command line parsed with argparse, as ros2cli parses it: one
sub-parser per command (``topic``), one per verb (``echo``), the same
positionals, options, help and error texts.

argparse prints and exits; here the parser raises instead, so a console can
show the text: :class:`ParseError` for a bad command line (one line,
``ros2 topic echo: error: the following arguments are required: topic_name``),
:class:`HelpShown` for ``-h`` (the help's lines).
"""

from __future__ import annotations

import argparse
from argparse import ArgumentParser, Namespace
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, NoReturn

from turtletui.ros2cli.common import CommandResult, hint

if TYPE_CHECKING:
    from turtletui.ros2cli.cli import Ros2Cli

NOT_HERE = ("component", "daemon", "doctor", "launch", "lifecycle", "multicast",
            "pkg", "run", "security", "wtf")
"""Commands of the real ros2 that turtletui does not model."""

INSTEAD = {
    "run": "turtlesim runs already, turtle_teleop_key is the arena's arrow keys (Esc first),"
           " and your own node runs with turtletui run FILE",
    "launch": "turtlesim runs already; several nodes run with turtletui run A.py B.py",
}
"""What the tutorials' ``ros2 run``/``launch`` lines are in turtletui."""


@dataclass(frozen=True)
class Verb:
    """One ``ros2 <command> <verb>``: its arguments and what runs it."""

    name: str
    doc: str
    """The first line of its help, as ``ros2 <command> -h`` lists it."""
    add_arguments: Callable[[ArgumentParser], None]
    main: Callable[[Ros2Cli, Namespace, str], CommandResult]
    """Runs the verb: (the cli, the parsed arguments, the command line)."""


@dataclass(frozen=True)
class Command:
    """One ``ros2 <command>`` and its verbs."""

    name: str
    doc: str
    verbs: tuple[Verb, ...]
    add_arguments: Callable[[ArgumentParser], None] | None = None


class ParseError(Exception):
    """A command line argparse refused; ``str()`` is the one line to show."""


class HelpShown(Exception):
    """``-h`` (or a command without its verb): ``lines`` is the help text."""

    def __init__(self, text: str) -> None:
        super().__init__("help")
        self.lines = text.rstrip("\n").split("\n")


class Ros2ArgumentParser(ArgumentParser):
    """An ArgumentParser that raises instead of printing and exiting."""

    def error(self, message: str) -> NoReturn:
        raise ParseError(f"{self.prog}: error: {' '.join(message.split())}")

    def exit(self, status: int = 0, message: str | None = None) -> NoReturn:
        if status:
            raise ParseError(f"{self.prog}: error: {message or f'exit status {status}'}".rstrip())
        raise HelpShown(message or "")

    def print_help(self, file: Any = None) -> NoReturn:
        raise HelpShown(self.format_help())

    def print_usage(self, file: Any = None) -> NoReturn:
        raise HelpShown(self.format_usage())

    def _check_value(self, action: argparse.Action, value: Any) -> None:
        # argparse says "argument Call `ros2 <command> -h` for more detailed
        # usage.: invalid choice: 'topik' (choose from 'action', 'bag', ...)";
        # name the close match instead, and the commands turtletui leaves out.
        if action.choices is None or value in action.choices:
            return
        choices = sorted(action.choices)
        if self.prog == "ros2" and value in INSTEAD:
            message = f"'{value}' is not available in turtletui: {INSTEAD[value]}"
        elif self.prog == "ros2" and value in NOT_HERE:
            message = f"'{value}' is not available in turtletui (available: {', '.join(choices)})"
        else:
            message = f"invalid choice: '{value}'" + (
                hint(value, choices, quote=True) or f" (choose from {', '.join(choices)})")
        raise argparse.ArgumentError(None, message)


def build_parser(commands: Sequence[Command], help_width: Callable[[], int]) -> Ros2ArgumentParser:
    """The ``ros2`` parser with every command and verb; ``help_width()`` gives
    the columns help is formatted for (read each time help is shown)."""

    def formatter(prog: str) -> argparse.HelpFormatter:
        return argparse.RawDescriptionHelpFormatter(prog, width=max(help_width(), 30))

    parser = Ros2ArgumentParser(
        prog="ros2", description="ros2 is an extensible command-line tool for ROS 2.",
        formatter_class=formatter)
    command_parsers = _subparsers(parser, "ros2", "_command", {c.name: c.doc for c in commands})
    for command in commands:
        command_parser = command_parsers.add_parser(command.name, description=command.doc,
                                                    formatter_class=formatter)
        command_parser.set_defaults(_command=command, _command_parser=command_parser)
        if command.add_arguments is not None:
            command.add_arguments(command_parser)
        verb_parsers = _subparsers(command_parser, f"ros2 {command.name}", "_verb",
                                   {v.name: v.doc for v in command.verbs})
        for verb in command.verbs:
            verb_parser = verb_parsers.add_parser(verb.name, description=verb.doc,
                                                  formatter_class=formatter)
            verb_parser.set_defaults(_verb=verb)
            verb.add_arguments(verb_parser)
    return parser


def _subparsers(parser: ArgumentParser, cli_name: str, dest: str, docs: dict[str, str]):
    """ros2cli's add_subparsers: a 'Commands' section listing each with its doc."""
    width = max(map(len, docs))
    description = "".join(f"{name.ljust(width)}  {docs[name]}\n" for name in sorted(docs))
    subparsers = parser.add_subparsers(
        title="Commands", description=description,
        metavar=f"Call `{cli_name} <command> -h` for more detailed usage.")
    subparsers.dest = " " + dest.lstrip("_")  # as ros2cli: readable in usage, no clash
    subparsers.required = False
    return subparsers


def list_options(parser: ArgumentParser, kind: str, count_option: str, hidden_option: str | None = None,
                 show_types: bool = True) -> None:
    """The options ros2's list verbs share: ``-t``, ``-c`` and the hidden ones."""
    if show_types:
        parser.add_argument("-t", "--show-types", action="store_true",
                            help=f"Additionally show the {kind} type")
    parser.add_argument("-c", count_option, action="store_true",
                        help=f"Only display the number of {kind}s discovered")
    if hidden_option is not None:
        parser.add_argument(hidden_option, action="store_true", help=f"Consider hidden {kind}s as well")


def command_and_verb(args: Namespace) -> tuple[Command | None, Verb | None]:
    """The command and verb argparse chose (None where the line has none)."""
    return getattr(args, "_command", None), getattr(args, "_verb", None)


def rejoin_flow_yaml(tokens: list[str]) -> list[str]:
    """Join a YAML mapping or sequence the shell split apart (``{linear: {x: 2.0}}``
    typed without quotes) back into one argument; students forget the quotes."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        token = tokens[i]
        i += 1
        if token[:1] in ("{", "[") and _depth(token) > 0:
            parts = [token]
            depth = _depth(token)
            while depth > 0 and i < len(tokens):
                parts.append(tokens[i])
                depth += _depth(tokens[i])
                i += 1
            token = " ".join(parts)
        out.append(token)
    return out


def _depth(text: str) -> int:
    return text.count("{") + text.count("[") - text.count("}") - text.count("]")


def positive_float(text: str) -> float:
    """ros2topic's positive_float (the rate of ``topic pub``)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError("Expects a floating point number") from None
    if not value > 0:  # NaN too
        raise argparse.ArgumentTypeError("Value must be positive")
    return value


def positive_int(text: str) -> int:
    """ros2topic's positive_int (``topic hz --window``)."""
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value <= 0:
        raise argparse.ArgumentTypeError("value must be a positive integer")
    return value


def nonnegative_int(text: str) -> int:
    """ros2topic's nonnegative_int (``topic pub --times``)."""
    value = int(text)
    if value < 0:
        raise ValueError(text)  # argparse: "invalid nonnegative_int value: '-1'"
    return value
