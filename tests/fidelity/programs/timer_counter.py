"""A timer that counts to five and stops itself; a second, one-shot timer cancelled after its first call."""
import rclpy
from rclpy.node import Node


class Counter(Node):
    def __init__(self):
        super().__init__("counter")
        self.count = 0
        self.timer = self.create_timer(0.05, self.tick)
        self.once = self.create_timer(0.02, self.first)

    def tick(self):
        self.count += 1
        self.get_logger().info(f"tick {self.count}")
        if self.count == 5:
            self.timer.cancel()
            print("cancelled:", self.timer.is_canceled())

    def first(self):
        self.get_logger().info("one-shot")
        self.once.cancel()


def main():
    rclpy.init()
    node = Counter()
    print("period ns:", node.timer.timer_period_ns)
    while node.count < 5:
        rclpy.spin_once(node, timeout_sec=1.0)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
