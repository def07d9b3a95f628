"""An incompatible_qos callback that raises: the error leaves spin_once, and
the other endpoint's event callback still runs at a later spin."""
import time

import rclpy
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("qos_raises")
    seen = []

    def fails(event):
        seen.append("pub")
        raise RuntimeError("publisher's handler fails")

    def records(event):
        seen.append(f"sub {event.total_count}")

    best_effort = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    node.create_publisher(String, "chatter", best_effort, event_callbacks=PublisherEventCallbacks(incompatible_qos=fails))
    node.create_subscription(String, "chatter", lambda m: None, 10,
                             event_callbacks=SubscriptionEventCallbacks(incompatible_qos=records))
    time.sleep(0.5)  # discovery done: both events wait
    for _ in range(6):
        try:
            rclpy.spin_once(node, timeout_sec=0.05)
        except RuntimeError as err:
            print("caught:", err, "after", seen)
    print("seen:", seen)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
