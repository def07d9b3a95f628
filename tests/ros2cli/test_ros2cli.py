"""The ros2 command interpreter: the tutorials' commands against a live
turtlesim, with ros2's own output (argparse's help and errors, PyYAML's
reading of values), and one clear line for every mistake."""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from turtletui.graph.core import NS_PER_S
from turtletui.interfaces import definition_text
from turtletui.ros2cli import (
    MAX_BUFFERED_LINES,
    CommandResult,
    Ros2Cli,
    YamlError,
    parse_yaml,
    yaml_lines,
)
from turtletui.runtime.simulation import Simulation

PACKAGE_ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def sim() -> Simulation:
    return Simulation()


@pytest.fixture
def cli(sim: Simulation) -> Ros2Cli:
    return Ros2Cli(sim)


def step(sim: Simulation, seconds: float) -> None:
    """Advance the lockstep simulation by ``seconds``."""
    sim.run_until(sim.graph.now_ns + round(seconds * NS_PER_S))


def ok(cli: Ros2Cli, line: str) -> CommandResult:
    result = cli.run(line)
    assert not result.error, result.lines
    return result


WAITING = ["Waiting for at least 1 matching subscription(s)..."]


def published(sim: Simulation, cli: Ros2Cli, line: str) -> list[str]:
    """What ``ros2 topic pub --once`` prints: it waits for turtlesim to match
    its new publisher (discovery, 50 ms; ros2cli looks every 100 ms)."""
    result = ok(cli, line)
    assert result.lines[-1:] == WAITING
    step(sim, 0.1)
    assert result.stream.done
    return result.stream.poll()


def hidden_nodes(sim: Simulation) -> list[str]:
    return [n.fqn for n in sim.graph.nodes if n.name.startswith("_")]


# -- ros2 node ------------------------------------------------------------------

def test_node_list_hides_the_cli_s_own_nodes(sim, cli):
    assert ok(cli, "ros2 node list").lines == ["/turtlesim"]
    echo = ok(cli, "ros2 topic echo /turtle1/pose")
    assert hidden_nodes(sim) == ["/_ros2cli_1"]
    assert ok(cli, "ros2 node list").lines == ["/turtlesim"]
    assert ok(cli, "ros2 node list -a").lines == ["/_ros2cli_1", "/turtlesim"]
    assert ok(cli, "ros2 node list --count-nodes").lines == ["1"]
    echo.stream.close()
    assert hidden_nodes(sim) == []


PARAMETER_SERVICES = [
    "describe_parameters: rcl_interfaces/srv/DescribeParameters",
    "get_parameter_types: rcl_interfaces/srv/GetParameterTypes",
    "get_parameters: rcl_interfaces/srv/GetParameters",
    "get_type_description: type_description_interfaces/srv/GetTypeDescription",
    "list_parameters: rcl_interfaces/srv/ListParameters",
    "set_parameters: rcl_interfaces/srv/SetParameters",
    "set_parameters_atomically: rcl_interfaces/srv/SetParametersAtomically",
]
"""What every node serves (Jazzy's turtlesim in the official 'Understanding nodes' tutorial)."""


def test_node_info_turtlesim_as_ros2node_prints_it(cli):
    assert ok(cli, "ros2 node info /turtlesim").lines == [
        "/turtlesim",
        "  Subscribers:",
        "    /parameter_events: rcl_interfaces/msg/ParameterEvent",
        "    /turtle1/cmd_vel: geometry_msgs/msg/Twist",
        "  Publishers:",
        "    /parameter_events: rcl_interfaces/msg/ParameterEvent",
        "    /rosout: rcl_interfaces/msg/Log",
        "    /turtle1/color_sensor: turtlesim/msg/Color",
        "    /turtle1/pose: turtlesim/msg/Pose",
        "  Service Servers:",
        "    /clear: std_srvs/srv/Empty",
        "    /kill: turtlesim/srv/Kill",
        "    /reset: std_srvs/srv/Empty",
        "    /spawn: turtlesim/srv/Spawn",
        "    /turtle1/set_pen: turtlesim/srv/SetPen",
        "    /turtle1/teleport_absolute: turtlesim/srv/TeleportAbsolute",
        "    /turtle1/teleport_relative: turtlesim/srv/TeleportRelative",
        *(f"    /turtlesim/{service}" for service in PARAMETER_SERVICES),
        "  Service Clients:",
        "",
        "  Action Servers:",
        "    /turtle1/rotate_absolute: turtlesim/action/RotateAbsolute",
        "  Action Clients:",
        "",
    ]


def test_node_info_teleop_turtle_as_the_tutorial_shows_it(sim, cli):
    """The 'Understanding nodes' tutorial's `ros2 node info /teleop_turtle` (Jazzy;
    turtletui leaves out an action client's hidden topics and services)."""
    from turtletui.tui.session import Teleop

    Teleop(sim)
    assert ok(cli, "ros2 node info /teleop_turtle").lines == [
        "/teleop_turtle",
        "  Subscribers:",
        "    /parameter_events: rcl_interfaces/msg/ParameterEvent",
        "  Publishers:",
        "    /parameter_events: rcl_interfaces/msg/ParameterEvent",
        "    /rosout: rcl_interfaces/msg/Log",
        "    /turtle1/cmd_vel: geometry_msgs/msg/Twist",
        "  Service Servers:",
        *(f"    /teleop_turtle/{service}" for service in PARAMETER_SERVICES),
        "  Service Clients:",
        "",
        "  Action Servers:",
        "",
        "  Action Clients:",
        "    /turtle1/rotate_absolute: turtlesim/action/RotateAbsolute",
    ]
    assert ok(cli, "ros2 param list /teleop_turtle").lines == [
        "  qos_overrides./parameter_events.publisher.depth", "  qos_overrides./parameter_events.publisher.durability",
        "  qos_overrides./parameter_events.publisher.history", "  qos_overrides./parameter_events.publisher.reliability",
        "  scale_angular", "  scale_linear", "  start_type_description_service", "  use_sim_time"]
    assert ok(cli, "ros2 param set /teleop_turtle scale_linear 4.0").lines == ["Set parameter successful"]
    assert ok(cli, "ros2 param get /teleop_turtle scale_linear").lines == ["Double value is: 4.0"]


def test_a_command_s_hidden_node_is_ros2cli_s_rclpy_node(sim, cli):
    """ros2cli's DirectNode: /rosout, /parameter_events, ~/get_type_description,
    use_sim_time and start_type_description_service; no parameter services."""
    echo = ok(cli, "ros2 topic echo /turtle1/pose")
    node = echo.stream.node
    info = ok(cli, f"ros2 node info {node.fqn} --include-hidden").lines
    assert info[info.index("  Publishers:") + 1:info.index("  Service Servers:") + 2] == [
        "    /parameter_events: rcl_interfaces/msg/ParameterEvent",
        "    /rosout: rcl_interfaces/msg/Log",
        "  Service Servers:",
        "    /_ros2cli_1/get_type_description: type_description_interfaces/srv/GetTypeDescription",
    ]
    assert info[info.index("  Subscribers:") + 1:info.index("  Publishers:")] == ["    /turtle1/pose: turtlesim/msg/Pose"]
    assert node.parameters == {"use_sim_time": False, "start_type_description_service": True}
    assert "/_ros2cli_1/get_type_description" not in ok(cli, "ros2 service list").lines  # hidden, as ROS's
    plain = ok(cli, f"ros2 node info {node.fqn}").lines
    assert plain[plain.index("  Service Servers:") + 1] == ""
    refused = cli.run(f"ros2 param set {node.fqn} use_sim_time true")
    assert refused.error


