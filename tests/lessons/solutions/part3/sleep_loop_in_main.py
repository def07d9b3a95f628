"""Wrong: a loop in main() logs the counter and sleeps a second. The lines look
like a timer's, but there is no timer and the node never spins: it could not
answer a message, a service call or a parameter change."""
import time

import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.counter_ = 0


def main(args=None):
    rclpy.init(args=args)
    node = MyNode()
    while rclpy.ok():
        node.get_logger().info("Hello " + str(node.counter_))
        node.counter_ += 1
        time.sleep(1.0)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
