"""The simulator's own nodes besides turtlesim (a scenario's ``teleop_turtle``,
rosbag2's ``rosbag2_player`` and ``rosbag2_recorder``) have what their real
counterparts have, as a controller sees it in both hosts: every rclcpp node's
/rosout and /parameter_events publishers, its /parameter_events subscription,
the parameter services and ``~/get_type_description``, rclcpp's parameters
(``use_sim_time``, ``start_type_description_service``, the read-only
``qos_overrides./parameter_events.publisher.*``), and their own
(turtle_teleop_key's ``scale_angular`` and ``scale_linear``, which its keys
follow)."""

from __future__ import annotations

from pathlib import Path

from support.hosts import node_logs

from turtletui.graph.core import NS_PER_S
from turtletui.recording.bag import BagPlayback, BagRecording
from turtletui.runtime.replica import ReplicableSetup, Step
from turtletui.runtime.simulation import Simulation

DRIVE = ReplicableSetup(steps=[Step("turtletui.grading.scenario_steps:ScenarioDriver", ((1.0, 0.0),))])

PROBE = """
import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient

TARGET = {target!r}


def main():
    rclpy.init()
    node = Node("probe")
    log = node.get_logger().info
    client = AsyncParameterClient(node, TARGET)

    def wait(future):
        rclpy.spin_until_future_complete(node, future, timeout_sec=2.0)
        return future.result()

    for _ in range(6):  # discovery
        rclpy.spin_once(node, timeout_sec=0.05)
    log(f"nodes {{sorted(node.get_node_names_and_namespaces())}}")
    log(f"publishers {{node.get_publisher_names_and_types_by_node(TARGET, '/')}}")
    log(f"subscriptions {{node.get_subscriber_names_and_types_by_node(TARGET, '/')}}")
    log(f"services {{node.get_service_names_and_types_by_node(TARGET, '/')}}")
    log(f"clients {{node.get_client_names_and_types_by_node(TARGET, '/')}}")
    log(f"ready {{client.wait_for_services(1.0)}}")
    names = list(wait(client.list_parameters()).result.names)
    log(f"parameters {{names}}")
    values = wait(client.get_parameters(names)).values
    log("values " + ", ".join(f"{{n}}={{v.type}}" for n, v in zip(names, values)))
    depth = "qos_overrides./parameter_events.publisher.depth"
    [descriptor] = wait(client.describe_parameters([depth])).descriptors
    log(f"descriptor {{descriptor.description!r}} read_only={{descriptor.read_only}} type={{descriptor.type}}")
    for name, value in (("use_sim_time", True), (depth, 10), ("use_sim_time", False)) + {own!r}:
        [result] = wait(client.set_parameters([Parameter(name, value=value)])).results
        log(f"set {{name}}={{value!r}}: {{result.successful}} {{result.reason!r}}")
"""

RCLCPP_PARAMETERS = {  # what rclcpp::Node declares, and their ParameterType
    "qos_overrides./parameter_events.publisher.depth": 2,
    "qos_overrides./parameter_events.publisher.durability": 4,
    "qos_overrides./parameter_events.publisher.history": 4,
    "qos_overrides./parameter_events.publisher.reliability": 4,
    "start_type_description_service": 1,
    "use_sim_time": 1,
}


def values_line(parameters: dict[str, int]) -> str:
    return "values " + ", ".join(f"{name}={kind}" for name, kind in sorted(parameters.items()))


def rclcpp_services(node: str) -> list:
    parameters = ("describe_parameters", "get_parameter_types", "get_parameters", "get_type_description",
                  "list_parameters", "set_parameters", "set_parameters_atomically")
    types = ("rcl_interfaces/srv/DescribeParameters", "rcl_interfaces/srv/GetParameterTypes",
             "rcl_interfaces/srv/GetParameters", "type_description_interfaces/srv/GetTypeDescription",
             "rcl_interfaces/srv/ListParameters", "rcl_interfaces/srv/SetParameters",
             "rcl_interfaces/srv/SetParametersAtomically")
    return [(f"/{node}/{name}", [kind]) for name, kind in zip(parameters, types, strict=True)]


EVENTS = ("/parameter_events", ["rcl_interfaces/msg/ParameterEvent"])
ACTION = "/turtle1/rotate_absolute/_action/"
ROTATE_CLIENT_TOPICS = [(f"{ACTION}feedback", ["turtlesim/action/RotateAbsolute_FeedbackMessage"]),
                        (f"{ACTION}status", ["action_msgs/msg/GoalStatusArray"])]
ROTATE_CLIENT_SERVICES = [(f"{ACTION}cancel_goal", ["action_msgs/srv/CancelGoal"]),
                          (f"{ACTION}get_result", ["turtlesim/action/RotateAbsolute_GetResult"]),
                          (f"{ACTION}send_goal", ["turtlesim/action/RotateAbsolute_SendGoal"])]