def test_node_info_shows_the_clients_of_a_running_command(cli):
    call = ok(cli, "ros2 service call /clear std_srvs/srv/Empty")
    info = ok(cli, f"ros2 node info {call.stream.node.fqn}").lines
    assert info[info.index("  Service Clients:") + 1] == "    /clear: std_srvs/srv/Empty"


# -- ros2 topic -----------------------------------------------------------------

def test_topic_list(cli):
    # as the tutorials show it: every node also publishes /parameter_events and /rosout
    assert ok(cli, "ros2 topic list").lines == [
        "/parameter_events", "/rosout", "/turtle1/cmd_vel", "/turtle1/color_sensor", "/turtle1/pose"]
    assert ok(cli, "topic list -t").lines == [
        "/parameter_events [rcl_interfaces/msg/ParameterEvent]",
        "/rosout [rcl_interfaces/msg/Log]",
        "/turtle1/cmd_vel [geometry_msgs/msg/Twist]",
        "/turtle1/color_sensor [turtlesim/msg/Color]",
        "/turtle1/pose [turtlesim/msg/Pose]",
    ]
    assert ok(cli, "topic list -c").lines == ["5"]
    assert ok(cli, "ros2 topic info /rosout").lines == [
        "Type: rcl_interfaces/msg/Log", "Publisher count: 1", "Subscription count: 0"]
    assert ok(cli, "ros2 topic type /parameter_events").lines == ["rcl_interfaces/msg/ParameterEvent"]


def test_topic_echo_rosout_prints_every_nodes_log_lines_as_log_messages(sim, cli):
    echo = ok(cli, "ros2 topic echo /rosout")
    sim.graph.log("talker", 20, "Publishing: hello")
    assert echo.stream.poll() == [
        "stamp:", "  sec: 1700000000", "  nanosec: 0", "level: 20", "name: talker",
        "msg: 'Publishing: hello'", "file: ''", "function: ''", "line: 0", "---",
    ]
    once = ok(cli, "ros2 topic echo /rosout --field msg --once")
    sim.graph.log("talker", 30, "careful")
    assert once.stream.poll() == ["careful", "---"] and once.stream.done
    assert "msg: careful" in echo.stream.poll()
    echo.stream.close()
    sim.graph.log("talker", 20, "after")
    assert echo.stream.poll() == []


def test_topic_info_counts_endpoints_including_a_running_echo(cli):
    assert ok(cli, "ros2 topic info /turtle1/pose").lines == [
        "Type: turtlesim/msg/Pose", "Publisher count: 1", "Subscription count: 0"]
    ok(cli, "ros2 topic echo /turtle1/pose")
    assert ok(cli, "ros2 topic info turtle1/pose").lines == [
        "Type: turtlesim/msg/Pose", "Publisher count: 1", "Subscription count: 1"]


def test_topic_info_verbose_names_nodes_and_qos(cli):
    lines = ok(cli, "ros2 topic info /turtle1/cmd_vel -v").lines
    assert lines[:4] == ["Type: geometry_msgs/msg/Twist", "", "Publisher count: 0", ""]
    at = lines.index("Subscription count: 1")
    assert lines[at + 2:at + 7] == [
        "Node name: turtlesim", "Node namespace: /", "Topic type: geometry_msgs/msg/Twist",
        "Topic type hash: RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a",
        "Endpoint type: SUBSCRIPTION"]
    # Fast DDS shares no history of another process's endpoint; the GID is a
    # program's get_subscriptions_info_by_topic's
    assert lines[at + 7].startswith("GID: ") and len(lines[at + 7].split(".")) == 16
    assert lines[at + 8:at + 16] == [
        "QoS profile:", "  Reliability: RELIABLE", "  History (Depth): UNKNOWN", "  Durability: VOLATILE",
        "  Lifespan: Infinite", "  Deadline: Infinite", "  Liveliness: AUTOMATIC", "  Liveliness lease duration: Infinite"]


def test_topic_type_and_find(cli):
    assert ok(cli, "ros2 topic type /turtle1/pose").lines == ["turtlesim/msg/Pose"]
    assert ok(cli, "ros2 topic find geometry_msgs/msg/Twist").lines == ["/turtle1/cmd_vel"]
    assert ok(cli, "ros2 topic find turtlesim/Color").lines == ["/turtle1/color_sensor"]


def test_topic_echo_prints_poses_as_yaml(sim, cli):
    result = ok(cli, "ros2 topic echo /turtle1/pose")
    assert result.lines == [] and not result.stream.done
    assert result.stream.poll() == []
    step(sim, 0.05)
    assert result.stream.poll() == []  # not discovered yet (50 ms)
    step(sim, 0.05)
    lines = result.stream.poll()
    assert lines[:6] == [
        "x: 5.544444561004639",
        "y: 5.544444561004639",
        "theta: 0.0",
        "linear_velocity: 0.0",
        "angular_velocity: 0.0",
        "---",
    ]
    assert len(lines) == 6 * lines.count("---") and lines.count("---") >= 2
    assert result.stream.poll() == []  # nothing new since


def test_topic_echo_once_ends_by_itself(sim, cli):
    result = ok(cli, "ros2 topic echo --once /turtle1/pose")
    step(sim, 0.5)
    assert result.stream.done
    assert result.stream.poll()[-1] == "---"
    assert result.stream.poll() == []
    assert hidden_nodes(sim) == [] and cli.streams == []


def test_topic_echo_field(sim, cli):
    result = ok(cli, "ros2 topic echo /turtle1/pose --field x --once")
    step(sim, 0.1)
    assert result.stream.poll() == ["5.544444561004639", "---"]


def test_topic_echo_nested_message_from_topic_pub(sim, cli):
    echo = ok(cli, "ros2 topic echo /turtle1/cmd_vel")
    published(sim, cli, "ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist "
                        "'{linear: {x: 2.0}, angular: {z: 1.8}}'")
    step(sim, 0.02)
    assert echo.stream.poll() == [
        "linear:", "  x: 2.0", "  y: 0.0", "  z: 0.0",
        "angular:", "  x: 0.0", "  y: 0.0", "  z: 1.8",
        "---",
    ]


def test_topic_echo_keeps_at_most_200_lines_of_whole_messages(sim, cli):
    echo = ok(cli, "ros2 topic echo /turtle1/pose")
    step(sim, 5.0)  # ~310 poses, 6 lines each, never polled
    lines = echo.stream.poll()
    assert 200 - 6 < len(lines) <= MAX_BUFFERED_LINES
    assert lines[0].startswith("x: ") and lines[-1] == "---"


def test_topic_hz_reports_62_5_hz_once_a_second(sim, cli):
    hz = ok(cli, "ros2 topic hz /turtle1/pose")
    step(sim, 0.9)
    assert hz.stream.poll() == []
    step(sim, 1.2)
    lines = hz.stream.poll()
    assert len(lines) == 4  # two reports
    assert lines[2] == "average rate: 62.500"
    assert re.fullmatch(r"\tmin: 0\.016s max: 0\.016s std dev: 0\.00000s window: \d+", lines[3])
    assert int(lines[3].rsplit(" ", 1)[1]) > int(lines[1].rsplit(" ", 1)[1]) > 50


