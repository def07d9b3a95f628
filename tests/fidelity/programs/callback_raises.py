"""An exception in a timer callback leaves spin_once, where the program catches it."""
import rclpy
from rclpy.node import Node


class Fragile(Node):
    def __init__(self):
        super().__init__("fragile")
        self.calls = 0
        self.create_timer(0.05, self.tick)

    def tick(self):
        self.calls += 1
        self.get_logger().info(f"tick {self.calls}")
        if self.calls == 3:
            raise ValueError("third tick fails")


def main():
    rclpy.init()
    node = Fragile()
    try:
        while node.calls < 5:
            rclpy.spin_once(node, timeout_sec=1.0)
    except ValueError as err:
        print("caught:", type(err).__name__, err, "after", node.calls, "calls")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
