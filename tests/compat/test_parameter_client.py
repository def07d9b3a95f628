"""rclpy.parameter_client.AsyncParameterClient under both hosts: against turtlesim's
parameters (rclcpp's services) and a student node's (rclpy's), and between two
sandboxed controllers. tests/fidelity/programs/parameter_client.py checks the
rclpy side against the real rclpy."""

from __future__ import annotations

import textwrap
from pathlib import Path

from support.hosts import node_logs

from turtletui.api import run

TURTLESIM_TUNER = """
import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient


def main():
    rclpy.init()
    node = Node("tuner")
    client = AsyncParameterClient(node, "/turtlesim")
    log = node.get_logger().info
    log(f"ready {client.wait_for_services(timeout_sec=2.0)}")

    def answer(future):
        rclpy.spin_until_future_complete(node, future)
        return future.result()

    log(f"list {list(answer(client.list_parameters()).result.names)}")
    values = answer(client.get_parameters(["background_r", "holonomic"])).values
    log(f"get {[(v.type, v.integer_value, v.bool_value) for v in values]}")
    log(f"unknown {list(answer(client.get_parameters(['background_r', 'nope'])).values)}")
    results = answer(client.set_parameters([
        Parameter("background_r", value=10), Parameter("background_g", value=300),
        Parameter("background_b", value="blue"), Parameter("nope", value=1)])).results
    for result in results:
        log(f"set {result.successful} {result.reason}")
    [green] = answer(client.describe_parameters(["background_g"])).descriptors
    log(f"describe {green.description} {green.integer_range[0].to_value}")
    log(f"types {list(answer(client.get_parameter_types(['holonomic', 'background_r'])).types)}")
    atomic = answer(client.set_parameters_atomically(
        [Parameter("background_b", value=0), Parameter("holonomic", value=1)])).result
    log(f"atomic {atomic.successful} {atomic.reason}")
    log(f"after {[v.integer_value for v in answer(client.get_parameters(['background_r', 'background_b'])).values]}")
"""


def test_a_parameter_client_reads_and_sets_turtlesims_parameters(controller_host):
    result = controller_host.run(TURTLESIM_TUNER, duration=3.0)
    assert result.ok, result.crashes
    assert node_logs(result, "tuner") == [
        "ready True",
        "list ['background_b', 'background_g', 'background_r', 'holonomic', "  # and rclcpp's own
        "'qos_overrides./parameter_events.publisher.depth', 'qos_overrides./parameter_events.publisher.durability', "
        "'qos_overrides./parameter_events.publisher.history', "
        "'qos_overrides./parameter_events.publisher.reliability', 'start_type_description_service', "
        "'use_sim_time']",
        "get [(2, 69, False), (1, 0, False)]",
        "unknown []",
        "set True ",
        "set False Parameter {background_g} doesn't comply with integer range.",
        "set False Wrong parameter type, parameter {background_b} is of type {integer}, "
        "setting it to {string} is not allowed.",
        "set False parameter 'nope' cannot be set because it was not declared",
        "describe Green channel of the background color 255",
        "types [1, 2]",
        "atomic False Wrong parameter type, parameter {holonomic} is of type {bool}, "
        "setting it to {integer} is not allowed.",
        "after [10, 255]",  # the refused atomic set changed nothing
    ]


DRIVER_FILE = """
import rclpy
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.declare_parameter("speed", 1.0, ParameterDescriptor(
            floating_point_range=[FloatingPointRange(from_value=0.0, to_value=2.0)]))
        self.create_timer(0.5, self.report)

    def report(self):
        self.get_logger().info(f"speed {self.get_parameter('speed').value}")


def main():
    rclpy.init()
    rclpy.spin(Driver())
"""

TUNER_FILE = """
import time

import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient


def main():
    rclpy.init()
    node = Node("tuner")
    client = AsyncParameterClient(node, "driver")
    log = node.get_logger().info
    log(f"ready {client.wait_for_services(timeout_sec=5.0)}")
    time.sleep(0.6)
    for speed in (1.5, 2.5):
        future = client.set_parameters([Parameter("speed", value=speed)])
        rclpy.spin_until_future_complete(node, future)
        [result] = future.result().results
        log(f"{speed}: {result.successful} {result.reason}")
"""


def test_a_sandboxed_parameter_client_tunes_a_node_in_another_controller(tmp_path: Path):
    driver = tmp_path / "driver.py"
    tuner = tmp_path / "tuner.py"
    driver.write_text(textwrap.dedent(DRIVER_FILE).lstrip())
    tuner.write_text(textwrap.dedent(TUNER_FILE).lstrip())
    result = run([driver, tuner], duration=1.6, sandbox=True)
    assert result.ok, result.crashes
    assert node_logs(result, "tuner") == [
        "ready True",
        "1.5: True ",
        "2.5: False Parameter speed out of range Min: 0.0, Max: 2.0, value: 2.5",
    ]
    assert node_logs(result, "driver") == ["speed 1.0", "speed 1.5", "speed 1.5"]
    again = run([driver, tuner], duration=1.6, sandbox=True)
    assert [(r.t, r.node, r.msg) for r in again.logs] == [(r.t, r.node, r.msg) for r in result.logs]


def test_a_client_waits_in_vain_for_a_node_that_does_not_exist(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from rclpy.parameter_client import AsyncParameterClient


def main():
    rclpy.init()
    node = Node("tuner", start_parameter_services=False)
    start = node.get_clock().now()
    ready = AsyncParameterClient(node, "ghost").wait_for_services(timeout_sec=1.0)
    waited = (node.get_clock().now() - start).nanoseconds / 1e9
    services = [name for name, _ in node.get_service_names_and_types() if name.startswith("/tuner/") and "param" in name]
    node.get_logger().info(f"{ready} after {waited} s; own parameter services {services}")
""",
        duration=2.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "tuner") == ["False after 1.0 s; own parameter services []"]
