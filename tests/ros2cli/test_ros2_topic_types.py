"""``ros2 topic`` on a name that processes use with two types (a student's
geometry_msgs/msg/Pose subscription on turtlesim's /turtle1/pose): what
ros2topic prints then (ros2cli's list, info, type and echo verbs)."""

from __future__ import annotations

import pytest

from turtletui.graph.core import NS_PER_S
from turtletui.interfaces.geometry_msgs import Pose
from turtletui.ros2cli import CommandResult, Ros2Cli
from turtletui.runtime.simulation import Simulation


@pytest.fixture
def sim() -> Simulation:
    sim = Simulation()
    student = sim.graph.add_node("student", owner="student")
    sim.graph.add_subscription(student, "/turtle1/pose", Pose, 10, lambda msg: None)
    return sim


@pytest.fixture
def cli(sim: Simulation) -> Ros2Cli:
    return Ros2Cli(sim)


def ok(cli: Ros2Cli, line: str) -> CommandResult:
    result = cli.run(line)
    assert not result.error, result.lines
    return result


def test_list_t_shows_both_types_sorted(cli):
    assert "/turtle1/pose [geometry_msgs/msg/Pose, turtlesim/msg/Pose]" in ok(cli, "ros2 topic list -t").lines


def test_info_lists_the_types_and_counts_every_endpoint(cli):
    assert ok(cli, "ros2 topic info /turtle1/pose").lines == [
        "Type: ['geometry_msgs/msg/Pose', 'turtlesim/msg/Pose']", "Publisher count: 1", "Subscription count: 1"]


def test_info_verbose_gives_each_endpoint_its_own_type(cli):
    lines = ok(cli, "ros2 topic info -v /turtle1/pose").lines
    assert lines[0] == "Type: ['geometry_msgs/msg/Pose', 'turtlesim/msg/Pose']"
    types = [line for line in lines if line.startswith(("Node name:", "Topic type:"))]
    assert types == ["Node name: turtlesim", "Topic type: turtlesim/msg/Pose",
                     "Node name: student", "Topic type: geometry_msgs/msg/Pose"]


def test_type_prints_one_type_a_line_and_find_finds_either(cli):
    assert ok(cli, "ros2 topic type /turtle1/pose").lines == ["geometry_msgs/msg/Pose", "turtlesim/msg/Pose"]
    assert ok(cli, "ros2 topic find geometry_msgs/msg/Pose").lines == ["/turtle1/pose"]
    assert "/turtle1/pose" in ok(cli, "ros2 topic find turtlesim/msg/Pose").lines


def test_echo_and_hz_refuse_to_guess_a_type(cli):
    refused = "Cannot echo topic '/turtle1/pose', as it contains more than one type: " \
              "[geometry_msgs/msg/Pose, turtlesim/msg/Pose]"
    for line in ("ros2 topic echo /turtle1/pose", "ros2 topic hz /turtle1/pose"):
        result = cli.run(line)
        assert result.error and result.lines[-1].endswith(refused), result.lines


def test_echo_with_a_type_listens_to_that_type(sim, cli):
    result = ok(cli, "ros2 topic echo /turtle1/pose turtlesim/msg/Pose --once")
    sim.run_until(sim.graph.now_ns + NS_PER_S // 5)
    assert result.stream.poll()[0] == "x: 5.544444561004639"
    quiet = ok(cli, "ros2 topic echo /turtle1/pose geometry_msgs/msg/Pose")
    sim.run_until(sim.graph.now_ns + NS_PER_S // 5)
    assert quiet.stream.poll() == []  # nothing publishes that type
    wrong = cli.run("ros2 topic echo /turtle1/pose std_msgs/msg/String")
    assert wrong.error and wrong.lines[-1].endswith(
        "topic '/turtle1/pose' has type geometry_msgs/msg/Pose, turtlesim/msg/Pose, not std_msgs/msg/String")