def test_topic_hz_window(sim, cli):
    hz = ok(cli, "ros2 topic hz /turtle1/pose -w 10")
    step(sim, 1.1)
    assert hz.stream.poll()[1].endswith("window: 11")


def test_topic_pub_once_moves_the_turtle(sim, cli):
    lines = published(sim, cli, "ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist "
                                "'{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 0.0}}'")
    assert lines == [
        "publisher: beginning loop",
        "publishing #1: geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=2.0, y=0.0, z=0.0),"
        " angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0))",
        "",
    ]
    assert hidden_nodes(sim) == [] and cli.streams == []
    step(sim, 1.5)  # turtlesim stops 1 s after the last command
    turtle = sim.world.turtles["turtle1"]
    assert turtle.x == pytest.approx(5.544 + 2.0, abs=0.05)
    assert turtle.y == pytest.approx(5.544, abs=1e-3)


def test_topic_pub_without_outer_braces_and_with_ints(sim, cli):
    ok(cli, "ros2 topic pub -1 /turtle1/cmd_vel geometry_msgs/msg/Twist 'angular: {z: 1}'")
    step(sim, 0.5)
    assert sim.world.turtles["turtle1"].theta > 0.3


def test_unquoted_yaml_is_joined_back_together(sim, cli):
    """The shell would split it; students forget the quotes, so join the rest."""
    pub = published(sim, cli, "ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist "
                              "{linear: {x: -1.0}, angular: {z: -1.5}} ")
    assert "angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=-1.5)" in pub[1]
    goal = ok(cli, "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute "
                   "{theta: -1.57} --feedback")
    assert goal.lines[2] == "     theta: -1.57"
    step(sim, 0.1)
    assert "Feedback:" in goal.stream.poll()


def test_topic_pub_rate_and_times(sim, cli):
    result = ok(cli, "ros2 topic pub -r 10 -t 3 /turtle1/cmd_vel geometry_msgs/Twist '{}'")
    topic = sim.graph.topics["/turtle1/cmd_vel"]
    assert result.lines == WAITING and topic.count == 0  # --times waits for one subscription
    step(sim, 0.1)
    assert topic.count == 1 and not result.stream.done
    step(sim, 0.25)
    assert topic.count == 3 and result.stream.done
    lines = result.stream.poll()
    assert [line.split(":")[0] for line in lines if line] == [
        "publisher", "publishing #1", "publishing #2", "publishing #3"]
    step(sim, 1.0)
    assert topic.count == 3 and hidden_nodes(sim) == []


def test_topic_pub_keeps_the_turtle_moving_until_closed(sim, cli):
    pub = ok(cli, "ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist "
                  "\"{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 1.8}}\"")
    step(sim, 2.5)
    turtle = sim.world.turtles["turtle1"]
    assert turtle.vx == 2.0 and turtle.wz == 1.8  # default 1 Hz keeps it going
    pub.stream.close()
    assert pub.stream.done and hidden_nodes(sim) == [] and cli.streams == []
    step(sim, 1.5)
    assert turtle.vx == 0.0


def test_topic_pub_rate_is_capped(sim, cli):
    result = ok(cli, "ros2 topic pub -r 1000 /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'")
    assert result.lines[0] == "WARNING: rate limited to 100 Hz in turtletui"
    step(sim, 1.0)
    assert result.stream.count == 101  # every 10 ms from t = 0
    # turtlesim heard those from 50 ms on, once it had discovered the publisher
    assert sim.graph.topics["/turtle1/cmd_vel"].count == 96


def test_topic_pub_print_every_nth(sim, cli):
    result = ok(cli, "ros2 topic pub -r 100 -p 50 /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'")
    assert result.lines == ["publisher: beginning loop"]
    step(sim, 1.0)
    assert [line[:14] for line in result.stream.poll() if line] == ["publishing #50", "publishing #10"]


def test_topic_pub_to_a_new_topic_and_string_fields(sim, cli):
    pub = ok(cli, "ros2 topic pub -r 10 /chatter std_msgs/msg/String '{data: 42}'")
    echo = ok(cli, "ros2 topic echo /chatter std_msgs/msg/String")
    step(sim, 0.15)
    assert echo.stream.poll() == ["data: '42'", "---"]
    pub.stream.close()
    echo.stream.close()


def test_topic_pub_warns_about_a_topic_nobody_listens_to(cli):
    result = ok(cli, "ros2 topic pub --once /turtle1/cmd_vell geometry_msgs/msg/Twist '{}'")
    assert result.lines[0] == (
        "WARNING: nothing subscribes to '/turtle1/cmd_vell' yet (did you mean /turtle1/cmd_vel?)")


# -- ros2 service ---------------------------------------------------------------

def test_service_list_type_find_info(cli):
    assert ok(cli, "ros2 service list").lines == [
        "/clear", "/kill", "/reset", "/spawn", "/turtle1/set_pen",
        "/turtle1/teleport_absolute", "/turtle1/teleport_relative",
        *(f"/turtlesim/{service.split(':')[0]}" for service in PARAMETER_SERVICES)]
    assert ok(cli, "ros2 service type /turtlesim/get_parameters").lines == ["rcl_interfaces/srv/GetParameters"]
    assert ok(cli, "ros2 service list -t").lines[3] == "/spawn [turtlesim/srv/Spawn]"
    assert ok(cli, "ros2 service type /spawn").lines == ["turtlesim/srv/Spawn"]
    assert ok(cli, "ros2 service find std_srvs/srv/Empty").lines == ["/clear", "/reset"]
    assert ok(cli, "ros2 service info /spawn").lines == [
        "Type: turtlesim/srv/Spawn", "Clients count: 0", "Services count: 1"]


def test_service_call_reaches_turtlesims_parameter_services(sim, cli):
    listed = ok(cli, "ros2 service call /turtlesim/list_parameters rcl_interfaces/srv/ListParameters")
    step(sim, 0.016)
    assert listed.stream.poll()[1] == (
        "rcl_interfaces.srv.ListParameters_Response(result=rcl_interfaces.msg.ListParametersResult("
        "names=['background_b', 'background_g', 'background_r', 'holonomic', "
        "'qos_overrides./parameter_events.publisher.depth', 'qos_overrides./parameter_events.publisher.durability', "
        "'qos_overrides./parameter_events.publisher.history', "
        "'qos_overrides./parameter_events.publisher.reliability', 'start_type_description_service', "
        "'use_sim_time'], prefixes=['qos_overrides./parameter_events.publisher']))"
    )
    refused = ok(cli, "ros2 service call /turtlesim/set_parameters rcl_interfaces/srv/SetParameters "
                      "\"{parameters: [{name: background_r, value: {type: 2, integer_value: 256}}]}\"")
    step(sim, 0.016)
    assert "doesn't comply with integer range" in refused.stream.poll()[1]
    assert sim.world.canvas.background == (69, 86, 255)


