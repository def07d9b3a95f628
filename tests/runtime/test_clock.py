"""In lockstep a controller's wall clocks read simulated time from the run's
epoch (1700000000 s), in both hosts: a loop timed with ``time.time()`` runs
for as long as it would on a robot. In real time they are the machine's."""

from __future__ import annotations

import sys
import textwrap
import time
from pathlib import Path

import pytest

from turtletui.api import RunResult, run
from turtletui.runtime.sandbox import Limits

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="the sandbox needs POSIX processes")

HOSTS = {"sandboxed": True, "in-process": False}

CLOCKS = """
import datetime, time
from datetime import datetime as DateTime
import rclpy
from rclpy.node import Node


class Clocks(Node):
    def __init__(self):
        super().__init__("clocks")
        self.create_timer(0.25, self.tick)
        self.ticks = 0

    def tick(self):
        self.ticks += 1
        if self.ticks != 2:
            return
        readings = {
            "time": time.time(),
            "time_ns": time.time_ns() / 1e9,
            "monotonic": time.monotonic(),
            "monotonic_ns": time.monotonic_ns() / 1e9,
            "perf_counter": time.perf_counter(),
            "perf_counter_ns": time.perf_counter_ns() / 1e9,
            "datetime.now": datetime.datetime.now().timestamp(),
            "DateTime.now": DateTime.now(datetime.timezone.utc).timestamp(),
            "utcnow": DateTime.utcnow().replace(tzinfo=datetime.timezone.utc).timestamp(),
            "localtime": time.mktime(time.localtime()),
            "gmtime": time.mktime(time.gmtime()) - time.mktime(time.gmtime(0)),
            "ros": self.get_clock().now().nanoseconds / 1e9,
        }
        for name, value in readings.items():
            self.get_logger().info(f"{name} {value:.6f}")
        self.get_logger().info(f"type {isinstance(DateTime.now(), datetime.datetime)} {datetime.datetime.now()!r}")


def main():
    rclpy.init()
    rclpy.spin(Clocks())
"""

DRIVE_FOR_TWO_SECONDS = """
import time
import rclpy
from geometry_msgs.msg import Twist

rclpy.init()
node = rclpy.create_node("beginner")
pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
start = time.time()
while time.time() - start < 2.0:
    msg = Twist()
    msg.linear.x = 1.0
    pub.publish(msg)
    PAUSE
pub.publish(Twist())
node.get_logger().info(f"drove for {time.time() - start:.2f} s")
"""


def write(folder: Path, text: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "node.py"
    path.write_text(textwrap.dedent(text))
    return path


def readings(result: RunResult) -> dict[str, float]:
    values = {}
    for record in result.logs:
        if record.node == "clocks" and not record.msg.startswith("type "):
            name, value = record.msg.split()
            values[name] = float(value)
    return values


@pytest.mark.parametrize("host", sorted(HOSTS))
def test_every_wall_clock_reads_simulated_time_in_lockstep(tmp_path: Path, host: str) -> None:
    result = run([write(tmp_path, CLOCKS)], duration=1.0, sandbox=HOSTS[host])
    assert result.crashes == []
    values = readings(result)
    assert set(values) >= {"time", "monotonic", "perf_counter", "datetime.now", "utcnow", "localtime"}
    for name, value in values.items():
        # the second tick of a 0.25 s timer; localtime has whole seconds
        assert value == pytest.approx(1_700_000_000.5, abs=0.6 if name in ("localtime", "gmtime") else 1e-6), name
    [kind] = [r.msg for r in result.logs if r.msg.startswith("type ")]
    assert kind.startswith("type True datetime.datetime(2023, 11, 1")


def test_the_clocks_are_the_machine_s_in_real_time(tmp_path: Path) -> None:
    before = time.time()
    result = run([write(tmp_path, CLOCKS)], duration=0.8, realtime=True)
    after = time.time()
    values = readings(result)
    assert before <= values["time"] <= after
    assert before <= values["datetime.now"] <= after


@pytest.mark.parametrize("host", sorted(HOSTS))
@pytest.mark.parametrize("pause", ["time.sleep(0.1)", "rclpy.spin_once(node, timeout_sec=0.05)", "pass"])
def test_a_loop_timed_with_time_time_drives_for_its_simulated_seconds(tmp_path: Path, host: str, pause: str) -> None:
    """A beginner's "drive for 2 s": 2 m at 1 m/s, as on a robot (it drove
    until the run ended when only time.sleep was simulated). Without any
    pause the loop reads the clock again and again: every 100 readings at one
    instant let 1 ms pass, as each turn of a loop takes time on a robot."""
    result = run([write(tmp_path, DRIVE_FOR_TWO_SECONDS.replace("PAUSE", pause))], duration=4.0, sandbox=HOSTS[host])
    assert result.crashes == []
    assert result.turtles["turtle1"].distance == pytest.approx(2.0, abs=0.1)
    [line] = [r for r in result.logs if r.node == "beginner"]
    assert line.msg.startswith("drove for 2.0")
    assert line.t == pytest.approx(2.0, abs=0.1)


def test_a_clock_loop_that_outlives_the_run_ends_with_it(tmp_path: Path) -> None:
    """After the run, time no longer comes from the simulation: timed waits
    pass at once and the clock jumps, so a loop waiting for some time ends
    (it used to spin until it was killed, reported as a crash)."""
    path = write(tmp_path, """
        import queue, time
        import rclpy
        from rclpy.node import Node


        class Patient(Node):
            def __init__(self):
                super().__init__("patient")
                self.create_timer(0.5, self.tick)

            def tick(self):
                try:
                    queue.Queue().get(timeout=2.0)
                except queue.Empty:
                    pass
                end = time.time() + 5.0
                while time.time() < end:
                    time.sleep(0.5)


        def main():
            rclpy.init()
            rclpy.spin(Patient())
    """)
    result = run([path], duration=1.0, limits=Limits(step_timeout=1.0))
    assert result.crashes == []
    assert result.sim_time == pytest.approx(1.0)
