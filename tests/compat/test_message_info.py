"""Subscription callbacks with a second parameter get rclpy's MessageInfo, in both hosts.

What the real rclpy (Kilted 9.1, Fast DDS) gives, measured with
tests/fidelity/programs/message_info.py: a plain dict, ``source_timestamp``
and ``received_timestamp`` in ns of system time, ``publication_sequence_number``
counting each publisher's messages from 1, ``reception_sequence_number``
None (Fast DDS does not count them), ``publisher_gid`` (Kilted on) naming
the publisher as its TopicEndpointInfo does. Humble passes the message only.
"""

from __future__ import annotations

import pytest
from support.hosts import node_logs

from turtletui.compat import message_info

POSE_INFO = """
import rclpy
from rclpy.node import Node
from {package}.msg import Pose


class Watcher(Node):
    def __init__(self):
        super().__init__("watcher")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_plain, 10)
        self.seen = 0

    def on_pose(self, msg, info):
        self.seen += 1
        if self.seen > 3:
            return
        gid = info.get("publisher_gid")
        listed = [bytes(e.endpoint_gid) for e in self.get_publishers_info_by_topic("/turtle1/pose")]
        now = self.get_clock().now().nanoseconds
        self.get_logger().info(
            f"keys={{list(info)}} seq={{info['publication_sequence_number']}} "
            f"rseq={{info['reception_sequence_number']}} "
            f"sent={{info['source_timestamp'] <= info['received_timestamp'] <= now}} "
            f"gid={{gid is None or (gid['data'] in listed, gid['implementation_identifier'])}}"
        )

    def on_plain(self, msg):
        if self.seen <= 3:
            self.get_logger().info("plain")
"""

KEYS = ["source_timestamp", "received_timestamp", "publication_sequence_number", "reception_sequence_number"]


@pytest.mark.parametrize(("distro", "package", "gid"), [("jazzy", "turtlesim", False), ("kilted", "turtlesim_msgs", True)])
def test_a_two_parameter_callback_gets_the_message_info_of_each_pose(controller_host, distro, package, gid):
    result = controller_host.run(POSE_INFO.format(package=package), duration=0.2, distro=distro)
    assert result.ok, result.crashes
    keys = KEYS + ["publisher_gid"] if gid else KEYS
    shown = "True, 'rmw_fastrtps_cpp')" if gid else "True"
    # turtlesim published twice before the watcher discovered it: its
    # sequence numbers go on from there; the plain callback, made second, runs second
    assert node_logs(result, "watcher") == [
        line
        for seq in (3, 4, 5)
        for line in (f"keys={keys} seq={seq} rseq=None sent=True gid={'(' if gid else ''}{shown}", "plain")
    ]


def test_a_publisher_counts_its_messages_from_one_and_a_late_joiner_gets_the_kept_ones_numbered(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String


class Counter(Node):
    def __init__(self):
        super().__init__("counter")
        latched = QoSProfile(depth=2, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.a = self.create_publisher(String, "chatter", latched)
        self.b = self.create_publisher(String, "chatter", latched)
        for i in range(3):
            self.a.publish(String(data=f"a{i}"))
        self.create_subscription(String, "chatter", self.on_message, latched)
        self.create_timer(0.1, self.tick)
        self.ticks = 0

    def tick(self):
        self.ticks += 1
        if self.ticks <= 2:
            self.a.publish(String(data=f"a{self.ticks + 2}"))
            self.b.publish(String(data=f"b{self.ticks}"))

    def on_message(self, msg, info):
        self.get_logger().info(f"{msg.data} {info['publication_sequence_number']}")
""",
        duration=0.5,
    )
    assert result.ok, result.crashes
    assert node_logs(result, "counter") == ["a1 2", "a2 3", "a3 4", "b1 1", "a4 5", "b2 2"]


def test_a_callback_it_cannot_call_is_refused_as_rclpy_refuses_it(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Picky(Node):
    def __init__(self):
        super().__init__("picky")
        for callback in (lambda: None, lambda a, b, c: None, 42):
            try:
                self.create_subscription(String, "chatter", callback, 10)
            except RuntimeError as err:
                self.get_logger().info(str(err))
        self.get_logger().info(f"subscriptions: {self.count_subscribers('chatter')}")
""",
        duration=0.1,
    )
    refused = (
        "Subscription.__init__(): callback should be either be callable with one argument"
        "(to get only the message) or two (to get message and message info)"
    )
    assert node_logs(result, "picky") == [refused] * 3 + ["subscriptions: 0"]


def test_humble_passes_the_message_only(controller_host):
    result = controller_host.run(
        """
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class Old(Node):
    def __init__(self):
        super().__init__("old")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, msg, info):
        pass
""",
        duration=0.1,
        distro="humble",
    )
    assert not result.ok
    assert "on_pose() missing 1 required positional argument: 'info'" in str(result.crashes)


@pytest.mark.parametrize(
    ("callback", "takes"),
    [
        (lambda msg: None, False),
        (lambda msg, info=None: None, False),
        (lambda *args: None, False),
        (lambda msg, info: None, True),
        (lambda msg, info, extra=None: None, True),
        (print, False),
    ],
)
def test_the_callback_s_signature_decides_as_rclpy_binds_it(callback, takes, monkeypatch):
    monkeypatch.setattr(message_info, "current_distro", lambda: "kilted")
    assert message_info.takes_message_info(callback) is takes



GID_AFTER_DESTROY = """
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("two")
    first = node.create_publisher(String, "/chatter", 10)
    second = node.create_publisher(String, "/chatter", 10)
    gids = []
    node.create_subscription(String, "/chatter", lambda msg, info: gids.append(bytes(info["publisher_gid"]["data"])), 10)
    second.publish(String(data="a"))
    rclpy.spin_once(node, timeout_sec=0.1)
    listed = [bytes(e.endpoint_gid) for e in node.get_publishers_info_by_topic("/chatter")]
    node.destroy_publisher(first)
    second.publish(String(data="b"))
    rclpy.spin_once(node, timeout_sec=0.1)
    after = [bytes(e.endpoint_gid) for e in node.get_publishers_info_by_topic("/chatter")]
    node.get_logger().info(f"same={gids[0] == gids[1]} listed={gids[0] in listed} still={after == [gids[0]]}")
    rclpy.shutdown()
"""


def test_a_publishers_gid_stays_what_it_was_when_another_goes(controller_host):
    """A DDS GUID is fixed: the second publisher of a node keeps its GID in
    MessageInfo and in TopicEndpointInfo when the first is destroyed."""
    result = controller_host.run(GID_AFTER_DESTROY, duration=1.0, distro="kilted")
    assert result.ok, result.crashes
    assert node_logs(result, "two") == ["same=True listed=True still=True"]
