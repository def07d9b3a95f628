"""turtlesim_node's own --ros-args: parameters held to turtlesim's declarations,
the node renamed, everything else refused with one line."""

from __future__ import annotations

import pytest

from turtletui.compat.ros_args import RosArgsError
from turtletui.graph.logs import INFO, WARN, LogRecord
from turtletui.runtime.simulation import Simulation
from turtletui.runtime.turtlesim_args import TurtlesimArgs, parse_turtlesim_args


def built(args: TurtlesimArgs, logs: list | None = None) -> Simulation:
    sinks = [] if logs is None else [args.log_filter(logs.append)]
    sim = Simulation(realtime=False, log_sinks=sinks, turtlesim_name=args.name)
    args.apply(sim)
    return sim


def test_no_arguments_is_turtlesim_as_it_starts() -> None:
    args = parse_turtlesim_args([])
    assert args == TurtlesimArgs("turtlesim", {}, INFO)
    sim = built(args)
    assert sim.world.background == (69, 86, 255) and not sim.world.holonomic


def test_parameters_and_node_name_reach_the_simulation() -> None:
    args = parse_turtlesim_args(
        ["--ros-args", "-p", "background_r:=0", "-p", "holonomic:=true", "-r", "__node:=my_sim"]
    )
    logs: list[LogRecord] = []
    sim = built(args, logs)
    assert sim.world.background == (0, 86, 255) and sim.world.holonomic
    node = sim.turtlesim.node
    assert node.fqn == "/my_sim"
    assert node.parameters["background_r"] == 0 and node.parameters["holonomic"] is True
    assert logs[0].node == "my_sim" and logs[0].msg == "Starting turtlesim with node name /my_sim"


def test_node_scoped_rules_apply_to_turtlesim_only() -> None:
    args = parse_turtlesim_args(
        ["-p", "turtlesim:background_b:=7", "-p", "teleop:scale_linear:=3.0", "-r", "teleop:__node:=x"]
    )
    assert args.name == "turtlesim" and args.parameters == {"background_b": 7}


def test_use_sim_time_false_is_accepted() -> None:
    assert parse_turtlesim_args(["-p", "use_sim_time:=false"]).parameters == {}


def test_log_level_hides_turtlesims_lower_lines_only() -> None:
    args = parse_turtlesim_args(["--log-level", "warn"])
    assert args.log_level == WARN
    logs: list[LogRecord] = []
    sim = built(args, logs)
    assert logs == []  # the start lines are INFO
    sim.graph.log("turtlesim", WARN, "kept")
    sim.graph.log("teleop_turtle", INFO, "another node's line, kept")
    assert [r.msg for r in logs] == ["kept", "another node's line, kept"]


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["-p", "background_r:=300"], "-p background_r:=300: parameter 'background_r' must be an integer in 0..255"),
        (["-p", "background_g:=-1"], "must be an integer in 0..255, got -1"),
        (["-p", "background_b:=2.5"], "must be an integer in 0..255, got 2.5"),
        (["-p", "holonomic:=1"], "parameter 'holonomic' must be a bool, got 1"),
        (["-p", "backround_r:=3"], "is not declared by /turtlesim (did you mean background_r?)"),
        (["-p", "speed:=3"], "(it has background_r, background_g, background_b, holonomic)"),
        (["-p", "use_sim_time:=true"], "use_sim_time can only be false"),
        (["-r", "__node:=9lives"], "'9lives' is not a valid node name"),
        (["-r", "/turtle1/cmd_vel:=/cmd"], "-r /turtle1/cmd_vel:=/cmd: turtletui's turtlesim can be renamed"),
        (["-r", "__ns:=/sim1"], "-r __ns:=/sim1"),
        (["--log-level", "loud"], "unknown log level 'loud'"),
        (["-p", "background_r"], "must look like NAME:=VALUE"),
        (["--ros-args", "-x"], "Found unknown ROS arguments: ['-x']"),
        (["--ros-args", "--", "extra"], "turtlesim takes only --ros-args, not 'extra'"),
    ],
)
def test_bad_arguments_are_one_line_errors(argv: list[str], expected: str) -> None:
    with pytest.raises(RosArgsError) as caught:
        parse_turtlesim_args(argv)
    message = str(caught.value)
    assert expected in message and "\n" not in message


def test_the_type_description_service_can_be_turned_off() -> None:
    assert "/turtlesim/get_type_description" in built(parse_turtlesim_args([])).graph.services
    args = parse_turtlesim_args(["--ros-args", "-p", "start_type_description_service:=false"])
    assert "/turtlesim/get_type_description" not in built(args).graph.services
    assert "/turtlesim/get_parameters" in built(args).graph.services
    with pytest.raises(RosArgsError, match="start_type_description_service:=1: .* must be a bool"):
        parse_turtlesim_args(["--ros-args", "-p", "start_type_description_service:=1"])