"""What rcl_action gives turtle_teleop_key's rotate_absolute client."""
ROSOUT = ("/rosout", ["rcl_interfaces/msg/Log"])
COMMON_SETS = [
    "set use_sim_time=True: False {refusal!r}",
    "set qos_overrides./parameter_events.publisher.depth=10: False \"parameter "
    "'qos_overrides./parameter_events.publisher.depth' cannot be set because it is read-only\"",
    "set use_sim_time=False: True ''",
]
"""What the probe's sets of rclcpp's parameters answer (an rclcpp node would take use_sim_time true)."""


def common_sets(node: str) -> list[str]:
    refusal = f"{node} keeps the simulation's clock: use_sim_time can only be false here"
    return [line.format(refusal=refusal) for line in COMMON_SETS]


DESCRIPTOR = "descriptor 'qos policy {depth} for publisher {/parameter_events}' read_only=True type=2"


def probe(controller_host, target: str, setup, own: tuple = ()) -> list[str]:
    result = controller_host.run(PROBE.format(target=target, own=own), duration=1.0, setup=setup)
    assert result.ok, result.crashes
    return node_logs(result, "probe")


def test_a_scenario_s_teleop_turtle_is_turtle_teleop_key_s_node(controller_host):
    lines = probe(controller_host, "teleop_turtle", DRIVE,
                  (("scale_linear", 4.0), ("scale_linear", 3), ("scale_angular", 1.5)))
    assert lines == [
        "nodes [('probe', '/'), ('teleop_turtle', '/'), ('turtlesim', '/')]",
        f"publishers {[EVENTS, ROSOUT, ('/turtle1/cmd_vel', ['geometry_msgs/msg/Twist'])]}",
        f"subscriptions {[EVENTS, *ROTATE_CLIENT_TOPICS]}",
        f"services {rclcpp_services('teleop_turtle')}",
        f"clients {ROTATE_CLIENT_SERVICES}",
        "ready True",
        f"parameters {sorted(['scale_angular', 'scale_linear', *RCLCPP_PARAMETERS])}",
        values_line({**RCLCPP_PARAMETERS, "scale_angular": 3, "scale_linear": 3}),
        DESCRIPTOR,
        *common_sets("/teleop_turtle"),
        "set scale_linear=4.0: True ''",
        "set scale_linear=3: False 'Wrong parameter type, parameter {scale_linear} is of type {double}, "
        "setting it to {integer} is not allowed.'",
        "set scale_angular=1.5: True ''",
    ]


def _bag(folder: Path) -> Path:
    sim = Simulation()
    recording = BagRecording(sim, ["/turtle1/pose"], folder / "poses")
    sim.run_until(NS_PER_S)
    recording.stop()
    return folder / "poses"


def test_rosbag2_s_player_and_recorder_are_rclcpp_nodes(controller_host, tmp_path):
    bag = _bag(tmp_path)
    for node, setup, topics in (
        ("rosbag2_player", lambda sim: BagPlayback(sim, bag, loop=True), [EVENTS, ROSOUT, (
            "/turtle1/pose", ["turtlesim/msg/Pose"])]),
        ("rosbag2_recorder", lambda sim: BagRecording(sim, ["/turtle1/pose"], tmp_path / "again"), [EVENTS, ROSOUT]),
    ):
        lines = probe(controller_host, node, setup)
        assert lines[1:] == [
            f"publishers {topics}",
            f"subscriptions {[EVENTS, ('/turtle1/pose', ['turtlesim/msg/Pose'])] if node.endswith('recorder') else [EVENTS]}",
            f"services {rclcpp_services(node)}",
            "clients []",
            "ready True",
            f"parameters {list(RCLCPP_PARAMETERS)}",
            values_line(RCLCPP_PARAMETERS),
            DESCRIPTOR,
            *common_sets(f"/{node}"),
        ], node
        assert f"('{node}', '/')" in lines[0]


def test_the_arrow_keys_follow_teleop_turtle_s_scales():
    from turtletui.tui.session import Teleop

    sim = Simulation()
    teleop = Teleop(sim)
    sent = []
    sim.graph.add_subscription(sim.graph.add_node("watcher"), "/turtle1/cmd_vel", type(teleop.ros.key_twist(0, 0)),
                               10, sent.append)
    assert teleop.node.parameter_setter("scale_linear", 0.5) is None
    sim.run_until(NS_PER_S // 10)  # discovered
    teleop.drive(linear=1.0)
    teleop.drive(angular=-1.0)
    sim.run_until(NS_PER_S // 5)
    assert [(m.linear.x, m.angular.z) for m in sent] == [(0.5, 0.0), (0.0, -2.0)]
    assert teleop.node.parameter_setter("scale_linear", "fast") is not None
