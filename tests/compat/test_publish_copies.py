"""rclpy's publish() sends what the message holds at that moment: changing
it afterwards changes nothing any subscriber, turtlesim, a recording or a
late joiner of a transient-local topic gets, in both hosts."""

from __future__ import annotations

import sys
import textwrap

import pytest

from turtletui.api import run

CONTROLLER = """
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Reuser(Node):
    def __init__(self):
        super().__init__("reuser")
        self.cmd = Twist()
        self.drive = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.echo = self.create_subscription(Twist, "/turtle1/cmd_vel", self.heard, 10)
        self.latched = self.create_publisher(String, "latched", LATCHED)
        self.note = String(data="first")
        self.latched.publish(self.note)
        self.note.data = "changed after publish"
        self.create_timer(0.1, self.tick)
        self.create_timer(0.55, self.join, callback_group=None)
        self.joined = False

    def tick(self):
        self.cmd.linear.x = 1.0
        self.drive.publish(self.cmd)
        self.cmd.linear.x = 50.0  # after publish: sent nowhere

    def heard(self, msg):
        self.get_logger().info(f"heard {msg.linear.x}")
        msg.linear.x = -1.0  # the subscriber's own copy

    def join(self):
        if not self.joined:
            self.joined = True
            self.create_subscription(String, "latched", lambda m: self.get_logger().info(f"late {m.data}"), LATCHED)


def main():
    rclpy.init()
    rclpy.spin(Reuser())
"""


@pytest.mark.parametrize("tapped", [False, True], ids=["plain", "tapped"])
@pytest.mark.parametrize(
    "sandbox",
    [
        pytest.param(False, id="in-process"),
        pytest.param(True, id="sandboxed", marks=pytest.mark.skipif(sys.platform == "win32", reason="POSIX")),
    ],
)
def test_changing_a_message_after_publish_changes_nothing_sent(tmp_path, sandbox, tapped):
    path = tmp_path / "reuser.py"
    path.write_text(textwrap.dedent(CONTROLLER).lstrip(), encoding="utf-8")
    result = run([path], duration=1.0, sandbox=sandbox, keep_poses=tapped, keep_calls=tapped)
    assert result.ok, result.crashes
    said = [r.msg for r in result.logs if r.node == "reuser"]
    assert set(said) == {"heard 1.0", "late first"}, said
    assert said.count("heard 1.0") >= 8
    turtle = result.turtles["turtle1"]
    # 1 m/s from the first command on (t = 0.1 s) to the end: about 0.9 m, never 50 m/s
    assert 0.8 < turtle.distance < 1.0