def test_service_call_spawn_creates_turtle2(sim, cli):
    result = ok(cli, "ros2 service call /spawn turtlesim/srv/Spawn \"{x: 2, y: 2, theta: 0.2, name: ''}\"")
    assert result.lines == [
        "requester: making request: turtlesim.srv.Spawn_Request(x=2.0, y=2.0, theta=0.2, name='')",
        "",
    ]
    assert not result.stream.done
    step(sim, 0.016)
    assert result.stream.done
    assert result.stream.poll() == ["response:", "turtlesim.srv.Spawn_Response(name='turtle2')", ""]
    assert "turtle2" in sim.world.turtles
    assert sim.world.turtles["turtle2"].x == pytest.approx(2.0)
    assert "/turtle2/pose" in ok(cli, "ros2 topic list").lines
    assert hidden_nodes(sim) == [] and cli.streams == []


def test_service_call_type_may_be_left_out_and_empty_request(sim, cli):
    kill = ok(cli, "ros2 service call /kill '{name: turtle1}'")
    reset = ok(cli, "ros2 service call /clear std_srvs/srv/Empty")
    step(sim, 0.016)
    assert kill.stream.poll()[:2] == ["response:", "turtlesim.srv.Kill_Response()"]
    assert reset.stream.poll()[:2] == ["response:", "std_srvs.srv.Empty_Response()"]
    assert "turtle1" not in sim.world.turtles


def test_service_call_set_pen_with_the_off_key_quoted(sim, cli):
    call = ok(cli, "ros2 service call /turtle1/set_pen turtlesim/srv/SetPen "
                   "\"{r: 255, g: 0, b: 0, width: 5, 'off': 1}\"")
    step(sim, 0.016)
    assert call.stream.done
    assert not sim.world.turtles["turtle1"].pen_on


def test_an_unquoted_off_key_is_read_as_a_boolean_as_pyyaml_reads_it(sim, cli):
    """YAML 1.1 reads ``off`` as false, keys too: the real ros2 fails here as well."""
    result = cli.run("ros2 service call /turtle1/set_pen turtlesim/srv/SetPen "
                     "'{r: 255, g: 0, b: 0, width: 5, off: 1}'")
    assert result.error and result.lines == [
        "Failed to populate field: a field name was read as the boolean false (YAML reads on,"
        " off, yes and no as booleans): quote it, e.g. \"{'off': 1}\""]
    assert sim.world.turtles["turtle1"].pen_on and hidden_nodes(sim) == []


def test_values_are_converted_as_set_message_fields_converts_them(sim, cli):
    """float('1e3'), int(2.9), str(42), as rosidl_runtime_py does."""
    pub = published(sim, cli, "ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist "
                              "'{linear: {x: 1e3, y: 017}, angular: {z: !!float 1}}'")
    assert ("linear=geometry_msgs.msg.Vector3(x=1000.0, y=15.0, z=0.0), "
            "angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=1.0)") in pub[1]
    spawn = ok(cli, "ros2 service call /spawn turtlesim/srv/Spawn '{x: 2, y: 3.5, name: 0o17}'")
    assert spawn.lines[0] == ("requester: making request: "
                              "turtlesim.srv.Spawn_Request(x=2.0, y=3.5, theta=0.0, name='0o17')")
    pen = ok(cli, "ros2 service call /turtle1/set_pen turtlesim/srv/SetPen '{r: 2.9, width: 4.0}'")
    assert "r=2, g=0, b=0, width=4," in pen.lines[0]


# -- ros2 param ------------------------------------------------------------------

TURTLESIM_PARAMETERS = [  # `ros2 param list /turtlesim` on Jazzy and Kilted: its own and rclcpp's
    "background_b", "background_g", "background_r", "holonomic",
    "qos_overrides./parameter_events.publisher.depth", "qos_overrides./parameter_events.publisher.durability",
    "qos_overrides./parameter_events.publisher.history", "qos_overrides./parameter_events.publisher.reliability",
    "start_type_description_service", "use_sim_time"]


def test_param_list_get(sim, cli):
    assert ok(cli, "ros2 param list").lines == ["/turtlesim:", *(f"  {name}" for name in TURTLESIM_PARAMETERS)]
    assert ok(cli, "ros2 param list /turtlesim").lines == [f"  {name}" for name in TURTLESIM_PARAMETERS]
    assert ok(cli, "ros2 param get /turtlesim background_r").lines == ["Integer value is: 69"]
    assert ok(cli, "ros2 param get /turtlesim holonomic").lines == ["Boolean value is: False"]
    assert ok(cli, "ros2 param get /turtlesim use_sim_time").lines == ["Boolean value is: False"]
    assert ok(cli, "ros2 param get /turtlesim qos_overrides./parameter_events.publisher.depth").lines == [
        "Integer value is: 1000"]


def test_humble_nodes_have_no_type_description_parameter():
    """start_type_description_service came with the type description service, in Iron."""
    from turtletui.graph.teleop_node import TeleopNode

    sim = Simulation(distro="humble")
    TeleopNode(sim.graph, "teleop", "humble")
    cli = Ros2Cli(sim)
    expected = [f"  {name}" for name in TURTLESIM_PARAMETERS if name != "start_type_description_service"]
    assert ok(cli, "ros2 param list /turtlesim").lines == expected
    assert "  start_type_description_service" not in ok(cli, "ros2 param list /teleop_turtle").lines
    assert "  use_sim_time" in ok(cli, "ros2 param list /teleop_turtle").lines


def test_param_list_with_types_and_get_without(cli):
    types = ["integer"] * 3 + ["boolean", "integer", "string", "string", "string", "boolean", "boolean"]
    assert ok(cli, "ros2 param list /turtlesim --param-type").lines == [
        f"  {name} (type: {kind})" for name, kind in zip(TURTLESIM_PARAMETERS, types, strict=True)]
    assert ok(cli, "ros2 param get /turtlesim background_r --hide-type").lines == ["69"]


def test_rclcpp_s_own_parameters_are_read_only_but_use_sim_time(sim, cli):
    refused = cli.run("ros2 param set /turtlesim qos_overrides./parameter_events.publisher.depth 10")
    assert refused.error and refused.lines == [
        "Setting parameter failed: parameter 'qos_overrides./parameter_events.publisher.depth' cannot be set"
        " because it is read-only"]
    assert cli.run("ros2 param set /turtlesim start_type_description_service false").error
    assert ok(cli, "ros2 param set /turtlesim use_sim_time false").lines == ["Set parameter successful"]
    refused = cli.run("ros2 param set /turtlesim use_sim_time true")
    assert refused.error and "use_sim_time can only be false" in refused.lines[0]
    assert ok(cli, "ros2 param get /turtlesim use_sim_time").lines == ["Boolean value is: False"]


def test_interface_list_and_packages_by_kind(cli):
    assert ok(cli, "ros2 interface list -a").lines == [
        "Actions:",
        "    example_interfaces/action/Fibonacci",
        "    tf2_msgs/action/LookupTransform",
        "    turtlesim/action/RotateAbsolute",
    ]
    assert ok(cli, "ros2 interface packages -a").lines == ["example_interfaces", "tf2_msgs", "turtlesim"]
    assert ok(cli, "ros2 interface package turtlesim -s").lines[0] == "turtlesim/srv/Kill"


def test_param_set_background_r_changes_the_canvas(sim, cli):
    assert ok(cli, "ros2 param set /turtlesim background_r 150").lines == ["Set parameter successful"]
    assert sim.world.canvas.background == (150, 86, 255)
    assert ok(cli, "ros2 param get /turtlesim background_r").lines == ["Integer value is: 150"]


