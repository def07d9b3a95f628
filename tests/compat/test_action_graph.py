"""An action's hidden topics and services in rclpy's graph queries, the same in
both hosts: turtlesim's rotate_absolute server, a file's own servers and
clients, and (sandboxed) another file's, as rcl_action makes them.

Checked against the real rclpy (Kilted) by tests/fidelity/programs/action_graph.py.
"""

from __future__ import annotations

from support.hosts import node_logs, write_controller

from turtletui.api import run

TURTLESIMS_ACTION = """
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

HIDDEN = "/turtle1/rotate_absolute/_action/"


class Looker(Node):
    def __init__(self):
        super().__init__("looker")
        self.timer = self.create_timer(0.2, self.look)

    def look(self):
        self.timer.cancel()
        log = self.get_logger().info
        hidden = lambda pairs: [(n, t) for n, t in pairs if n.startswith(HIDDEN)]
        log(f"topics {hidden(self.get_topic_names_and_types())}")
        log(f"services {[n for n, _ in hidden(self.get_service_names_and_types())]}")
        log(f"turtlesim publishes {[n for n, _ in hidden(self.get_publisher_names_and_types_by_node('turtlesim', '/'))]}")
        log(f"turtlesim serves {[n for n, _ in hidden(self.get_service_names_and_types_by_node('turtlesim', '/'))]}")
        log(f"counts {self.count_publishers(HIDDEN + 'status')} {self.count_subscribers(HIDDEN + 'status')}")
        self.client = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        log(f"with a client {self.count_subscribers(HIDDEN + 'feedback')} {self.count_clients(HIDDEN + 'send_goal')}")
        log(f"looker calls {[n for n, _ in self.get_client_names_and_types_by_node('looker', '/')]}")
        for info in self.get_publishers_info_by_topic(HIDDEN + "status") + self.get_subscriptions_info_by_topic(
            HIDDEN + "status"
        ):
            qos = info.qos_profile
            log(f"{info.endpoint_type.name} {info.node_name} {info.topic_type} {qos.durability.name} {qos.depth}")
        self.client.destroy()
        log(f"client destroyed {self.count_subscribers(HIDDEN + 'feedback')} {self.count_clients(HIDDEN + 'send_goal')}")
"""


def test_turtlesims_rotate_absolute_has_its_hidden_endpoints(controller_host):
    result = controller_host.run(TURTLESIMS_ACTION, duration=0.5)
    assert result.ok, result.crashes
    hidden = "/turtle1/rotate_absolute/_action/"
    assert node_logs(result, "looker") == [
        f"topics [('{hidden}feedback', ['turtlesim/action/RotateAbsolute_FeedbackMessage']), "
        f"('{hidden}status', ['action_msgs/msg/GoalStatusArray'])]",
        f"services ['{hidden}cancel_goal', '{hidden}get_result', '{hidden}send_goal']",
        f"turtlesim publishes ['{hidden}feedback', '{hidden}status']",
        f"turtlesim serves ['{hidden}cancel_goal', '{hidden}get_result', '{hidden}send_goal']",
        "counts 1 0",
        "with a client 1 1",
        f"looker calls ['{hidden}cancel_goal', '{hidden}get_result', '{hidden}send_goal']",
        "PUBLISHER turtlesim action_msgs/msg/GoalStatusArray TRANSIENT_LOCAL 0",
        "SUBSCRIPTION looker action_msgs/msg/GoalStatusArray TRANSIENT_LOCAL 0",
        "client destroyed 0 0",
    ]


SERVER_FILE = """
import rclpy
from rclpy.action import ActionServer
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class Server(Node):
    def __init__(self):
        super().__init__("server", namespace="/lab")
        self.server = ActionServer(self, RotateAbsolute, "spin", lambda goal_handle: RotateAbsolute.Result())
        self.timer = self.create_timer(0.5, self.look)

    def look(self):
        self.timer.cancel()
        log = self.get_logger().info
        log(f"subscribers {self.count_subscribers('/lab/spin/_action/status')}")
        for info in self.get_subscriptions_info_by_topic("/lab/spin/_action/feedback"):
            log(f"subscription {info.node_namespace} {info.node_name} {info.qos_profile.durability.name}")
        log(f"watcher subscribes {self.get_subscriber_names_and_types_by_node('watcher', '/')}")
"""

WATCHER_FILE = """
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class Watcher(Node):
    def __init__(self):
        super().__init__("watcher")
        self.client = ActionClient(self, RotateAbsolute, "/lab/spin")
        self.timer = self.create_timer(0.5, self.look)

    def look(self):
        self.timer.cancel()
        log = self.get_logger().info
        ours = lambda pairs: [n for n, _ in pairs if n.startswith("/lab/spin/")]
        log(f"topics {ours(self.get_topic_names_and_types())}")
        log(f"server serves {ours(self.get_service_names_and_types_by_node('server', '/lab'))}")
        log(f"counts {self.count_publishers('/lab/spin/_action/feedback')} {self.count_services('/lab/spin/_action/get_result')}")
        [info] = self.get_publishers_info_by_topic("/lab/spin/_action/status")
        log(f"status publisher {info.node_namespace} {info.node_name} {info.topic_type} {info.qos_profile.durability.name}")
"""


def test_another_files_action_endpoints_are_in_the_queries(tmp_path):
    # two files run sandboxed only (in-process runs one): two processes, each
    # with the other's action records mirrored
    server = write_controller(tmp_path, SERVER_FILE, "server.py")
    watcher = write_controller(tmp_path, WATCHER_FILE, "watcher.py")
    result = run([server, watcher], duration=1.0)
    assert result.ok, result.crashes
    assert node_logs(result, "lab.server") == [
        "subscribers 1",
        "subscription / watcher VOLATILE",
        "watcher subscribes [('/lab/spin/_action/feedback', ['turtlesim/action/RotateAbsolute_FeedbackMessage']), "
        "('/lab/spin/_action/status', ['action_msgs/msg/GoalStatusArray'])]",
    ]
    assert node_logs(result, "watcher") == [
        "topics ['/lab/spin/_action/feedback', '/lab/spin/_action/status']",
        "server serves ['/lab/spin/_action/cancel_goal', '/lab/spin/_action/get_result', '/lab/spin/_action/send_goal']",
        "counts 1 1",
        "status publisher /lab server action_msgs/msg/GoalStatusArray TRANSIENT_LOCAL",
    ]
