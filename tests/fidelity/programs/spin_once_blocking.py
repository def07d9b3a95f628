"""rclpy.spin_once(node) with no timeout: it blocks until something is ready, so with a timer
due it runs exactly that timer's callback and returns; with two timers, one callback per call,
in the order they become due; a subscription message arriving takes one call too."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("blocking")
    calls = []
    fast = node.create_timer(0.05, lambda: calls.append("fast"))
    rclpy.spin_once(node)
    print("after one spin_once:", calls)
    fast.cancel()
    slow = node.create_timer(0.2, lambda: calls.append("slow"))
    rclpy.spin_once(node)
    print("after the slow timer:", calls)
    slow.cancel()
    node.create_subscription(String, "words", lambda msg: calls.append("heard " + msg.data), 10)
    pub = node.create_publisher(String, "words", 10)
    pub.publish(String(data="hello"))
    rclpy.spin_once(node)
    print("after publishing:", calls)
    print("timers cancelled:", fast.is_canceled(), slow.is_canceled())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