def test_param_set_holonomic(sim, cli):
    assert ok(cli, "ros2 param set /turtlesim holonomic true").lines == ["Set parameter successful"]
    assert sim.world.holonomic is True


def test_param_dump(cli):
    """As ros2param's dump: dotted names nest, keys sorted."""
    assert ok(cli, "ros2 param dump /turtlesim").lines == [
        "/turtlesim:",
        "  ros__parameters:",
        "    background_b: 255",
        "    background_g: 86",
        "    background_r: 69",
        "    holonomic: false",
        "    qos_overrides:",
        "      /parameter_events:",
        "        publisher:",
        "          depth: 1000",
        "          durability: volatile",
        "          history: keep_last",
        "          reliability: reliable",
        "    start_type_description_service: true",
        "    use_sim_time: false",
    ]


def test_params_of_other_nodes_and_setters(sim, cli):
    node = sim.graph.add_node("my_node", owner="test")
    sim.graph.set_parameter(node, "speed", 2.5)
    sim.graph.set_parameter(node, "name", "abc")
    assert ok(cli, "ros2 param get /my_node speed").lines == ["Double value is: 2.5"]
    assert ok(cli, "ros2 param get /my_node name").lines == ["String value is: abc"]
    refused = cli.run("ros2 param set /my_node speed 3.0")
    assert refused.error and refused.lines[0].startswith("Setting parameter failed:")
    seen = []
    node.parameter_setter = lambda name, value: seen.append((name, value))
    assert ok(cli, "ros2 param set /my_node speed 3").lines == ["Set parameter successful"]
    assert seen == [("speed", 3)]


# -- ros2 action ------------------------------------------------------------------

def test_action_list_and_info(cli):
    assert ok(cli, "ros2 action list").lines == ["/turtle1/rotate_absolute"]
    assert ok(cli, "ros2 action list -t").lines == [
        "/turtle1/rotate_absolute [turtlesim/action/RotateAbsolute]"]
    assert ok(cli, "ros2 action info /turtle1/rotate_absolute").lines == [
        "Action: /turtle1/rotate_absolute", "Action clients: 0", "Action servers: 1", "    /turtlesim"]


def test_action_send_goal_reaches_the_goal(sim, cli):
    result = ok(cli, "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute "
                     "\"{theta: 1.57}\"")
    assert result.lines == [
        "Waiting for an action server to become available...",
        "Sending goal:",
        "     theta: 1.57",
        "",
    ]
    step(sim, 0.016)
    accepted = result.stream.poll()
    assert re.fullmatch(r"Goal accepted with ID: [0-9a-f]{32}", accepted[0]) and accepted[1] == ""
    step(sim, 2.5)  # 1 rad/s
    assert result.stream.done
    lines = result.stream.poll()
    assert "Feedback:" not in lines
    assert lines[0] == "Result:" and lines[1].startswith("    delta: ") and lines[2] == ""
    assert lines[3] == "Goal finished with status: SUCCEEDED"
    assert sim.world.turtles["turtle1"].theta == pytest.approx(1.57, abs=0.02)
    assert hidden_nodes(sim) == []


def test_action_send_goal_feedback(sim, cli):
    result = ok(cli, "ros2 action send_goal --feedback /turtle1/rotate_absolute "
                     "turtlesim/action/RotateAbsolute '{theta: -0.5}'")
    step(sim, 1.0)
    lines = result.stream.poll()
    assert lines[2:5] == ["Feedback:", "    remaining: -0.5", ""]
    assert lines[-1] == "Goal finished with status: SUCCEEDED"


def test_closing_send_goal_cancels_it(sim, cli):
    result = ok(cli, "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute "
                     "'{theta: 3.0}'")
    step(sim, 0.5)
    handle = result.stream.handle
    result.stream.close()
    step(sim, 0.1)
    assert handle.status == "canceled"
    theta = sim.world.turtles["turtle1"].theta
    step(sim, 0.5)
    assert sim.world.turtles["turtle1"].theta == theta


# -- an action's hidden topics and services -------------------------------------------
# rcl_action gives turtlesim's rotate_absolute server (and every action client)
# endpoints under <action>/_action/: ros2 shows them only when asked (ros2cli's
# topic_or_service_is_hidden), as on a real graph.

ROTATE = "/turtle1/rotate_absolute/_action"


def test_hidden_action_topics_and_services_are_listed_when_asked(cli):
    assert not any("/_action/" in line for line in ok(cli, "ros2 topic list").lines)
    assert not any("/_action/" in line for line in ok(cli, "ros2 service list").lines)
    topics = ok(cli, "ros2 topic list -t --include-hidden-topics").lines
    assert [line for line in topics if "/_action/" in line] == [
        f"{ROTATE}/feedback [turtlesim/action/RotateAbsolute_FeedbackMessage]",
        f"{ROTATE}/status [action_msgs/msg/GoalStatusArray]",
    ]
    services = ok(cli, "ros2 service list -t --include-hidden-services").lines
    assert [line for line in services if "/_action/" in line] == [
        f"{ROTATE}/cancel_goal [action_msgs/srv/CancelGoal]",
        f"{ROTATE}/get_result [turtlesim/action/RotateAbsolute_GetResult]",
        f"{ROTATE}/send_goal [turtlesim/action/RotateAbsolute_SendGoal]",
    ]
    assert ok(cli, "ros2 topic find action_msgs/msg/GoalStatusArray").lines == []
    assert ok(cli, "ros2 topic find action_msgs/msg/GoalStatusArray --include-hidden-topics").lines == [
        f"{ROTATE}/status"]
    assert ok(cli, "ros2 service find action_msgs/srv/CancelGoal -c --include-hidden-services").lines == ["1"]
    info = ok(cli, "ros2 node info /turtlesim --include-hidden").lines
    assert f"    {ROTATE}/status: action_msgs/msg/GoalStatusArray" in info
    assert f"    {ROTATE}/send_goal: turtlesim/action/RotateAbsolute_SendGoal" in info
    assert info.index(f"    {ROTATE}/status: action_msgs/msg/GoalStatusArray") < info.index("  Service Servers:")


def test_a_send_goal_client_subscribes_to_the_hidden_topics(sim, cli):
    assert ok(cli, f"ros2 topic info {ROTATE}/status").lines == [
        "Type: action_msgs/msg/GoalStatusArray", "Publisher count: 1", "Subscription count: 0"]
    goal = ok(cli, "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute '{theta: 3.0}'")
    assert ok(cli, f"ros2 topic info {ROTATE}/feedback").lines[1:] == ["Publisher count: 1", "Subscription count: 1"]
    verbose = ok(cli, f"ros2 topic info -v {ROTATE}/status").lines
    assert verbose[:4] == ["Type: action_msgs/msg/GoalStatusArray", "", "Publisher count: 1", ""]
    assert verbose[4:6] == ["Node name: turtlesim", "Node namespace: /"]
    assert verbose.count("  Durability: TRANSIENT_LOCAL") == 2  # rcl_action's status QoS, both sides
    assert verbose.count("  History (Depth): UNKNOWN") == 2
    assert f"Node name: {goal.stream.node.name}" in verbose
    assert ok(cli, f"ros2 service --include-hidden-services info {ROTATE}/get_result").lines == [
        "Type: turtlesim/action/RotateAbsolute_GetResult", "Clients count: 1", "Services count: 1"]
    goal.stream.close()
    step(sim, 0.1)
    assert ok(cli, f"ros2 topic info {ROTATE}/feedback").lines[2] == "Subscription count: 0"


