"""Discovery takes time, as in ROS 2: a new publisher and the subscriptions on
its topic match DISCOVERY_NS (simulated) after the younger was made, and what
is published before that reaches no one. The same in both hosts."""

from __future__ import annotations

import pytest
from support.hosts import node_logs

from turtletui.api import run
from turtletui.graph.core import DISCOVERY_NS, NS_PER_S

HEADER = """
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from std_msgs.msg import String
"""

DISCOVERY_S = DISCOVERY_NS / NS_PER_S


def test_a_message_published_right_after_create_publisher_is_lost_and_the_log_says_why(controller_host):
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    node = Node("eager")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    msg = Twist()
    msg.linear.x = 2.0
    pub.publish(msg)
    pub.publish(msg)
    node.get_logger().info(f"matched at once: {pub.get_subscription_count()}")
    rclpy.spin_once(node, timeout_sec=0.5)
    rclpy.shutdown()
""",
        duration=1.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "eager") == ["matched at once: 0"]
    assert result.turtles["turtle1"].distance == 0.0
    notes = [r.msg for r in result.logs if r.node == "turtletui" and "discovered" in r.msg]
    assert len(notes) == 1, notes  # once, though published twice
    assert "/eager published on /turtle1/cmd_vel" in notes[0]
    assert "get_subscription_count() > 0" in notes[0]


def test_waiting_for_a_subscriber_then_publishing_drives_the_turtle(controller_host):
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    node = Node("patient")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    while pub.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.005)
    node.get_logger().info(f"matched after {node.get_clock().now().nanoseconds - 1_700_000_000 * 10**9} ns")
    msg = Twist()
    msg.linear.x = 1.0
    pub.publish(msg)
    rclpy.spin_once(node, timeout_sec=0.5)
    rclpy.shutdown()
""",
        duration=2.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "patient") == [f"matched after {DISCOVERY_NS} ns"]
    assert result.turtles["turtle1"].distance == pytest.approx(1.0, abs=0.05)  # one command: 1 s at 1 m/s
    assert not [r for r in result.logs if r.node == "turtletui" and "discovered" in r.msg]


def test_within_one_program_a_new_subscription_matches_at_once(controller_host):
    # One process is one DDS participant: its endpoints match as they are made
    # (real rclpy: get_subscription_count() is 1 right after create_publisher).
    result = controller_host.run(
        HEADER
        + """
def main():
    rclpy.init()
    talker = Node("talker")
    listener = Node("listener")
    heard = []
    listener.create_subscription(String, "/chat", lambda m: heard.append(m.data), 10)
    pub = talker.create_publisher(String, "/chat", 10)
    talker.get_logger().info(f"matched at once: {pub.get_subscription_count()}")
    pub.publish(String(data="early"))
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(listener)
    executor.spin_once(timeout_sec=0.1)
    listener.get_logger().info(" ".join(heard))
    rclpy.shutdown()
""",
        duration=1.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "talker") == ["matched at once: 1"]
    assert node_logs(result, "listener") == ["early"]
    assert not [r for r in result.logs if r.node == "turtletui" and "discovered" in r.msg]


TALKER = HEADER + """
class Talker(Node):
    def __init__(self):
        super().__init__("talker")
        self.pub = self.create_publisher(String, "/chat", 10)
        self.sent = 0
        self.create_timer(0.02, self.talk)

    def talk(self):
        self.sent += 1
        self.pub.publish(String(data=str(self.sent)))
        if self.sent == 5:
            self.get_logger().info(f"subscribers {self.pub.get_subscription_count()}")
"""

LISTENER = HEADER + """
class Listener(Node):
    def __init__(self):
        super().__init__("listener")
        self.heard = []
        self.sub = self.create_subscription(String, "/chat", self.heard.append, 10)
        self.create_timer(0.11, self.report)

    def report(self):
        self.get_logger().info(" ".join(m.data for m in self.heard) + f" from {self.sub.get_publisher_count()}")
        self.heard.clear()
"""


def test_two_programs_discover_each_other_after_the_delay(tmp_path):
    # Two controller files are two processes (sandboxed: in-process runs one).
    (tmp_path / "talker.py").write_text(TALKER)
    (tmp_path / "listener.py").write_text(LISTENER)
    result = run([tmp_path / "talker.py", tmp_path / "listener.py"], duration=0.15)
    assert result.ok, result.crashes
    # sent every 20 ms; those of 20 and 40 ms went before discovery (50 ms)
    assert node_logs(result, "listener") == ["3 4 5 from 1"]
    assert node_logs(result, "talker") == ["subscribers 1"]


def test_a_call_before_the_service_is_discovered_is_never_answered_and_the_log_says_why(controller_host):
    # Real rclpy (Kilted, Fast DDS): call_async right after create_client, to a
    # server in another process, was not answered within 3 s, every time.
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from turtlesim.srv import Spawn

