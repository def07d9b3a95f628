"""Timers, Rate and clock sleeps on /clock time (use_sim_time), under both hosts.

Checked against the real rclpy (Kilted) by tests/fidelity/programs/
sim_time_timers.py and sim_time_rate.py; here the same rules in controllers
as students write them: a node's timers follow its /clock, not the run's
time, and whatever follows the run's time (a steady clock's timer, the
simulator) keeps going.
"""

from __future__ import annotations

import pytest
from support.hosts import node_logs, write_controller
from test_node_plumbing import (
    CLOCK,  # publishes /clock on a steady clock: 101 s, 102 s ... every 0.2 s
)

from turtletui.api import run

TWO_CLOCKS = """
import rclpy
from rclpy.clock import Clock, ClockType
from rclpy.node import Node


class Timed(Node):
    def __init__(self):
        super().__init__("timed")
        self.create_timer(0.25, self.on_node_clock)
        self.create_timer(0.25, self.on_steady_clock, clock=Clock(clock_type=ClockType.STEADY_TIME))

    def on_node_clock(self):
        self.get_logger().info(f"node clock {self.get_clock().now().nanoseconds}")

    def on_steady_clock(self):
        self.get_logger().info(f"steady clock, node clock {self.get_clock().now().nanoseconds}")
"""


def test_without_clock_a_node_clock_timer_never_fires_and_a_steady_one_does(controller_host):
    result = controller_host.run(TWO_CLOCKS, duration=0.6, ros_args=["-p", "use_sim_time:=true"])
    assert result.ok, result.crashes
    assert node_logs(result, "timed") == ["steady clock, node clock 0", "steady clock, node clock 0"]


def test_without_use_sim_time_both_timers_follow_the_run(controller_host):
    result = controller_host.run(TWO_CLOCKS, duration=0.3)
    assert result.ok, result.crashes
    stamp = 1_700_000_000_250_000_000
    assert node_logs(result, "timed") == [f"node clock {stamp}", f"steady clock, node clock {stamp}"]


def test_a_node_clock_timer_fires_as_another_files_clock_passes_it(tmp_path):
    timed = write_controller(tmp_path, TWO_CLOCKS, "timed.py")
    clock = write_controller(tmp_path, CLOCK, "clock.py")
    result = run([timed, clock], duration=1.1, ros_args=["-p", "use_sim_time:=true"])
    assert result.ok, result.crashes
    # /clock jumps a whole second every 0.2 s of the run: the 0.25 s timer fires
    # once per jump (missed periods are skipped), the steady one every 0.25 s.
    node_clock = [line for line in node_logs(result, "timed") if line.startswith("node clock")]
    assert node_clock == [f"node clock {s}000000000" for s in (101, 102, 103, 104, 105)]
    steady = [line for line in node_logs(result, "timed") if line.startswith("steady")]
    assert len(steady) == 4


PACED = """
import rclpy
from builtin_interfaces.msg import Time
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.clock import Clock as WallClock, ClockType
from rclpy.duration import Duration
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rosgraph_msgs.msg import Clock


class Paced(Node):
    def __init__(self):
        super().__init__("paced", parameter_overrides=[Parameter("use_sim_time", value=True)])
        self.rate = self.create_rate(2)
        self.create_timer(0.01, self.loop, MutuallyExclusiveCallbackGroup(), WallClock(clock_type=ClockType.STEADY_TIME))
        self.done = False

    def loop(self):
        if self.done:
            return
        self.done = True
        for _ in range(3):
            self.rate.sleep()
            self.get_logger().info(f"rate {self.get_clock().now().nanoseconds}")
        slept = self.get_clock().sleep_for(Duration(seconds=1))
        self.get_logger().info(f"slept {slept} {self.get_clock().now().nanoseconds}")


class Simulator(Node):
    def __init__(self):
        super().__init__("simulator")
        self.publisher = self.create_publisher(Clock, "/clock", 10)
        self.tenths = 0
        self.create_timer(0.05, self.tick)

    def tick(self):
        self.tenths += 1
        sec, tenth = divmod(self.tenths, 10)
        self.publisher.publish(Clock(clock=Time(sec=sec, nanosec=tenth * 100_000_000)))


def main():
    rclpy.init()
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(Paced())
    executor.add_node(Simulator())
    executor.spin()
"""


def test_rate_and_sleep_for_wait_for_clock_inside_a_multithreaded_callback(controller_host):
    result = controller_host.run(PACED, duration=1.8)
    assert result.ok, result.crashes
    # /clock runs at twice the run's pace: the 2 Hz rate wakes every 0.25 s of the run
    assert node_logs(result, "paced") == [
        "rate 500000000", "rate 1000000000", "rate 1500000000", "slept True 2500000000",
    ]
    assert [r.t for r in result.logs if r.node == "paced"] == pytest.approx([0.25, 0.5, 0.75, 1.25])


SLEEP_IN_DEFAULT_GROUP = """
import rclpy
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from std_msgs.msg import Empty


class Stuck(Node):
    def __init__(self):
        super().__init__("stuck", parameter_overrides=[Parameter("use_sim_time", value=True)])
        self.rate = self.create_rate(2)
        self.pub = self.create_publisher(Empty, "go", 1)
        self.create_subscription(Empty, "go", self.go, 1)
        self.pub.publish(Empty())

    def go(self, _msg):
        self.rate.sleep()


def main():
    rclpy.init()
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(Stuck())
    executor.spin()
"""


def test_rate_sleep_in_the_default_group_on_clock_time_says_it_would_hang(controller_host):
    result = controller_host.run(SLEEP_IN_DEFAULT_GROUP, duration=0.5)
    said = [c.details() for c in result.crashes] + [r.msg for r in result.logs]
    assert any("its clock cannot move while it waits: in ROS 2 it would wait for ever" in text for text in said)