@pytest.mark.parametrize(("line", "shown"), [
    (f"ros2 topic --include-hidden-topics type {ROTATE}/feedback", "turtlesim/action/RotateAbsolute_FeedbackMessage"),
    (f"ros2 service --include-hidden-services type {ROTATE}/cancel_goal", "action_msgs/srv/CancelGoal"),
])
def test_hidden_names_are_typed_when_asked(cli, line, shown):
    assert ok(cli, line).lines == [shown]


@pytest.mark.parametrize(("line", "message"), [
    # ros2 exits 1 silently (type) or says "Unknown service" (info): one line says why here
    (f"ros2 topic type {ROTATE}/status",
     f"ros2 topic type: topic '{ROTATE}/status' is hidden (a part of its name starts with '_'): "
     f"try 'ros2 topic --include-hidden-topics type {ROTATE}/status'"),
    (f"ros2 service info {ROTATE}/send_goal",
     f"ros2 service info: service '{ROTATE}/send_goal' is hidden (a part of its name starts with '_'): "
     f"try 'ros2 service --include-hidden-services info {ROTATE}/send_goal'"),
    # nothing travels there: the graph hands goals, feedback and results over itself
    (f"ros2 topic echo {ROTATE}/feedback",
     "ros2 topic echo: turtletui sends nothing on the hidden topics of action '/turtle1/rotate_absolute': "
     "'ros2 action send_goal --feedback /turtle1/rotate_absolute turtlesim/action/RotateAbsolute GOAL' prints a "
     "goal's feedback and result"),
    (f"ros2 topic pub --once {ROTATE}/feedback turtlesim/action/RotateAbsolute_FeedbackMessage",
     "ros2 topic pub: turtletui sends nothing on the hidden topics of action '/turtle1/rotate_absolute'"),
    (f"ros2 topic hz {ROTATE}/status", "ros2 topic hz: turtletui sends nothing on the hidden topics"),
    (f"ros2 service call {ROTATE}/cancel_goal action_msgs/srv/CancelGoal",
     "ros2 service call: turtletui's actions are reached through 'ros2 action send_goal /turtle1/rotate_absolute "
     "turtlesim/action/RotateAbsolute GOAL' (Ctrl+C cancels the goal), not through their hidden services"),
    ("ros2 service type /turtle1/rotate_absolute/_action/sendgoal",
     "ros2 service type: service '/turtle1/rotate_absolute/_action/sendgoal' does not exist"),
])
def test_hidden_action_names_get_one_clear_line(cli, line, message):
    result = cli.run(line)
    assert result.error and len(result.lines) == 1
    assert result.lines[0].startswith(message)


def test_a_service_with_only_clients_is_listed_as_ros2_lists_it(sim, cli):
    node = sim.graph.add_node("caller")
    sim.graph.add_client(node, "/nobody_serves", sim.graph.services["/clear"].srv_type)
    assert "/nobody_serves" in ok(cli, "ros2 service list").lines
    assert ok(cli, "ros2 service info /nobody_serves").lines == [
        "Type: std_srvs/srv/Empty", "Clients count: 1", "Services count: 0"]
    called = cli.run("ros2 service call /nobody_serves std_srvs/srv/Empty")
    assert called.error and called.lines == ["ros2 service call: service '/nobody_serves' is not available"]


# -- ros2 interface ----------------------------------------------------------------

def test_interface_show(cli):
    lines = ok(cli, "ros2 interface show geometry_msgs/msg/Twist").lines
    assert lines == definition_text("geometry_msgs/msg/Twist").split("\n")
    assert lines[2:4] == ["Vector3  linear", "\tfloat64 x"]
    assert ok(cli, "ros2 interface show turtlesim/srv/Spawn").lines[-2:] == ["---", "string name"]


def test_interface_list_and_package(cli):
    lines = ok(cli, "ros2 interface list").lines
    assert lines[0] == "Messages:" and "Services:" in lines and "Actions:" in lines
    assert "    turtlesim/action/RotateAbsolute" in lines
    assert ok(cli, "ros2 interface package turtlesim").lines[0] == "turtlesim/action/RotateAbsolute"
    assert "turtlesim" in ok(cli, "ros2 interface packages").lines


# -- the command line ---------------------------------------------------------------

def test_leading_ros2_is_optional_and_blank_lines_print_nothing(cli):
    assert ok(cli, "topic list").lines == ok(cli, "ros2 topic list").lines
    assert cli.run("   ").lines == [] and not cli.run("").error


def test_help_is_argparse_s_as_ros2cli_builds_it(cli):
    root = ok(cli, "ros2").lines
    assert root == ok(cli, "ros2 --help").lines == ok(cli, "ros2 -h").lines
    assert root[0] == "usage: ros2 [-h] Call `ros2 <command> -h` for more detailed usage. ..."
    assert "ros2 is an extensible command-line tool for ROS 2." in root
    at = root.index("Commands:")
    assert root[at + 1:at + 8] == [
        "  action     Various action related sub-commands",
        "  bag        Various rosbag related sub-commands",
        "  interface  Show information about ROS interfaces",
        "  node       Various node related sub-commands",
        "  param      Various param related sub-commands",
        "  service    Various service related sub-commands",
        "  topic      Various topic related sub-commands",
    ]
    # a command without its verb prints the command's help, as ros2cli does
    topic = ok(cli, "ros2 topic").lines
    assert topic[0].startswith("usage: ros2 topic [-h] [--include-hidden-topics]")
    assert "  echo  Output messages from a topic" in topic
    pub = ok(cli, "ros2 topic pub -h").lines
    assert pub[0].startswith("usage: ros2 topic pub [-h] [-r N] [-p N] [-1 | -t TIMES]")
    assert any(line.strip().startswith("-r N, --rate N") for line in pub)
    assert "Publish a message to a topic" in pub


def test_help_fits_the_width_the_console_asks_for(cli):
    # (echo's and pub's QoS choices are one word each, wider than that, as in ros2)
    cli.help_width = 50
    assert max(map(len, ok(cli, "ros2 topic hz -h").lines)) <= 50
    cli.help_width = 100
    assert max(map(len, ok(cli, "ros2 topic hz -h").lines)) > 50


