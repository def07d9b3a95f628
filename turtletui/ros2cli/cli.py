"""The interpreter: one command line in, what ``ros2`` prints out."""

from __future__ import annotations

import shlex
from argparse import ArgumentParser
from typing import TYPE_CHECKING, Protocol

from turtletui.compat.distro import NEWEST_LTS
from turtletui.graph.core import Graph, GraphError, NodeRecord
from turtletui.graph.simulated_node import SimulatedNode
from turtletui.interfaces import InterfaceError
from turtletui.ros2cli import action, bag, interface, node, param, service, topic
from turtletui.ros2cli.arguments import (
    HelpShown,
    ParseError,
    build_parser,
    command_and_verb,
    rejoin_flow_yaml,
)
from turtletui.ros2cli.common import CommandError, CommandResult, PlainError, error, one_line
from turtletui.ros2cli.streams import OWNER

if TYPE_CHECKING:
    from turtletui.ros2cli.streams import Stream

COMMANDS = (action.COMMAND, bag.COMMAND, interface.COMMAND, node.COMMAND, param.COMMAND, service.COMMAND,
            topic.COMMAND)

HIDDEN_NODE_PREFIX = "_ros2cli_"
"""The real CLI names its per-command node ``_ros2cli_<pid>``; '_' hides it."""

SHELL_OPERATORS = frozenset((">", ">>", "<", "|", "||", "&", "&&", ";", "2>", "2>&1"))


class _HasGraph(Protocol):
    graph: Graph


class Ros2Cli:
    """Interprets ``ros2`` command lines against a live graph (a Simulation or
    anything with a ``graph``). See the package docstring for the API."""

    def __init__(self, sim: _HasGraph | Graph, *, help_width: int = 80) -> None:
        self.graph: Graph = sim if isinstance(sim, Graph) else sim.graph
        self.sim = None if isinstance(sim, Graph) else sim
        """The simulation, for ``ros2 bag`` (None when only a graph was given)."""
        self.distro: str = getattr(self.sim, "distro", None) or NEWEST_LTS
        """The ROS 2 distro the graph's nodes run as: which types exist, and their names."""
        self.streams: list[Stream] = []
        """Streams still running, oldest first."""
        self.help_width = help_width
        """Columns ``-h`` help is formatted for (a console sets its own width)."""
        self._hidden = 0
        self._parser: ArgumentParser = build_parser(COMMANDS, lambda: self.help_width)

    def run(self, line: str) -> CommandResult:
        """Interpret one command line; never raises (errors are one line)."""
        try:
            tokens = shlex.split(line, comments=False)
        except ValueError as exc:
            return error(f"ros2: could not split the command line ({str(exc).lower()})")
        operators = [t for t in tokens if t in SHELL_OPERATORS]
        if operators:
            return error(f"ros2: shell operators such as '{operators[0]}' are not supported here"
                         " (quote YAML arguments: '{x: 1.0}')")
        if not tokens:
            return CommandResult([])
        if tokens[0] == "ros2":
            tokens = tokens[1:]
        tokens = rejoin_flow_yaml(tokens)
        try:
            args = self._parser.parse_args(tokens)
        except HelpShown as shown:
            return CommandResult(shown.lines)
        except ParseError as exc:
            return error(_with_quoting_hint(str(exc), line))
        command, verb = command_and_verb(args)
        if command is None:
            return CommandResult(self._parser.format_help().rstrip("\n").split("\n"))
        if verb is None:
            # ros2cli prints the command's help when its verb is missing
            return CommandResult(args._command_parser.format_help().rstrip("\n").split("\n"))
        prefix = f"ros2 {command.name} {verb.name}"
        try:
            return verb.main(self, args, line.strip())
        except PlainError as exc:
            return error(str(exc))
        except CommandError as exc:
            return error(f"{prefix}: {exc}")
        except (GraphError, InterfaceError) as exc:
            return error(f"{prefix}: {one_line(str(exc))}")
        except Exception as exc:  # a bug here must not take the app down: say what it was
            return error(f"{prefix}: internal error: {type(exc).__name__}: {one_line(str(exc))}")

    def close_all(self) -> None:
        """Stop every running stream (the app quits or resets)."""
        for stream in list(self.streams):
            stream.close()

    # -- for the verbs and streams ---------------------------------------------------
    def hidden_node(self) -> NodeRecord:
        """A new hidden node for one command (``/_ros2cli_1``, ``/_ros2cli_2``...),
        its process's own (the others discover its endpoints in time)."""
        self._hidden += 1
        # ros2cli's DirectNode: an rclpy node without parameter services
        name, owner = f"{HIDDEN_NODE_PREFIX}{self._hidden}", f"{OWNER}:{self._hidden}"
        return SimulatedNode(self.graph, name, owner, rclcpp=False).node

    def start(self, stream: Stream) -> CommandResult:
        """The result of a streaming command: its first lines, and the stream
        if it goes on."""
        lines = stream.poll()
        if not stream.done:
            self.streams.append(stream)
            return CommandResult(lines, stream=stream)
        return CommandResult(lines)

    def forget(self, stream: Stream) -> None:
        """A stream ended: it is no longer running."""
        if stream in self.streams:
            self.streams.remove(stream)


def _with_quoting_hint(message: str, line: str) -> str:
    """argparse's 'unrecognized arguments' after unquoted YAML: say to quote it."""
    if "unrecognized arguments" in message and ":" in line:
        return f"{message} (quote YAML values: \"{{x: 1.0}}\")"
    return message
