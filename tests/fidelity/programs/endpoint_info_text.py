"""What printing a TopicEndpointInfo shows (ros2 topic info -v prints the same):
every line but the GID, which the middleware makes up, for a default publisher
and a best-effort, transient-local subscription."""
import rclpy
from _discovery import spin_until
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String


def without_gid(info):
    return "\n".join(line for line in str(info).splitlines() if not line.startswith("GID: "))


def main():
    rclpy.init()
    talker = Node("talker")
    watcher = Node("watcher")
    executor = SingleThreadedExecutor()
    executor.add_node(talker)
    executor.add_node(watcher)
    talker.create_publisher(String, "/chatter", 10)
    latched = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    watcher.create_subscription(String, "/chatter", lambda msg: None, latched)
    print("seen", spin_until(executor, lambda: watcher.get_publishers_info_by_topic("/chatter")
                             and talker.get_subscriptions_info_by_topic("/chatter")))
    print(without_gid(watcher.get_publishers_info_by_topic("/chatter")[0]))
    print(without_gid(talker.get_subscriptions_info_by_topic("/chatter")[0]))
    talker.destroy_node()
    watcher.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