ERRORS = [
    ("ros2 topik list", "ros2: error: invalid choice: 'topik' (did you mean 'topic'?)"),
    ("ros2 foo", "ros2: error: invalid choice: 'foo' (choose from action, bag, interface, node, param, service, topic)"),
    ("ros2 run turtlesim turtlesim_node", "ros2: error: 'run' is not available in turtletui: turtlesim runs already,"
     " turtle_teleop_key is the arena's arrow keys (Esc first), and your own node runs with turtletui run FILE"),
    ("ros2 launch turtlesim multisim.launch.py", "ros2: error: 'launch' is not available in turtletui: turtlesim"),
    ("ros2 doctor", "ros2: error: 'doctor' is not available in turtletui (available: action, bag,"),
    ("ros2 topic lst", "ros2 topic: error: invalid choice: 'lst' (did you mean 'list'?)"),
    ("ros2 topic echo 'abc", "ros2: could not split the command line (no closing quotation)"),
    ("ros2 topic echo", "ros2 topic echo: error: the following arguments are required: topic_name"),
    ("ros2 topic echo /turtle1/pos",
     "ros2 topic echo: topic '/turtle1/pos' does not appear to be published yet (did you mean /turtle1/pose?)"),
    ("ros2 topic echo /turtle1/pose geometry_msgs/msg/Twist",
     "ros2 topic echo: topic '/turtle1/pose' has type turtlesim/msg/Pose, not geometry_msgs/msg/Twist"),
    ("ros2 topic echo /turtle1/pose --field q", "ros2 topic echo: invalid field 'q' of turtlesim/msg/Pose"),
    ("ros2 topic echo /turtle1/pose --field .", "ros2 topic echo: Invalid field value '.'"),
    ("ros2 topic echo /turtle1/pose --ones", "ros2: error: unrecognized arguments: --ones"),
    ("ros2 topic hz /turtle1/poze", "ros2 topic hz: topic '/turtle1/poze' does not appear to be published yet"),
    ("ros2 topic hz /turtle1/pose -w x",
     "ros2 topic hz: error: argument --window/-w: value must be a positive integer"),
    ("ros2 topic info /nope", "ros2 topic info: topic '/nope' does not exist"),
    ("ros2 topic list extra", "ros2: error: unrecognized arguments: extra"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist 'linear: {x: 2.0'",
     "ros2 topic pub: could not parse message 'linear: {x: 2.0' as YAML (unbalanced braces)"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: [x: 2.0}'",
     "ros2 topic pub: could not parse message '{linear: [x: 2.0}' as YAML (unbalanced brackets)"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist \"{linear: {x: 'a}}\"",
     "ros2 topic pub: could not parse message '{linear: {x: 'a}}' as YAML (found unexpected end of stream"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: fast}}'",
     "Failed to populate field: geometry_msgs/msg/Twist: field 'linear.x' must be a float, got str 'fast'"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '{linar: {x: 1}}'",
     "Failed to populate field: geometry_msgs/msg/Twist: unknown field 'linar'"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '[1, 2]'",
     "ros2 topic pub: the message must be a YAML dictionary"),
    ("ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twst '{}'",
     "ros2 topic pub: unknown interface type 'geometry_msgs/msg/Twst'; did you mean geometry_msgs/msg/Twist"),
    ("ros2 topic pub /turtle1/cmd_vel turtlesim/srv/Spawn '{}'",
     "ros2 topic pub: 'turtlesim/srv/Spawn' is a service type, not a message type"),
    ("ros2 topic pub /turtle1/cmd_vel turtlesim/msg/Pose '{}'",
     "ros2 topic pub: topic '/turtle1/cmd_vel' has type geometry_msgs/msg/Twist, not turtlesim/msg/Pose"),
    ("ros2 topic pub -r 0 /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'",
     "ros2 topic pub: error: argument -r/--rate: Value must be positive"),
    ("ros2 topic pub -r nan /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'",
     "ros2 topic pub: error: argument -r/--rate: Value must be positive"),
    ("ros2 topic pub -r fast /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'",
     "ros2 topic pub: error: argument -r/--rate: Expects a floating point number"),
    ("ros2 topic pub --once -t 3 /turtle1/cmd_vel geometry_msgs/msg/Twist",
     "ros2 topic pub: error: argument -t/--times: not allowed with argument -1/--once"),
    ("ros2 topic pub /turtle1/cmd_vel",
     "ros2 topic pub: error: the following arguments are required: message_type"),
    ("ros2 topic pub /t std_msgs/msg/String data: hello",
     "ros2: error: unrecognized arguments: hello (quote YAML values: \"{x: 1.0}\")"),
    ("ros2 service call /spwn turtlesim/srv/Spawn '{}'",
     "ros2 service call: service '/spwn' is not available (did you mean /spawn?)"),
    ("ros2 service call /spawn turtlesim/srv/Kill '{}'",
     "ros2 service call: service '/spawn' has type turtlesim/srv/Spawn, not turtlesim/srv/Kill"),
    ("ros2 service call /spawn turtlesim/srv/Spawn '{name: [1}'",
     "ros2 service call: could not parse request '{name: [1}' as YAML (unbalanced brackets)"),
    ("ros2 service call /clear",
     "ros2 service call: error: the following arguments are required: service_type"),
    ("ros2 service type /spwan", "ros2 service type: service '/spwan' does not exist (did you mean /spawn?)"),
    ("ros2 param get /turtlsim background_r", "ros2 param get: node '/turtlsim' not found (did you mean /turtlesim?)"),
    ("ros2 param get /turtlesim background", "Parameter not set. (did you mean background_"),
    ("ros2 param set /turtlesim background_r 300",
     "Setting parameter failed: parameter 'background_r' must be an integer in 0..255, got 300"),
    ("ros2 param set /turtlesim background_r",
     "ros2 param set: error: the following arguments are required: value"),
    ("ros2 param set /turtlesim speed 1", "Setting parameter failed: parameter 'speed' is not declared by /turtlesim"),
    ("ros2 action send_goal /turtle1/rotate turtlesim/action/RotateAbsolute '{theta: 1}'",
     "ros2 action send_goal: action '/turtle1/rotate' is not available (did you mean /turtle1/rotate_absolute?)"),
    ("ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute '{heading: 1}'",
     "Failed to populate field: turtlesim/action/RotateAbsolute_Goal: unknown field 'heading'"),
    ("ros2 action send_goal /turtle1/rotate_absolute",
     "ros2 action send_goal: error: the following arguments are required: action_type"),
    ("ros2 action info /nope", "ros2 action info: action '/nope' does not exist"),
    ("ros2 interface show geometry_msgs/msg/Twst",
     "ros2 interface show: unknown interface type 'geometry_msgs/msg/Twst'; did you mean geometry_msgs/msg/Twist"),
    ("ros2 interface show foo/Bar",
     "ros2 interface show: unknown interface type 'foo/Bar' (see 'ros2 interface list' for the"),
    ("ros2 interface package turtlesimm",
     "ros2 interface package: unknown package 'turtlesimm' (did you mean turtlesim?)"),
    ("ros2 node info /turtlesm", "ros2 node info: node '/turtlesm' not found (did you mean /turtlesim?)"),
    ("ros2 param dump /turtlesim > turtlesim.yaml",
     "ros2: shell operators such as '>' are not supported here"),
]


@pytest.mark.parametrize(("line", "expected"), ERRORS, ids=[line for line, _ in ERRORS])
def test_errors_are_one_clear_line(sim, cli, line, expected):
    result = cli.run(line)
    assert result.error and result.stream is None
    assert len(result.lines) == 1 and "\n" not in result.lines[0]
    assert result.lines[0].startswith(expected), result.lines[0]
    assert "Traceback" not in result.lines[0]
    assert hidden_nodes(sim) == [] and cli.streams == []


