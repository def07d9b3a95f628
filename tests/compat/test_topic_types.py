"""One topic name, several message types, as in ROS 2 (Kilted, Fast DDS;
measured with rclpy 9.1): another process's endpoint of another type is
created and never matched (graph queries list both types); one process asking
for a second type on a name raises RCLError. Under both hosts."""

from __future__ import annotations

from support.hosts import node_logs, write_controller

from turtletui.api import run

WRONG_POSE = """
import rclpy
from geometry_msgs.msg import Pose, Twist
from rclpy.node import Node


class Follower(Node):
    def __init__(self):
        super().__init__("follower")
        self.heard = 0
        self.sub = self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.5, self.drive)

    def on_pose(self, msg):
        self.heard += 1

    def drive(self):
        self.pub.publish(Twist())
        log = self.get_logger().info
        log(f"heard {self.heard}, matched {self.sub.get_publisher_count()}")
        log(f"types {dict(self.get_topic_names_and_types())['/turtle1/pose']}")
        log(f"counts {self.count_publishers('/turtle1/pose')} {self.count_subscribers('/turtle1/pose')}")
        log(f"publishers {[i.topic_type for i in self.get_publishers_info_by_topic('/turtle1/pose')]}")
        log(f"subscriptions {[i.topic_type for i in self.get_subscriptions_info_by_topic('/turtle1/pose')]}")


def main():
    rclpy.init()
    rclpy.spin(Follower())
"""


def test_a_subscription_of_another_type_than_turtlesim_publishes_hears_nothing(controller_host):
    result = controller_host.run(WRONG_POSE, duration=1.2)
    assert node_logs(result, "follower")[-5:] == [
        "heard 0, matched 0",
        "types ['geometry_msgs/msg/Pose', 'turtlesim/msg/Pose']",
        "counts 1 1",
        "publishers ['turtlesim/msg/Pose']",
        "subscriptions ['geometry_msgs/msg/Pose']",
    ]
    assert node_logs(result, "turtletui") == [
        "/follower subscribes to /turtle1/pose with type geometry_msgs/msg/Pose, but /turtlesim publishes it "
        "with type turtlesim/msg/Pose: endpoints of different types never match, so nothing passes between them"
    ]


def test_a_publisher_of_another_type_than_turtlesim_subscribes_drives_nothing(controller_host):
    result = controller_host.run(
        """
        import rclpy
        from geometry_msgs.msg import Vector3
        from rclpy.node import Node


        def main():
            rclpy.init()
            node = Node("pusher")
            pub = node.create_publisher(Vector3, "/turtle1/cmd_vel", 10)
            node.create_timer(0.1, lambda: pub.publish(Vector3(x=2.0)))
            rclpy.spin(node)
        """,
        duration=2.0,
    )
    assert result.distance == 0.0
    assert node_logs(result, "turtletui") == [
        "/pusher publishes on /turtle1/cmd_vel with type geometry_msgs/msg/Vector3, but /turtlesim subscribes "
        "to it with type geometry_msgs/msg/Twist: endpoints of different types never match, so nothing passes "
        "between them"
    ]


def test_one_process_cannot_use_a_name_with_two_types(controller_host):
    result = controller_host.run(
        """
        import rclpy
        from geometry_msgs.msg import Pose
        from rclpy.node import Node
        from std_msgs.msg import String


        def main():
            rclpy.init()
            one, other = Node("one"), Node("other")
            one.create_subscription(String, "/chatter", lambda msg: None, 10)
            for make in (
                lambda: other.create_subscription(Pose, "/chatter", lambda msg: None, 10),
                lambda: one.create_publisher(Pose, "chatter", 10),
            ):
                try:
                    make()
                except Exception as err:
                    one.get_logger().info(f"{type(err).__module__}.{type(err).__name__}: {err}")
            one.get_logger().info(f"{one.get_topic_names_and_types()[0]}")
        """,
        duration=0.5,
    )
    assert node_logs(result, "one") == [
        "rclpy._rclpy_pybind11.RCLError: Failed to create subscription: create_subscription() called for "
        "existing topic name rt/chatter with incompatible type geometry_msgs::msg::dds_::Pose_",
        "rclpy._rclpy_pybind11.RCLError: Failed to create publisher: create_publisher() called for "
        "existing topic name rt/chatter with incompatible type geometry_msgs::msg::dds_::Pose_",
        "('/chatter', ['std_msgs/msg/String'])",
    ]


def test_two_files_use_one_name_with_two_types(tmp_path):
    talker = write_controller(tmp_path, """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String


        def main():
            rclpy.init()
            node = Node("talker")
            pub = node.create_publisher(String, "/chatter", 10)
            node.create_timer(0.1, lambda: pub.publish(String(data="hi")))
            rclpy.spin(node)
        """, "talker.py")
    listener = write_controller(tmp_path, """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import Int32, String


        def main():
            rclpy.init()
            node = Node("listener")
            heard = []
            node.create_subscription(Int32, "/chatter", lambda m: heard.append("int"), 10)
            node.create_timer(1.0, lambda: node.get_logger().info(
                f"heard {heard} {dict(node.get_topic_names_and_types())['/chatter']}"))
            rclpy.spin(node)
        """, "listener.py")
    # two files are two processes (only the sandbox runs two): each child's
    # mirror of the graph lists the other's type, and nothing is delivered
    result = run([talker, listener], duration=1.1, sandbox=True)
    assert node_logs(result, "listener") == ["heard [] ['std_msgs/msg/Int32', 'std_msgs/msg/String']"]
