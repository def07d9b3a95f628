"""Right, with other numbers: a 0.5 s timer, a counter from 1, other words and a
start-up line without a number. The checks judge behaviour, so it passes."""
import rclpy
from rclpy.node import Node


class CounterNode(Node):
    def __init__(self):
        super().__init__("counter")
        self.count = 1
        self.timer = self.create_timer(0.5, self.tick)
        self.get_logger().info("Counter node started")

    def tick(self):
        self.get_logger().info(f"tick number {self.count}")
        self.count += 1


def main(args=None):
    rclpy.init(args=args)
    node = CounterNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
