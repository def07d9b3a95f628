"""A controller's own subscription to /rosout, under both hosts.

Checked against the real rclpy (Kilted) by tests/fidelity/programs/
rosout_subscription.py; here the same between files and with turtlesim,
and a node that logs in its /rosout callback, which floods its log as on
ROS 2 without freezing the run.
"""

from __future__ import annotations

from support.hosts import node_logs, write_controller

from turtletui.api import run
from turtletui.runtime.sandbox import Limits

LISTENER = """
import os

import rclpy
from rcl_interfaces.msg import Log
from rclpy.node import Node


class Listener(Node):
    def __init__(self):
        super().__init__("listener")
        self.create_subscription(Log, "/rosout", self.on_log, 50)
        self.create_timer(0.2, self.speak)

    def speak(self):
        self.get_logger().warning("mine")

    def on_log(self, msg):
        report = rclpy.logging.get_logger("report")  # a logger of no node: not on /rosout
        if msg.name != "listener":
            report.info(f"{msg.level} {msg.name} {msg.msg} {os.path.basename(msg.file)} {msg.function} "
                        f"{msg.line} {msg.stamp.sec} {msg.stamp.nanosec}")
        elif msg.msg == "mine":
            report.info(f"own {msg.level} {os.path.basename(msg.file)} {msg.function} {msg.line} {msg.stamp.nanosec}")
"""

TALKER = """
import rclpy
from rclpy.node import Node
from turtlesim.srv import Spawn


class Talker(Node):
    def __init__(self):
        super().__init__("talker", namespace="/lab")
        self.spawn = self.create_client(Spawn, "/spawn")
        self.create_timer(0.3, self.talk)
        self.said = 0

    def talk(self):
        self.said += 1
        if self.said == 1:
            self.get_logger().get_child("part").error("from a child logger")
            self.spawn.call_async(Spawn.Request(x=2.0, y=2.0, name="other"))
"""


def test_a_rosout_subscription_hears_its_own_lines_with_where_they_were_logged(controller_host):
    result = controller_host.run(LISTENER, duration=0.5)
    assert result.ok, result.crashes
    assert node_logs(result, "report") == [
        "own 30 controller.py speak 15 200000000", "own 30 controller.py speak 15 400000000",
    ]


def test_lines_of_other_files_and_of_turtlesim_reach_a_rosout_subscription(tmp_path):
    listener = write_controller(tmp_path, LISTENER, "listener.py")
    talker = write_controller(tmp_path, TALKER, "talker.py")
    result = run([listener, talker], duration=0.6)
    assert result.ok, result.crashes
    heard = [line for line in node_logs(result, "report") if not line.startswith("own")]
    # another process's lines carry no call site here (see the README's fidelity table)
    assert heard == [
        "40 lab.talker.part from a child logger   0 1700000000 300000000",
        "20 turtlesim Spawning turtle [other] at x=[2.000000], y=[2.000000], theta=[0.000000]   0 1700000000 300000000",
    ]


ECHO = """
import rclpy
from rcl_interfaces.msg import Log
from rclpy.node import Node


class Echo(Node):
    def __init__(self):
        super().__init__("echo")
        self.create_subscription(Log, "/rosout", self.on_log, 10)
        self.get_logger().info("start")

    def on_log(self, msg):
        self.get_logger().info(f"heard {len(msg.msg)}")
"""


def test_logging_in_the_rosout_callback_floods_the_log_without_freezing_the_run(controller_host):
    result = controller_host.run(ECHO, duration=0.05)
    assert result.ok, result.crashes
    lines = node_logs(result, "echo")
    # "start" is heard at once; a line logged in the callback comes back a
    # millisecond later, as through DDS: one more line each ms
    assert lines[:3] == ["start", "heard 5", "heard 7"]
    assert [r.t for r in result.logs if r.node == "echo"][:4] == [0.0, 0.0, 0.001, 0.002]
    assert len(lines) == 52


def test_the_log_budget_stops_the_flood_in_the_sandbox(tmp_path):
    echo = write_controller(tmp_path, ECHO, "echo.py")
    result = run([echo], duration=0.5, limits=Limits(log_lines=100))
    assert result.ok, result.crashes
    assert len(node_logs(result, "echo")) == 100
    notes = [r.msg for r in result.logs if r.node == "turtletui" and "log over its budget" in r.msg]
    assert len(notes) == 1 and notes[0].endswith("echo.py: log over its budget of 100 messages or 4.0 MB per run: the rest is dropped")
