"""rclpy.wait_for_message under both hosts (rclpy 9's; the differential
program tests/fidelity/programs/wait_for_message.py checks it against the real rclpy)."""

from __future__ import annotations

from support.hosts import node_logs


def test_wait_for_message_takes_the_next_pose_and_times_out_on_a_silent_topic(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from rclpy.wait_for_message import wait_for_message
from std_msgs.msg import String
from turtlesim.msg import Pose


def main():
    rclpy.init()
    node = Node("waiter")
    ok, pose = wait_for_message(Pose, node, "/turtle1/pose", time_to_wait=2.0)
    log = node.get_logger().info
    log(f"pose: {ok} {type(pose).__name__} x={pose.x:.3f}")
    start = node.get_clock().now()
    ok, msg = wait_for_message(String, node, "/nobody", time_to_wait=0.75)
    waited = (node.get_clock().now() - start).nanoseconds / 1e9
    log(f"silent: {ok} {msg} after {waited:.2f} s; subscriptions left {node.count_subscribers('/nobody')}")
""",
        duration=3.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "waiter") == [
        "pose: True Pose x=5.544",
        "silent: False None after 0.75 s; subscriptions left 0",
    ]
