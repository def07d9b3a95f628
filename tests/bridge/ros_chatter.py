"""Another ROS 2 process (the real rclpy): publishes /chatter (std_msgs/String)
at 10 Hz and prints each /from_app message it receives, for SECONDS."""

import sys
import time

import rclpy
from std_msgs.msg import String


def main() -> None:
    rclpy.init()
    node = rclpy.create_node("chatter")
    publisher = node.create_publisher(String, "/chatter", 10)
    node.create_subscription(String, "/from_app", lambda m: print("got", m.data, flush=True), 10)
    node.create_timer(0.1, lambda: publisher.publish(String(data="hello from ROS 2")))
    end = time.monotonic() + float(sys.argv[1])
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
