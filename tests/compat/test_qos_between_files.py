"""QoS between two sandboxed controller files, each its own process (as
students' files run, and as `ros2 launch` starts two programs): matching,
rclpy's warnings on both sides, counts and transient-local history as
between two ROS 2 processes (in one process: test_rclpy_behaviour.py and the
fidelity program qos_incompatible)."""

from __future__ import annotations

from support.hosts import node_logs, write_controller

from turtletui.api import run

TALKER = """
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node('talker')
    fast = node.create_publisher(String, '/chatter', qos_profile_sensor_data)
    status = node.create_publisher(String, '/status', 10)
    latched = node.create_publisher(String, '/latched', QoSProfile(depth=2, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    for i in range(3):  # before anyone discovered the publisher: kept for transient-local late joiners
        latched.publish(String(data=f'latched {i}'))

    def tick():
        fast.publish(String(data='fast'))
        status.publish(String(data='status'))

    node.create_timer(0.1, tick)
    node.create_timer(
        1.5,
        lambda: node.get_logger().info(
            f'matched {fast.get_subscription_count()} {status.get_subscription_count()} '
            f'{latched.get_subscription_count()}'
        ),
    )
    rclpy.spin(node)
"""

LISTENER = """
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node('listener')
    heard = []
    node.create_subscription(String, '/chatter', lambda m: heard.append(m.data), 10)
    latched = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    node.create_subscription(String, '/status', lambda m: heard.append(m.data), latched)
    rclpy.spin_once(node, timeout_sec=0.5)
    # joins late: the talker's transient-local publisher gives it its last 2 messages
    late = node.create_subscription(String, '/latched', lambda m: heard.append(m.data), latched)
    node.create_subscription(String, '/latched', lambda m: heard.append('volatile ' + m.data), 10)
    node.create_timer(1.5, lambda: node.get_logger().info(f'heard {heard} from {late.get_publisher_count()}'))
    rclpy.spin(node)
"""

PUBLISHER_SIDE = (
    "New subscription discovered on topic '{}', requesting incompatible QoS. "
    "No messages will be sent to it. Last incompatible policy: {}"
)
SUBSCRIPTION_SIDE = (
    "New publisher discovered on topic '{}', offering incompatible QoS. "
    "No messages will be received from it. Last incompatible policy: {}"
)


def test_two_files_match_warn_count_and_give_late_joiners_the_kept_messages(tmp_path):
    talker, listener = write_controller(tmp_path, TALKER, "talker.py"), write_controller(tmp_path, LISTENER, "listener.py")
    result = run([talker, listener], duration=2.0, sandbox=True)
    assert result.ok, result.crashes
    assert node_logs(result, "talker") == [
        PUBLISHER_SIDE.format("/chatter", "RELIABILITY"),
        PUBLISHER_SIDE.format("/status", "DURABILITY"),
        "matched 0 0 2",
    ]
    assert node_logs(result, "listener") == [
        SUBSCRIPTION_SIDE.format("/chatter", "RELIABILITY"),
        SUBSCRIPTION_SIDE.format("/status", "DURABILITY"),
        "heard ['latched 1', 'latched 2'] from 1",
    ]


def test_the_same_run_twice_logs_the_same(tmp_path):
    talker, listener = write_controller(tmp_path, TALKER, "talker.py"), write_controller(tmp_path, LISTENER, "listener.py")
    runs = [run([talker, listener], duration=2.0, sandbox=True) for _ in range(2)]
    assert [(r.t, r.node, r.msg) for r in runs[0].logs] == [(r.t, r.node, r.msg) for r in runs[1].logs]
