"""Publishers of the simulator's own nodes are publishers as on ROS 2: a
scenario's scripted drive (turtle_teleop_key, held down) is a
``teleop_turtle`` node a controller counts, lists and discovers, in both
hosts; the app's teleop keys and ``ros2 bag play`` are tested with the app
and with the bags."""

from __future__ import annotations

from support.hosts import node_logs

from turtletui.runtime.replica import ReplicableSetup, Step

DRIVE = ReplicableSetup(steps=[Step("turtletui.grading.scenario_steps:ScenarioDriver", ((1.0, 0.0),))])

WATCHER = """
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from geometry_msgs.msg import Twist


class Watcher(Node):
    def __init__(self):
        super().__init__("watcher")
        self.heard = 0
        self.create_subscription(Twist, "/turtle1/cmd_vel", self.count, 10)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.create_subscription(Twist, "/turtle1/cmd_vel", lambda m: None, latched)
        self.create_timer(0.5, self.report)

    def count(self, msg):
        self.heard += 1

    def report(self):
        infos = self.get_publishers_info_by_topic("/turtle1/cmd_vel")
        self.get_logger().info(
            f"{self.count_publishers('/turtle1/cmd_vel')} publisher(s): "
            + ", ".join(f"{i.node_name} {i.qos_profile.reliability.name} {i.qos_profile.durability.name}" for i in infos)
            + f"; heard {self.heard}; nodes {sorted(self.get_node_names())}"
        )


def main():
    rclpy.init()
    rclpy.spin(Watcher())
"""


def test_a_scenario_drive_is_a_teleop_turtle_node_with_a_publisher(controller_host):
    result = controller_host.run(WATCHER, duration=0.6, setup=DRIVE)
    assert result.ok, result.crashes
    [line] = [m for m in node_logs(result, "watcher") if "publisher(s)" in m]
    # every 16 ms from 16 ms on; the watcher, made at t=0, hears them once it
    # and the teleop node have discovered each other (50 ms)
    heard = len(range(64, 500 + 1, 16))
    assert line == (
        f"1 publisher(s): teleop_turtle RELIABLE VOLATILE; heard {heard}; "
        "nodes ['teleop_turtle', 'turtlesim', 'watcher']"
    )
    # a subscription it cannot serve: teleop_turtle warns in rclcpp's words
    assert node_logs(result, "teleop_turtle") == [
        "New subscription discovered on topic '/turtle1/cmd_vel', requesting incompatible QoS. "
        "No messages will be sent to it. Last incompatible policy: DURABILITY_QOS_POLICY"
    ]
