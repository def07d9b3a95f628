"""turtlesim_node's own ``--ros-args``: what ``ros2 run turtlesim turtlesim_node
--ros-args -p background_r:=0 -r __node:=sim`` asks of the simulator.

Parameters are held to turtlesim's declared types and ranges, as rclcpp holds
parameter overrides at start-up (an out-of-range colour stops turtlesim_node);
a misspelt parameter, which ROS would ignore without a word, is refused with
the names turtlesim has. The node can be renamed (``__node``/``__name``);
other remappings are refused, since turtletui's turtlesim cannot apply them.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from turtletui.compat.ros_args import RosArgsError, parse_ros_args
from turtletui.graph.logs import INFO, LogRecord, parse_level
from turtletui.graph.turtlesim_node import PARAMETERS, TurtlesimNode, parameter_problem
from turtletui.graph.type_description_service import PARAMETER as TYPE_DESCRIPTION_PARAMETER

if TYPE_CHECKING:
    from turtletui.runtime.simulation import Simulation

_NODE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


@dataclass(frozen=True)
class TurtlesimArgs:
    """turtlesim_node's settings from its command line."""

    name: str = TurtlesimNode.NAME
    """The node's name (``-r __node:=NAME``)."""
    parameters: dict[str, Any] = field(default_factory=dict)
    """Parameter overrides (``-p NAME:=VALUE``), checked against turtlesim's declarations."""
    log_level: int = INFO
    """The lowest level turtlesim logs at (``--log-level``)."""
    type_description_service: bool = True
    """``-p start_type_description_service:=false`` turns ~/get_type_description off."""

    def log_filter(self, sink: Callable[[LogRecord], None]) -> Callable[[LogRecord], None]:
        """``sink`` without turtlesim's lines below ``log_level``."""
        if self.log_level <= INFO:
            return sink  # turtlesim logs nothing below INFO
        name, level = self.name, self.log_level

        def filtered(record: LogRecord) -> None:
            if record.node != name or record.level >= level:
                sink(record)

        return filtered

    def apply(self, sim: Simulation) -> None:
        """Set the parameters on a simulation built with this node name."""
        for name, value in self.parameters.items():
            problem = sim.turtlesim.set_parameter(name, value)
            if problem is not None:  # parse_turtlesim_args checked them: a bug if reached
                raise RosArgsError(problem)
        if not self.type_description_service:
            sim.turtlesim.stop_type_description_service()


def parse_turtlesim_args(argv: Sequence[str]) -> TurtlesimArgs:
    """Read a ``--ros-args`` section for turtlesim; RosArgsError (one line) if it is wrong."""
    args = list(argv)
    if args and args[0] != "--ros-args":
        args.insert(0, "--ros-args")
    parsed = parse_ros_args(args)
    if parsed.user_args:
        raise RosArgsError(f"turtlesim takes only --ros-args, not {' '.join(parsed.user_args)!r}")
    own = TurtlesimNode.NAME
    name = own
    for node, source, target in parsed.remaps:
        if node not in (None, own):
            continue  # a rule for another node, as rcl ignores it
        if source not in ("__node", "__name"):
            raise RosArgsError(
                f"-r {source}:={target}: turtletui's turtlesim can be renamed (-r __node:=NAME) "
                "but not remapped otherwise"
            )
        if not _NODE_NAME.match(target):
            raise RosArgsError(
                f"-r {source}:={target}: {target!r} is not a valid node name "
                "(letters, digits and underscores, not starting with a digit)"
            )
        name = target
    parameters: dict[str, Any] = {}
    type_description_service = True
    for source, param, value in parsed.param_rules(f"/{name}"):
        # an rclcpp node leaves a file's parameters that it does not declare
        # (a /** section is for every node); -p names them, and is told
        if source == "--params-file" and param not in (*PARAMETERS, "use_sim_time", TYPE_DESCRIPTION_PARAMETER):
            continue
        flag = "--params-file: " if source == "--params-file" else "-p "
        if param == TYPE_DESCRIPTION_PARAMETER:
            if not isinstance(value, bool):
                raise RosArgsError(f"{flag}{param}:={_shown(value)}: {param} must be a bool")
            type_description_service = value
            continue
        if param == "use_sim_time":
            if value is not False:
                raise RosArgsError(
                    f"{flag}use_sim_time:={_shown(value)}: turtletui's turtlesim keeps its own clock; "
                    "use_sim_time can only be false"
                )
            continue
        problem = parameter_problem(param, value, f"/{name}")
        if problem is not None:
            if param not in PARAMETERS:
                close = difflib.get_close_matches(param, PARAMETERS, n=1)
                hint = f" (did you mean {close[0]}?)" if close else f" (it has {', '.join(PARAMETERS)})"
                problem += hint
            raise RosArgsError(f"{flag}{param}:={_shown(value)}: {problem}")
        parameters[param] = value
    log_level = INFO
    level = parsed.log_levels.get(name, parsed.log_levels.get(own, parsed.log_level))
    if level is not None:  # parse_ros_args checked it
        log_level = parse_level(level)
    return TurtlesimArgs(name, parameters, log_level, type_description_service)


def _shown(value: Any) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    return str(value)
