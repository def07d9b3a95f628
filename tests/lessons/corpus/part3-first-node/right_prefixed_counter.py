"""Right, written differently: a start-up line with a number in it, and the
counter at the end of a line with a prefix ("[node1] counter = 3")."""
import rclpy
from rclpy.node import Node


class Node1(Node):
    def __init__(self):
        super().__init__("node1")
        self.get_logger().info("Part 3 node has started")
        self.counter = 0
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        self.get_logger().info(f"[node1] counter = {self.counter}")
        self.counter += 1


def main(args=None):
    rclpy.init(args=args)
    node = Node1()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
