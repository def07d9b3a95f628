"""rclpy.spin in a thread, the loop in main paced by node.create_rate(): the loop publishes,
the spinning thread runs the node's subscription, main waits for what it heard. Sandboxed only:
threads need turtletui's sandbox."""
import threading

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32


class Echo(Node):
    def __init__(self):
        super().__init__("echo")
        self.heard = []
        self.publisher = self.create_publisher(Int32, "numbers", 10)
        self.create_subscription(Int32, "numbers", lambda msg: self.heard.append(msg.data), 10)


def main():
    rclpy.init()
    node = Echo()
    spinner = threading.Thread(target=rclpy.spin, args=(node,), daemon=True)
    spinner.start()
    while node.publisher.get_subscription_count() == 0:
        pass
    rate = node.create_rate(20)
    for i in range(5):
        node.publisher.publish(Int32(data=i * i))
        rate.sleep()
    while len(node.heard) < 5:
        rate.sleep()
    node.get_logger().info(f"heard {node.heard}")
    rclpy.shutdown()
    spinner.join()
    print("spinner stopped:", not spinner.is_alive())


if __name__ == "__main__":
    main()
