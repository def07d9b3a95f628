"""Cheat: a timer every 3 s that logs three counter lines at once: enough
lines, rising by one, but not one line per period."""
import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.counter_ = 0
        self.create_timer(3.0, self.burst)

    def burst(self):
        for _ in range(3):
            self.get_logger().info(f"Hello {self.counter_}")
            self.counter_ += 1


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MyNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