def main():
    rclpy.init()
    node = Node("eager_client")
    client = node.create_client(Spawn, "/spawn")
    node.get_logger().info(f"ready at once: {client.service_is_ready()}")
    lost = client.call_async(Spawn.Request(x=2.0, y=2.0, name="lost"))
    rclpy.spin_until_future_complete(node, lost, timeout_sec=1.0)
    node.get_logger().info(f"first call answered: {lost.done()}")
    client.wait_for_service()
    found = client.call_async(Spawn.Request(x=3.0, y=3.0, name="found"))
    rclpy.spin_until_future_complete(node, found, timeout_sec=1.0)
    node.get_logger().info(f"second call answered: {found.result().name}")
    rclpy.shutdown()
""",
        duration=2.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "eager_client") == [
        "ready at once: False",
        "first call answered: False",
        "second call answered: found",
    ]
    assert set(result.turtles) == {"turtle1", "found"}
    notes = [r.msg for r in result.logs if r.node == "turtletui" and "discovered the service" in r.msg]
    assert len(notes) == 1 and "wait_for_service()" in notes[0]


def test_wait_for_service_returns_once_discovered(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from std_srvs.srv import Empty

def main():
    rclpy.init()
    node = Node("patient_client")
    client = node.create_client(Empty, "/clear")
    while not client.wait_for_service(timeout_sec=0.01):
        node.get_logger().info("waiting")
    node.get_logger().info(f"ready at {node.get_clock().now().nanoseconds - 1_700_000_000 * 10**9} ns")
    rclpy.shutdown()
""",
        duration=1.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "patient_client") == ["waiting"] * 4 + [f"ready at {DISCOVERY_NS} ns"]


def test_a_service_of_the_same_program_is_ready_at_once(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from std_srvs.srv import Trigger

def main():
    rclpy.init()
    server = Node("server")
    server.create_service(Trigger, "/ping", lambda request, response: Trigger.Response(success=True, message="pong"))
    caller = Node("caller")
    client = caller.create_client(Trigger, "/ping")
    caller.get_logger().info(f"ready at once: {client.service_is_ready()}")
    future = client.call_async(Trigger.Request())
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(server)
    executor.add_node(caller)
    executor.spin_until_future_complete(future, timeout_sec=1.0)
    caller.get_logger().info(future.result().message)
    rclpy.shutdown()
""",
        duration=1.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "caller") == ["ready at once: True", "pong"]


def test_a_goal_before_the_action_server_is_discovered_is_never_answered_and_the_log_says_why(controller_host):
    # As a service request: rclpy's goal is a request to the server's
    # send_goal service, lost when the server has not discovered the client.
    result = controller_host.run(
        """
import math
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

def main():
    rclpy.init()
    node = Node("eager_action_client")
    client = ActionClient(node, RotateAbsolute, "/turtle1/rotate_absolute")
    node.get_logger().info(f"ready at once: {client.server_is_ready()}")
    lost = client.send_goal_async(RotateAbsolute.Goal(theta=math.pi / 2))
    rclpy.spin_until_future_complete(node, lost, timeout_sec=1.0)
    node.get_logger().info(f"first goal answered: {lost.done()}")
    while not client.wait_for_server(timeout_sec=0.01):
        node.get_logger().info("waiting")
    node.get_logger().info(f"ready: {client.server_is_ready()}")
    found = client.send_goal_async(RotateAbsolute.Goal(theta=-math.pi / 2))
    rclpy.spin_until_future_complete(node, found, timeout_sec=1.0)
    node.get_logger().info(f"second goal accepted: {found.result().accepted}")
    rclpy.shutdown()
""",
        duration=2.0,
    )
    assert result.ok, result.crashes
    # the first wait starts at t=1 s, after the discovery: no "waiting"
    assert node_logs(result, "eager_action_client") == [
        "ready at once: False",
        "first goal answered: False",
        "ready: True",
        "second goal accepted: True",
    ]
    notes = [r.msg for r in result.logs if r.node == "turtletui" and "discovered the action" in r.msg]
    assert len(notes) == 1 and "wait_for_server()" in notes[0]


def test_wait_for_server_returns_once_discovered(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

def main():
    rclpy.init()
    node = Node("patient_action_client")
    client = ActionClient(node, RotateAbsolute, "/turtle1/rotate_absolute")
    while not client.wait_for_server(timeout_sec=0.01):
        node.get_logger().info("waiting")
    node.get_logger().info(f"ready at {node.get_clock().now().nanoseconds - 1_700_000_000 * 10**9} ns")
    rclpy.shutdown()
""",
        duration=1.0,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "patient_action_client") == ["waiting"] * 4 + [f"ready at {DISCOVERY_NS} ns"]
