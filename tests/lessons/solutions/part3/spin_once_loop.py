"""Wrong: spin_once in a loop of main(), logging between the spins. The node
spins, but the counter is logged by main(), not by a timer's callback."""
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
        rclpy.spin_once(node, timeout_sec=1.0)
        node.get_logger().info("Hello " + str(node.counter_))
        node.counter_ += 1
    rclpy.shutdown()


if __name__ == "__main__":
    main()
