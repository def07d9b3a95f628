"""A transient-local ("latched") publisher keeps its last messages for subscriptions that
join late: a transient-local one gets the last N, a volatile one only what comes after.

(A late subscription with a smaller depth than the publisher's is left out: under Fast DDS
it gets the publisher's last 2 or 3 messages, by how soon the executor takes them.)"""
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("latched")
    latched = QoSProfile(depth=3, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    publisher = node.create_publisher(String, "map", latched)
    for i in range(5):
        publisher.publish(String(data=f"map v{i}"))
    late = []
    volatile = []
    node.create_subscription(String, "map", lambda m: late.append(m.data), latched)
    node.create_subscription(String, "map", lambda m: volatile.append(m.data), 10)
    for _ in range(10):
        rclpy.spin_once(node, timeout_sec=0.05)
    publisher.publish(String(data="map v5"))
    for _ in range(10):
        rclpy.spin_once(node, timeout_sec=0.05)
    print("transient-local, depth 3:", late)
    print("volatile:", volatile)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
