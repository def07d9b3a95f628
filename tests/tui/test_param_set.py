"""ros2 param set on the controllers the app runs (sandboxed): the node's own
rules apply, as with the real ros2 CLI."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from turtletui.ros2cli import Ros2Cli
from turtletui.runtime.loader import ControllerSpec
from turtletui.tui.session import LiveSession

NODE = """\
import rclpy
from rclpy.node import Node
from rcl_interfaces.msg import SetParametersResult


class Tuned(Node):
    def __init__(self):
        super().__init__("tuned")
        self.declare_parameter("speed", 1.0)
        self.declare_parameter("mode", "calm")
        self.add_on_set_parameters_callback(self.check)
        self.create_timer(0.05, self.report)

    def check(self, params):
        for p in params:
            if p.name == "speed" and p.value > 5.0:
                return SetParametersResult(successful=False, reason="speed above 5.0 m/s")
        return SetParametersResult(successful=True)

    def report(self):
        self.get_logger().info(f"speed {self.get_parameter('speed').value}", throttle_duration_sec=0.2)


def main():
    rclpy.init()
    rclpy.spin(Tuned())
"""


def run_for(session: LiveSession, seconds: float) -> None:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        session.advance(time.monotonic())
        time.sleep(0.01)


@pytest.fixture
def session(tmp_path: Path):
    path = tmp_path / "tuned.py"
    path.write_text(NODE)
    live = LiveSession([ControllerSpec(name="tuned", path=path)])
    run_for(live, 0.3)
    yield live
    live.close()


def test_param_set_reaches_the_node_and_its_rules_hold(session: LiveSession):
    cli = Ros2Cli(session.sim)
    assert cli.run("ros2 param get /tuned speed").lines == ["Double value is: 1.0"]
    assert cli.run("ros2 param set /tuned speed 2.5").lines == ["Set parameter successful"]
    run_for(session, 0.4)
    assert cli.run("ros2 param get /tuned speed").lines == ["Double value is: 2.5"]
    assert any(r.node == "tuned" and r.msg == "speed 2.5" for r in session.logs)

    # the type is the node's: an integer for a double is refused, as ROS does
    wrong = cli.run("ros2 param set /tuned speed 3")
    assert wrong.error and "expecting type 'DOUBLE'" in wrong.lines[0]
    assert cli.run("ros2 param set /tuned mode busy").lines == ["Set parameter successful"]
    run_for(session, 0.2)
    assert cli.run("ros2 param get /tuned mode").lines == ["String value is: busy"]


def test_the_nodes_own_callback_can_refuse(session: LiveSession):
    cli = Ros2Cli(session.sim)
    result = cli.run("ros2 param set /tuned speed 9.0")
    run_for(session, 0.3)
    assert cli.run("ros2 param get /tuned speed").lines == ["Double value is: 1.0"]
    # the node answers a step later: its log says why it refused
    assert result.lines == ["Set parameter successful"]
    refusals = [r.msg for r in session.logs if r.node == "tuned" and "speed above 5.0 m/s" in r.msg]
    assert refusals == ["Setting parameter speed failed: speed above 5.0 m/s"]