@pytest.mark.parametrize("line", [
    "ros2 topic pub", "ros2 topic pub --rate", "ros2 topic pub -r -1", "ros2 topic pub a b c d e",
    "ros2 param set / / /", "ros2 topic echo /", "ros2 service call", "ros2 service call /spawn '{{{'",
    "ros2 action send_goal / / /", "ros2 topic pub /x '' ''", "ros2 interface show ''",
    "ros2 topic echo /turtle1/pose --field x.y", "ros2 node info ''", "ros2 param get '' ''",
    "ros2 topic pub /t std_msgs/msg/String '{data: \"\\q\"}'", "ros2 -- --", "ros2 topic --once",
    "ros2 topic pub /t std_msgs/msg/String '!!python/object:os.system echo'",
    "ros2 topic pub /t std_msgs/msg/String '{data: *a}'", "ros2 param set /turtlesim holonomic '['",
    "ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: 1e999}}'",
    "ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: .nan}}'",
])
def test_no_command_raises(cli, line):
    result = cli.run(line)
    assert isinstance(result, CommandResult)
    assert all(isinstance(text, str) for text in result.lines)
    assert not any("internal error" in text for text in result.lines), result.lines
    if result.error:
        assert len(result.lines) == 1
    if result.stream is not None:
        result.stream.close()


def test_close_all_removes_every_hidden_node(sim, cli):
    ok(cli, "ros2 topic echo /turtle1/pose")
    ok(cli, "ros2 topic hz /turtle1/pose")
    ok(cli, "ros2 topic pub /turtle1/cmd_vel geometry_msgs/msg/Twist '{}'")
    assert len(cli.streams) == 3 and len(hidden_nodes(sim)) == 3
    cli.close_all()
    assert cli.streams == [] and hidden_nodes(sim) == []
    assert ok(cli, "ros2 topic info /turtle1/pose").lines[2] == "Subscription count: 0"
    step(sim, 1.5)  # nothing of theirs is left to run


# -- the YAML of arguments and of echo -------------------------------------------------

@pytest.mark.parametrize(("text", "value"), [
    ("{linear: {x: 2.0, y: 0.0, z: 0.0}, angular: {x: 0.0, y: 0.0, z: 1.8}}",
     {"linear": {"x": 2.0, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 1.8}}),
    ("{x: 1, y: 1, theta: 0, name: ''}", {"x": 1, "y": 1, "theta": 0, "name": ""}),
    ("linear: {x: 2.0}", {"linear": {"x": 2.0}}),
    ("{}", {}),
    ("", None),
    ("150", 150),
    ("-3", -3),
    ("1.5e+3", 1500.0),
    ("1.5e3", "1.5e3"),  # YAML 1.1 wants the exponent's sign
    ("{x: 1, x: 2}", {"x": 2}),  # the last of a repeated key wins
    ("0x1F", 31),
    ("true", True),
    ("on", True),
    ("~", None),
    ("hello world", "hello world"),
    ("'quoted: string'", "quoted: string"),
    ("'it''s'", "it's"),
    ("[1, 2.5, abc, [], {}]", [1, 2.5, "abc", [], {}]),
    ("{name: turtle 2}  # a comment", {"name": "turtle 2"}),
    ("{a: .inf, b: -.inf}", {"a": math.inf, "b": -math.inf}),
    # YAML 1.1 as PyYAML's safe_load reads it, which ros2 uses
    ("017", 15),
    ("0o17", "0o17"),
    ("1e3", "1e3"),
    ("!!float 1", 1.0),
    ("{off: 1, 'on': 2}", {False: 1, "on": 2}),
    ("x: 1\ny: -2.5", {"x": 1, "y": -2.5}),
])
def test_parse_yaml_is_pyyaml_safe_load(text, value):
    assert parse_yaml(text) == value


@pytest.mark.parametrize(("text", "reason"), [
    ("{a: 1", "unbalanced braces"),
    ("{a: 1}}", "unbalanced braces"),
    ("a: {b: 1", "unbalanced braces"),
    ("[1, 2", "unbalanced brackets"),
    ("{a: [1}", "unbalanced brackets"),
    ("{a: 'x}", "found unexpected end of stream"),
    ("{a: \"\\q\"}", "found unknown escape character 'q'"),
    ("{a: !!python/object:os.system x}", "could not determine a constructor"),
])
def test_parse_yaml_errors_are_one_line(text, reason):
    with pytest.raises(YamlError, match=re.escape(reason)) as caught:
        parse_yaml(text)
    assert "\n" not in str(caught.value)


def test_yaml_lines_as_pyyaml_dumps_them():
    assert yaml_lines({
        "a": 1.0, "b": 1e17, "c": True, "d": "", "e": "plain", "f": "yes", "g": "12",
        "h": "a: b", "i": [1, 2], "j": [], "k": {}, "l": [{"x": 1, "y": 2}],
        "m": {"n": {"o": 0.1}}, "p": "it's", "q": math.nan, "r": -math.inf,
    }) == [
        "a: 1.0", "b: 1.0e+17", "c: true", "d: ''", "e: plain", "f: 'yes'", "g: '12'",
        "h: 'a: b'", "i:", "- 1", "- 2", "j: []", "k: {}", "l:", "- x: 1", "  y: 2",
        "m:", "  n:", "    o: 0.1", "p: it's", "q: .nan", "r: -.inf",
    ]
    assert yaml_lines({}) == ["{}"]
    assert yaml_lines(5.5) == ["5.5"]
    assert yaml_lines([[1, 2], [3]]) == ["- - 1", "  - 2", "- - 3"]


# -- hygiene ---------------------------------------------------------------------------

def test_the_interpreter_imports_no_front_end():
    code = ("import sys, turtletui.ros2cli; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('textual', 'typer')"
            " or m.startswith(('turtletui.tui', 'turtletui.cli'))))")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(PACKAGE_ROOT), env.get("PYTHONPATH")) if p)
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          timeout=60, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def test_topic_echo_and_hz_hear_a_best_effort_scan_as_ros2cli_adapts_its_qos():
    from turtletui.sim import Lidar, World

    sim = Simulation(world=World(lidar=Lidar(samples=4, range_max=20.0)))
    logs: list = []
    sim.graph.log_sinks.append(logs.append)
    cli = Ros2Cli(sim)
    echo = ok(cli, "ros2 topic echo /turtle1/scan --field range_max")
    hz = ok(cli, "ros2 topic hz /turtle1/scan")
    step(sim, 1.2)
    assert echo.stream.poll()[:2] == ["20.0", "---"]
    assert any(line.startswith("average rate: 62.") for line in hz.stream.poll())
    assert not [r.msg for r in logs if "incompatible QoS" in r.msg]


def test_echo_and_pub_take_ros2clis_qos_options(sim, cli):
    from turtletui.sim import Lidar, World

    sim = Simulation(world=World(lidar=Lidar(samples=4, range_max=20.0)))
    cli = Ros2Cli(sim)
    # asking for reliable delivery of a best-effort scan hears nothing, as in ROS 2
    deaf = ok(cli, "ros2 topic echo /turtle1/scan --qos-reliability reliable --field range_max")
    hears = ok(cli, "ros2 topic echo /turtle1/scan --qos-profile sensor_data --field range_max")
    # a best-effort publisher never matches turtlesim's reliable cmd_vel subscription
    pub = ok(cli, "ros2 topic pub --once --qos-reliability best_effort /turtle1/cmd_vel "
                  "geometry_msgs/msg/Twist '{linear: {x: 2.0}}'")
    step(sim, 1.2)
    assert deaf.stream.poll() == []
    assert hears.stream.poll()[:2] == ["20.0", "---"]
    assert pub.lines[-1:] == WAITING and pub.stream.count == 0
    assert sim.world.turtles["turtle1"].x == pytest.approx(5.544445)
    assert "invalid choice: 'fast'" in cli.run("ros2 topic echo /turtle1/scan --qos-reliability fast").lines[-1]
