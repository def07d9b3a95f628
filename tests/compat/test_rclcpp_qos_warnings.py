"""The simulator's C++ nodes warn of QoS mismatches in rclcpp's words, from
their own side, as a real turtlesim does (rclcpp's default
incompatible-QoS callbacks), once for each mismatched pair, in both hosts."""

from __future__ import annotations

from support.hosts import node_logs

TURTLESIM_PUBLISHER_SIDE = (
    "New subscription discovered on topic '{}', requesting incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}_QOS_POLICY"
)
STUDENT_SUBSCRIPTION_SIDE = (
    "New publisher discovered on topic '{}', offering incompatible QoS. "
    "No messages will be received from it. Last incompatible policy: {}"
)

LATCHED_POSE = """
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from turtlesim.msg import Pose
from turtlesim.srv import Spawn

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Watcher(Node):
    def __init__(self):
        super().__init__("watcher")
        self.heard = 0
        self.create_subscription(Pose, "/turtle1/pose", self.count, LATCHED)
        self.create_subscription(Pose, "/turtle2/pose", self.count, LATCHED)  # before turtle2 exists
        self.spawn = self.create_client(Spawn, "/spawn")
        self.create_timer(0.2, self.spawn_once)
        self.create_timer(0.9, lambda: self.get_logger().info(f"heard {self.heard}"))
        self.spawned = False

    def count(self, msg):
        self.heard += 1

    def spawn_once(self):
        if not self.spawned and self.spawn.service_is_ready():
            self.spawned = True
            self.spawn.call_async(Spawn.Request(x=2.0, y=2.0, name="turtle2"))


def main():
    rclpy.init()
    rclpy.spin(Watcher())
"""


def test_turtlesim_warns_of_a_subscription_it_cannot_serve(controller_host):
    result = controller_host.run(LATCHED_POSE, duration=1.0)
    assert result.ok, result.crashes
    turtlesim = [m for m in node_logs(result, "turtlesim") if "incompatible" in m]
    assert turtlesim == [
        TURTLESIM_PUBLISHER_SIDE.format("/turtle1/pose", "DURABILITY"),
        TURTLESIM_PUBLISHER_SIDE.format("/turtle2/pose", "DURABILITY"),
    ]
    assert node_logs(result, "watcher") == [
        STUDENT_SUBSCRIPTION_SIDE.format("/turtle1/pose", "DURABILITY"),
        STUDENT_SUBSCRIPTION_SIDE.format("/turtle2/pose", "DURABILITY"),
        "heard 0",
    ]


def test_turtlesim_warns_at_the_level_rclcpp_uses(controller_host):
    result = controller_host.run(LATCHED_POSE, duration=0.5)
    levels = {r.level for r in result.logs if r.node == "turtlesim" and "incompatible" in r.msg}
    assert levels == {30}
