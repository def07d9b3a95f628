"""Cheat: logs "Hello 0" to "Hello 9" all at once from __init__, with no timer."""
import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        for counter in range(10):
            self.get_logger().info("Hello " + str(counter))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MyNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
