"""Right, written differently: a second line each tick that also ends with a
number (the uptime), beside the counter line."""
import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.counter_ = 0
        self.start_ = self.get_clock().now()
        self.create_timer(1.0, self.timer_callback)

    def timer_callback(self):
        self.get_logger().info(f"Hello {self.counter_}")
        up = (self.get_clock().now() - self.start_).nanoseconds // 1_000_000
        self.get_logger().info(f"uptime ms: {up}")
        self.counter_ += 1


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MyNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
