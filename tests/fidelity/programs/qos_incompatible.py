"""QoS that never match: a best-effort publisher and a reliable subscription, a volatile
publisher and a transient-local subscription. Nothing passes, and both sides warn (one node:
rclpy's executor orders the events of one node, not those of several)."""
import time

import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("mismatch", namespace="robot")
    heard = []
    fast = node.create_publisher(String, "/robot/chatter", qos_profile_sensor_data)
    node.create_subscription(String, "chatter", lambda m: heard.append(m.data), 10)
    status = node.create_publisher(String, "status", 10)
    latched = QoSProfile(depth=5, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    node.create_subscription(String, "/robot/status", lambda m: heard.append(m.data), latched)
    time.sleep(1.0)  # discovery done: the executor then sees every QoS event at once
    for i in range(10):
        fast.publish(String(data=f"fast {i}"))
        status.publish(String(data=f"status {i}"))
        rclpy.spin_once(node, timeout_sec=0.05)
    print("heard:", heard)
    print("matched subscriptions:", fast.get_subscription_count(), status.get_subscription_count())
    print("subscribers on the graph:", node.count_subscribers("chatter"), node.count_subscribers("/robot/status"))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
