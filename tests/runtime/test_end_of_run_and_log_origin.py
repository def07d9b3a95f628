"""Both hosts end a run alike: what is due at the last instant runs (a timer's
callback, a sleep that ends then, the code after it) until the controller waits
for a later moment; and each log line says whether a callback logged it."""

from __future__ import annotations

from pathlib import Path

import pytest

from turtletui.api import run
from turtletui.runtime.loader import ControllerSpec

LOOPS = {
    "sleep": """
import time
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("looper")
    n = 0
    while rclpy.ok():
        node.get_logger().info(f"line {n}")
        n += 1
        time.sleep(1.0)
""",
    "spin_once": """
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("looper")
    n = 0
    while rclpy.ok():
        rclpy.spin_once(node, timeout_sec=1.0)
        node.get_logger().info(f"line {n}")
        n += 1
""",
    "timer": """
import rclpy
from rclpy.node import Node


class Looper(Node):
    def __init__(self):
        super().__init__("looper")
        self.get_logger().info("started")
        self.n = 0
        self.create_timer(1.0, self.tick)

    def tick(self):
        self.get_logger().info(f"line {self.n}")
        self.n += 1


def main():
    rclpy.init()
    rclpy.spin(Looper())
""",
}


def lines(path: Path, *, trusted: bool) -> list[tuple[float, str, bool]]:
    result = run([ControllerSpec("looper", path, trusted=trusted)], duration=3.0)
    assert result.ok, result.crashes
    return [(r.t, r.msg, r.in_callback) for r in result.logs if r.node == "looper"]


@pytest.mark.parametrize("kind", sorted(LOOPS))
def test_a_run_ends_alike_in_both_hosts_and_says_where_each_line_came_from(tmp_path: Path, kind: str) -> None:
    path = tmp_path / f"{kind}.py"
    path.write_text(LOOPS[kind])
    in_process = lines(path, trusted=True)
    assert lines(path, trusted=False) == in_process
    expected = {
        # the sleep that ends at t=3 s returns, its line is logged, the next sleep ends the run
        "sleep": [(0.0, "line 0", False), (1.0, "line 1", False), (2.0, "line 2", False), (3.0, "line 3", False)],
        # the last spin_once waits past the end: it returns at once and the loop logs once more
        "spin_once": [(1.0, "line 0", False), (2.0, "line 1", False), (3.0, "line 2", False), (3.0, "line 3", False)],
        "timer": [(0.0, "started", False), (1.0, "line 0", True), (2.0, "line 1", True), (3.0, "line 2", True)],
    }[kind]
    assert in_process == expected
